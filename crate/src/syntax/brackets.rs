//! Bracket depth: the one scanner that says what "outside parentheses" means, for the parser's
//! module strings and for every importer (which may use `syntax`, to its left).
//!
//! A scan walks the text once and counts a set of brackets ([`PARENTHESES`], or with braces
//! for cpfg's statement blocks, or all three kinds for C's macro arguments): an opening bracket
//! stands inside itself (depth 1 at the top level), its closing bracket outside (depth 0). A
//! closing bracket with no opening one takes the depth below 0, and nothing after it is at the
//! top level until an opening one makes up for it.

/// A set of opening brackets and their closing ones, counted together (`(` and `{` nest in one
/// another as one depth).
#[derive(Clone, Copy, Debug)]
pub struct Brackets {
    opens: &'static str,
    closes: &'static str,
}

/// Parentheses: parameter lists, calls and grouped expressions.
pub const PARENTHESES: Brackets = Brackets::new("(", ")");

/// Parentheses and braces: cpfg's statement blocks `{ … }` around and in expressions.
pub const PARENTHESES_AND_BRACES: Brackets = Brackets::new("({", ")}");

/// Braces alone: cpfg's blocks of statements, whose parentheses do not matter.
pub const BRACES: Brackets = Brackets::new("{", "}");

/// Parentheses, square brackets and braces: the arguments of a C macro call.
pub const ALL_BRACKETS: Brackets = Brackets::new("([{", ")]}");

impl Brackets {
    const fn new(opens: &'static str, closes: &'static str) -> Brackets {
        Brackets { opens, closes }
    }

    /// Whether `c` is one of these brackets, opening or closing.
    pub fn contains(self, c: char) -> bool {
        self.opens.contains(c) || self.closes.contains(c)
    }

    /// Each character of `text` with its byte index and the depth after it: an opening bracket
    /// at the top level is at depth 1, its closing bracket and what follows at depth 0.
    pub fn depths(self, text: &str) -> impl Iterator<Item = (usize, char, i32)> + '_ {
        self.depths_of(text.char_indices())
    }

    fn depths_of<I: Iterator<Item = (usize, char)>>(
        self,
        chars: I,
    ) -> impl Iterator<Item = (usize, char, i32)> {
        let mut depth = 0i32;
        chars.map(move |(i, c)| {
            if self.opens.contains(c) {
                depth += 1;
            } else if self.closes.contains(c) {
                depth -= 1;
            }
            (i, c, depth)
        })
    }

    /// The byte index of the first character outside brackets (not a bracket itself) that
    /// `wanted` accepts, given its byte index and itself.
    pub fn find_top_level(
        self,
        text: &str,
        mut wanted: impl FnMut(usize, char) -> bool,
    ) -> Option<usize> {
        self.depths(text)
            .find(|&(i, c, depth)| depth == 0 && !self.contains(c) && wanted(i, c))
            .map(|(i, _, _)| i)
    }

    /// The byte index of the first `token` outside brackets.
    pub fn find_char(self, text: &str, token: char) -> Option<usize> {
        self.find_top_level(text, |_, c| c == token)
    }

    /// The byte index of the first `token` (a string that starts with no bracket) outside
    /// brackets.
    pub fn find_str(self, text: &str, token: &str) -> Option<usize> {
        self.find_top_level(text, |i, _| text[i..].starts_with(token))
    }

    /// The byte index of the bracket that closes the one at byte `open` (counting from there:
    /// the first closing bracket that brings the depth back to 0).
    pub fn closing(self, text: &str, open: usize) -> Option<usize> {
        let rest = text.get(open..)?;
        self.closer(rest.char_indices()).map(|i| open + i)
    }

    /// As [`Brackets::closing`], over characters: the index in `chars` of the bracket that
    /// closes the one at `open`.
    pub fn closing_char(self, chars: &[char], open: usize) -> Option<usize> {
        let rest = chars.get(open..)?;
        self.closer(rest.iter().copied().enumerate())
            .map(|i| open + i)
    }

    fn closer<I: Iterator<Item = (usize, char)>>(self, chars: I) -> Option<usize> {
        self.depths_of(chars)
            .find(|&(_, c, depth)| depth == 0 && self.closes.contains(c))
            .map(|(i, _, _)| i)
    }

    /// `text` split at each `sep` outside brackets: the pieces, each with its byte offset.
    pub fn split(self, text: &str, sep: char) -> Vec<(usize, &str)> {
        let mut pieces = Vec::new();
        let mut start = 0;
        for (i, c, depth) in self.depths(text) {
            if c == sep && depth == 0 {
                pieces.push((start, &text[start..i]));
                start = i + c.len_utf8();
            }
        }
        pieces.push((start, &text[start..]));
        pieces
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_top_level_is_outside_every_counted_bracket() {
        assert_eq!(PARENTHESES.find_char("A(x:1):x>0", ':'), Some(6));
        assert_eq!(PARENTHESES.find_char("A(x:1", ':'), None);
        // An unmatched closing bracket leaves nothing at the top level after it.
        assert_eq!(PARENTHESES.find_char("a):b", ':'), None);
        assert_eq!(
            PARENTHESES_AND_BRACES.find_str("{a->b} c -> d", "->"),
            Some(9)
        );
        assert_eq!(PARENTHESES.find_str("{a->b} c -> d", "->"), Some(2));
    }

    #[test]
    fn closing_finds_the_bracket_that_matches() {
        assert_eq!(PARENTHESES.closing("f(a(b),c) d", 1), Some(8));
        assert_eq!(PARENTHESES.closing("f(a(b),c", 1), None);
        // Braces and parentheses are one depth: the `}` does not close the `{`.
        assert_eq!(PARENTHESES_AND_BRACES.closing("{(})", 0), Some(3));
        let chars: Vec<char> = "é(ü(1))x".chars().collect();
        assert_eq!(PARENTHESES.closing_char(&chars, 1), Some(6));
        assert_eq!(PARENTHESES.closing("é(ü)", 2), Some(5));
        assert_eq!(PARENTHESES.closing("ab", 7), None);
    }

    #[test]
    fn split_keeps_what_brackets_hold_together() {
        assert_eq!(
            PARENTHESES.split("a, f(b, c), d", ','),
            [(0, "a"), (2, " f(b, c)"), (11, " d")]
        );
        assert_eq!(PARENTHESES.split("", ','), [(0, "")]);
    }
}
