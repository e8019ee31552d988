//! cpfg's C preprocessor, as far as L-system files use it: `#define` with and without arguments,
//! `#undef`, `#if`/`#ifdef`/`#ifndef`/`#elif`/`#else`/`#endif`, `#include` of the object's own
//! files, and lines continued by `\`.
//!
//! A macro whose value is a number expression stays a Meristem `#define` (the line is kept for
//! the importer, so the studio shows it as a slider); every other macro (with arguments, or whose
//! value is modules) is expanded where it is used, as cpp does.
//!
//! A kept macro is never expanded as text, not even in another macro's value or an `#if`: a value
//! names the kept macros it uses (Meristem's `#define`s refer to each other), and an `#if` reads
//! each one's number, worked out once when it was defined. So a chain of macros that each use the
//! one before twice costs one expansion a link, not a doubling text (issue 19).

use super::super::Line;
use crate::syntax::ALL_BRACKETS;

/// A `#define`.
#[derive(Clone, Debug)]
struct Macro {
    /// `None` for an object-like macro.
    params: Option<Vec<String>>,
    body: String,
    /// Kept as a Meristem `#define` (not expanded).
    kept: bool,
    /// A kept macro's number (for `#if`), worked out once when it is defined; `None` when it is
    /// not a constant Meristem can work out.
    value: Option<f64>,
}

/// How deep `#include` may nest, and how many expansions one line may take (a macro that grows
/// without end stops here).
const MAX_INCLUDE_DEPTH: usize = 8;
const MAX_EXPANSIONS: usize = 2_000;
const MAX_LINE: usize = 100_000;
/// The most bytes `#include` may bring in, all files and all times together: files that include
/// each other several times grow as a power of that count however shallow (issue 50, 6: eight
/// files of 400 bytes ran for minutes).
const MAX_INCLUDED: usize = 1 << 20;
/// The most bytes the expansion of macros may add to a file, all lines together: each line's
/// own caps still let a 45 KB file of 2,000 lines, each using a macro 20,000 characters long,
/// grow to 40 MB, which took the importer 1.2 GB (issue 50).
const MAX_GROWTH: usize = 1 << 20;

/// The preprocessor's state.
pub(in crate::import::abop) struct Preprocessor<'a> {
    /// The macros defined now, by name (a new `#define` of a name replaces the old one).
    macros: std::collections::HashMap<String, Macro>,
    /// Macro uses replaced by text so far (a measure of the work done: linear in the input).
    pub expansions: usize,
    /// The object's other files by name (for `#include "file"`).
    include: &'a dyn Fn(&str) -> Option<String>,
    pub notes: Vec<(usize, String)>,
    /// Functions the importer translates (their names are never taken for module text).
    functions: &'a [&'a str],
    /// The bytes `#include` brought in so far; past [`MAX_INCLUDED`] once it refused a file.
    included: usize,
    /// The bytes expansion added so far; [`MAX_GROWTH`] at most.
    grown: usize,
}

/// One level of `#if`: is this branch taken, was one taken already, was the enclosing one active.
struct Condition {
    active: bool,
    taken: bool,
    outer: bool,
}

impl<'a> Preprocessor<'a> {
    pub fn new(include: &'a dyn Fn(&str) -> Option<String>, functions: &'a [&'a str]) -> Self {
        Preprocessor {
            macros: std::collections::HashMap::new(),
            expansions: 0,
            include,
            notes: Vec::new(),
            functions,
            included: 0,
            grown: 0,
        }
    }

    /// The lines after preprocessing: directives it handled are gone (a kept `#define` stays),
    /// lines of a branch not taken are empty, macros are expanded.
    pub fn run(&mut self, lines: Vec<Line>, depth: usize) -> Vec<Line> {
        let mut out = Vec::new();
        let mut stack: Vec<Condition> = Vec::new();
        for mut line in continued(lines) {
            let active = stack.last().is_none_or(|c| c.active);
            if let Some(directive) = line.code.strip_prefix('#') {
                let directive = directive.trim_start().to_string();
                let word: String = directive
                    .chars()
                    .take_while(char::is_ascii_alphabetic)
                    .collect();
                let rest = directive[word.len()..].trim().to_string();
                if self.conditional(&word, &rest, active, &mut stack, line.n) {
                    continue;
                }
                if !active {
                    continue;
                }
                match word.as_str() {
                    "define" => {
                        if let Some(kept) = self.define(&rest) {
                            line.code = kept;
                            out.push(line);
                        }
                    }
                    "undef" => {
                        self.macros.remove(rest.trim());
                    }
                    "include" => out.extend(self.include_file(&rest, line.n, depth)),
                    _ => {
                        // Left to the importer, which notes it.
                        out.push(line);
                    }
                }
                continue;
            }
            if !active {
                continue;
            }
            line.code = self.expand(&line.code, line.n);
            out.push(line);
        }
        out
    }

    /// The kept macros whose value is a constant, with that value (what an lpfg surface id
    /// such as `Surface(LEAF, s)` reads).
    pub fn constants(&self) -> Vec<(String, f64)> {
        self.macros
            .iter()
            .filter_map(|(name, m)| Some((name.clone(), m.value.filter(|_| m.kept)?)))
            .collect()
    }

    /// `#if`, `#ifdef`, `#ifndef`, `#elif`, `#else`, `#endif`; false for another word.
    fn conditional(
        &mut self,
        word: &str,
        rest: &str,
        active: bool,
        stack: &mut Vec<Condition>,
        n: usize,
    ) -> bool {
        match word {
            "if" | "ifdef" | "ifndef" => {
                let value = active
                    && match word {
                        "ifdef" => self.defined(rest),
                        "ifndef" => !self.defined(rest),
                        _ => self.truth(rest, n),
                    };
                stack.push(Condition {
                    active: value,
                    taken: value,
                    outer: active,
                });
            }
            "elif" | "else" => {
                if let Some(c) = stack.last_mut() {
                    let value = c.outer && !c.taken && (word == "else" || self.truth(rest, n));
                    c.active = value;
                    c.taken |= value;
                }
            }
            "endif" => {
                stack.pop();
            }
            _ => return false,
        }
        true
    }

    fn defined(&self, name: &str) -> bool {
        self.macros.contains_key(name.trim())
    }

    /// The value of an `#if` condition: macros expanded, `defined(X)` read, other names 0 (as
    /// cpp does); a condition that is not a constant expression is false, and noted.
    fn truth(&mut self, condition: &str, n: usize) -> bool {
        let mut text = condition.to_string();
        // `defined(X)` and `defined X`.
        while let Some(i) = find_word(&text, "defined") {
            let after = text[i + 7..].trim_start();
            let (name, len) = if let Some(inner) = after.strip_prefix('(') {
                let close = inner.find(')').unwrap_or(inner.len());
                (inner[..close].trim().to_string(), close + 2)
            } else {
                let end = after
                    .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                    .unwrap_or(after.len());
                (after[..end].to_string(), end)
            };
            let skipped = text[i + 7..].len() - after.len();
            let value = if self.defined(&name) { "1" } else { "0" };
            let end = (i + 7 + skipped + len).min(text.len());
            text.replace_range(i..end, value);
        }
        let expanded = self.expand(&text, n);
        let value = self.constant(&expanded);
        match value {
            Some(v) => v != 0.0,
            None => {
                self.notes.push((
                    n,
                    format!("the condition of #if {condition} is not a constant Meristem can work out: its lines are left out"),
                ));
                false
            }
        }
    }

    /// The number `text` works out to, with each kept macro read as its number (worked out when
    /// it was defined) and any other name as 0 (cpp's rule for `#if`); `None` when it is not a
    /// constant.
    fn constant(&self, text: &str) -> Option<f64> {
        let numbers = map_words(text, |word, rest, out| {
            match self.macros.get(word) {
                Some(m) if m.kept => out.push_str(&format!("({:?})", m.value?)),
                // A function the importer translates (sin, …) stays for the compiler.
                _ if rest.trim_start().starts_with('(') && self.functions.contains(&word) => {
                    out.push_str(word)
                }
                _ => out.push('0'),
            }
            Some(())
        })?;
        let value = crate::syntax::parse_expression(&numbers, 0)
            .ok()
            .and_then(|e| crate::model::Program::compile(&e, &NoNames).ok())
            .and_then(|p| p.constant());
        value.filter(|v| v.is_finite())
    }

    /// Records `#define …` (the text after `define`); returns the line to keep when the macro
    /// stays a Meristem `#define`.
    fn define(&mut self, rest: &str) -> Option<String> {
        let end = rest
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(rest.len());
        let name = rest[..end].to_string();
        if name.is_empty() {
            return Some(format!("#define {rest}"));
        }
        let after = &rest[end..];
        let (params, body) = match after.strip_prefix('(') {
            Some(inner) => {
                let close = inner.find(')')?;
                let params = inner[..close]
                    .split(',')
                    .map(|p| p.trim().to_string())
                    .filter(|p| !p.is_empty())
                    .collect();
                (Some(params), inner[close + 1..].trim().to_string())
            }
            None => (None, after.trim().to_string()),
        };
        // The macros that are not kept are expanded; the kept ones stay names (see the module).
        let body = self.expand(&body, 0);
        let kept = params.is_none() && !body.is_empty() && self.is_expression(&body);
        let value = if kept { self.constant(&body) } else { None };
        self.macros.insert(
            name.clone(),
            Macro {
                params,
                body: body.clone(),
                kept,
                value,
            },
        );
        kept.then(|| format!("#define {name} {body}"))
    }

    /// True when `body` is a number expression: numbers, operators, kept macros and calls of
    /// functions (a name followed by `(` that is no module: the translated functions).
    fn is_expression(&self, body: &str) -> bool {
        let chars: Vec<char> = body.chars().collect();
        let mut i = 0;
        let mut any = false;
        while i < chars.len() {
            let c = chars[i];
            if c.is_ascii_alphabetic() || c == '_' {
                let start = i;
                while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                    i += 1;
                }
                let word: String = chars[start..i].iter().collect();
                let call = chars[i..].iter().find(|c| !c.is_whitespace()) == Some(&'(');
                let known = if call {
                    self.functions.contains(&word.as_str())
                } else {
                    self.macros.get(&word).is_some_and(|m| m.kept)
                };
                if !known {
                    return false;
                }
                any = true;
                continue;
            }
            if c.is_ascii_digit() || c == '.' {
                any = true;
            } else if !(c.is_whitespace() || "+-*/%^()<>=!&|?:,".contains(c)) {
                return false;
            }
            i += 1;
        }
        any
    }

    /// `#include "file"`: the file's lines, preprocessed, at the line of the `#include`.
    fn include_file(&mut self, rest: &str, n: usize, depth: usize) -> Vec<Line> {
        let name = rest.trim_matches(|c: char| c == '"' || c == '<' || c == '>' || c == ' ');
        if rest.starts_with('<') {
            // A C library header (<math.h>): cpfg's expressions have its functions anyway.
            return Vec::new();
        }
        if depth >= MAX_INCLUDE_DEPTH {
            self.notes
                .push((n, format!("#include \"{name}\" nests too deep; left out")));
            return Vec::new();
        }
        match (self.include)(name) {
            Some(text) if self.included + text.len() > MAX_INCLUDED => {
                // Said once: every later `#include` is left out too.
                if self.included <= MAX_INCLUDED {
                    self.included = MAX_INCLUDED + 1;
                    self.notes.push((
                        n,
                        format!("#include \"{name}\" and those after it are left out: the files they include would bring in more than {} MB together", MAX_INCLUDED >> 20),
                    ));
                }
                Vec::new()
            }
            Some(text) => {
                self.included += text.len();
                let included =
                    crate::import::abop::prepare::lines(&text, crate::import::abop::Flavour::Cpfg)
                        .into_iter()
                        .map(|l| Line { n, ..l })
                        .collect();
                self.run(included, depth + 1)
            }
            None => {
                self.notes.push((
                    n,
                    format!("#include \"{name}\": the file was not opened with this one, so what it holds (productions, definitions) is missing"),
                ));
                Vec::new()
            }
        }
    }

    /// Expands the macros that are not kept as `#define`s.
    fn expand(&mut self, text: &str, n: usize) -> String {
        let mut text = text.to_string();
        let mut count = 0;
        let mut from = 0;
        loop {
            let Some((start, end, replacement)) = self.next_macro(&text, from) else {
                return text;
            };
            count += 1;
            self.expansions += 1;
            if count > MAX_EXPANSIONS || text.len() > MAX_LINE {
                // Either a macro that grows without end, or a long line (continued lines
                // joined) with many uses: say which limit, not which cause.
                self.notes.push((
                    n,
                    format!(
                        "the macros of this line expand more than {MAX_EXPANSIONS} times or past \
                         {MAX_LINE} characters (a macro that grows without end does); the rest \
                         of the line is left unexpanded"
                    ),
                ));
                return text;
            }
            let growth = replacement.len().saturating_sub(end - start);
            if self.grown + growth > MAX_GROWTH {
                if self.grown <= MAX_GROWTH {
                    self.notes.push((
                        n,
                        format!(
                            "the macros of this file add more than {} MB to it: from here on \
                             they are left unexpanded",
                            MAX_GROWTH >> 20
                        ),
                    ));
                    // Said once: every later use finds the budget passed.
                    self.grown = MAX_GROWTH + 1;
                }
                return text;
            }
            self.grown += growth;
            text.replace_range(start..end, &replacement);
            // Rescan the replacement (nested macros), but a macro met again at the same place
            // is cpp's recursion, which stops; MAX_EXPANSIONS bounds it here.
            from = start;
        }
    }

    /// The first macro use at or after byte `from`: its span and its replacement.
    fn next_macro(&self, text: &str, from: usize) -> Option<(usize, usize, String)> {
        let bytes = text.as_bytes();
        let mut i = from;
        while i < bytes.len() {
            let c = bytes[i];
            if c.is_ascii_alphabetic() || c == b'_' {
                let start = i;
                i = word_end(bytes, i);
                let word = &text[start..i];
                let found = self.macros.get(word).filter(|m| !m.kept);
                if let Some(m) = found {
                    match &m.params {
                        None => return Some((start, i, m.body.clone())),
                        Some(params) => {
                            let rest = &text[i..];
                            let open = rest.len() - rest.trim_start().len();
                            if rest[open..].starts_with('(') {
                                let args_at = i + open + 1;
                                if let Some((args, close)) = arguments(text, args_at) {
                                    return Some((
                                        start,
                                        close + 1,
                                        substitute(&m.body, params, &args),
                                    ));
                                }
                            }
                        }
                    }
                }
                continue;
            }
            i += 1;
        }
        None
    }
}

/// The end of the identifier that starts at byte `i`.
fn word_end(bytes: &[u8], mut i: usize) -> usize {
    while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
        i += 1;
    }
    i
}

/// Joins lines that end with `\` to the next.
fn continued(lines: Vec<Line>) -> Vec<Line> {
    let mut out: Vec<Line> = Vec::new();
    let mut open = false;
    // The line being continued (the lines joined to it stay, empty, for the line numbers).
    let mut head = 0;
    for line in lines {
        if open {
            if let Some(last) = out.get_mut(head) {
                last.code.push(' ');
                last.code.push_str(&line.code);
                open = strip_continuation(&mut last.code);
                out.push(Line {
                    code: String::new(),
                    ..line
                });
                continue;
            }
        }
        let mut line = line;
        open = strip_continuation(&mut line.code);
        head = out.len();
        out.push(line);
    }
    out
}

/// Takes a line's continuation `\` off its end; true when there was one. A line that ends with
/// `\\` (vlab's editor escapes the backslash, as in the course's `02-fern-leaf`) is continued
/// too, both taken off: cpp would leave the first in the macro's value, where it is no token of an
/// expression cpfg could read.
fn strip_continuation(code: &mut String) -> bool {
    if !code.ends_with('\\') {
        return false;
    }
    code.pop();
    if code.ends_with('\\') {
        code.pop();
    }
    true
}

/// The arguments of a macro call whose first argument starts at byte `at` (after `(`): split at
/// top-level commas; with the index of the closing `)`.
fn arguments(text: &str, at: usize) -> Option<(Vec<String>, usize)> {
    let mut args = Vec::new();
    let mut start = at;
    for (k, c, depth) in ALL_BRACKETS.depths(&text[at..]) {
        let i = at + k;
        // A `)` that takes the depth below the arguments' closes the call.
        if c == ')' && depth == -1 {
            args.push(text[start..i].trim().to_string());
            return Some((args, i));
        }
        if c == ',' && depth == 0 {
            args.push(text[start..i].trim().to_string());
            start = i + 1;
        }
    }
    None
}

/// The body with each parameter (a whole word) replaced by its argument.
pub(in crate::import::abop) fn substitute(
    body: &str,
    params: &[String],
    args: &[String],
) -> String {
    map_words(body, |word, _, out| {
        match params.iter().position(|p| p == word) {
            Some(k) => out.push_str(args.get(k).map_or("", String::as_str)),
            None => out.push_str(word),
        }
        Some(())
    })
    .unwrap_or_default()
}

/// `text` with each identifier written by `word(name, the text after it, out)`, everything else
/// copied; a number (`1e5`, `2.5E-3`) is copied whole, so its exponent is never read as a name.
/// `None` from `word` gives `None`.
fn map_words(
    text: &str,
    mut word: impl FnMut(&str, &str, &mut String) -> Option<()>,
) -> Option<String> {
    let mut out = String::with_capacity(text.len());
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        let start = i;
        if c.is_ascii_alphabetic() || c == b'_' {
            i = word_end(bytes, i);
            word(&text[start..i], &text[i..], &mut out)?;
        } else if c.is_ascii_digit() || c == b'.' {
            // A number: its digits, exponent and all, as they are.
            i += 1;
            while i < bytes.len()
                && (bytes[i].is_ascii_alphanumeric()
                    || bytes[i] == b'.'
                    || ((bytes[i] == b'+' || bytes[i] == b'-')
                        && matches!(bytes[i - 1], b'e' | b'E')))
            {
                i += 1;
            }
            out.push_str(&text[start..i]);
        } else {
            i += text[i..].chars().next().map_or(1, char::len_utf8);
            out.push_str(&text[start..i]);
        }
    }
    Some(out)
}

/// The byte index of `word` standing alone.
fn find_word(text: &str, word: &str) -> Option<usize> {
    let bytes = text.as_bytes();
    text.match_indices(word).map(|(i, _)| i).find(|&i| {
        let before = i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
        let end = i + word.len();
        let after =
            end >= bytes.len() || !(bytes[end].is_ascii_alphanumeric() || bytes[end] == b'_');
        before && after
    })
}

/// A scope with no names: `#if` conditions are constants once macros are expanded.
struct NoNames;

impl crate::model::Scope for NoNames {
    fn slot(&self, _: &str) -> Option<u16> {
        None
    }
    fn define(&self, _: &str) -> Option<&crate::syntax::ExprSyntax> {
        None
    }
    fn random_var(&self, _: &str) -> Option<u16> {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::substitute;

    #[test]
    fn a_parameter_is_replaced_as_a_whole_word_never_inside_a_number() {
        let params = ["e5".to_string(), "x".to_string()];
        let args = ["A".to_string(), "(1+2)".to_string()];
        assert_eq!(
            substitute("x*1e5+e5-x2+2.5E-3", &params, &args),
            "(1+2)*1e5+A-x2+2.5E-3"
        );
    }
}
