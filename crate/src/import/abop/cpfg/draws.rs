//! cpfg's block variables that draw random numbers (`{nl = floor(n*bran(5,16)); nr = n-nl-1;}`).
//!
//! A block variable is computed once and read wherever the successor names it; the importer
//! substitutes each variable's expression where it is read, which for a random one would draw a
//! new number at each place (`nl` and `nr` would no longer add up to `n-1`). So a production
//! whose block draws is written in two parts that run in the same step: the production writes
//! an auxiliary module carrying its parameters and each drawn value, drawn once
//! (`A(n) : n>1 -> A_d1(n, floor(n*betavariate(5,16)))`), and a decomposition production turns that
//! module into the successor, reading the values as parameters (`A_d1(n, nl_d) -> …A(nl_d)…
//! A(n-nl_d-1)`). Decomposition runs after the step's productions, so the string after the step
//! is cpfg's. Only top-level assignments are drawn this way (one inside an `if` stays
//! substituted); a production whose condition or probability reads a drawn value, a value that
//! reads an earlier drawn one, or a model with a decomposition section of its own keeps the
//! substitution, with a note.

use super::super::{top_level, Importer};
use crate::syntax::PARENTHESES;

/// What reading one production's blocks draws: each random variable, its auxiliary name and
/// its value (translated).
#[derive(Default)]
pub(in crate::import::abop) struct Draws {
    pub values: Vec<(String, String, String)>,
    /// A value read an earlier drawn one: the production keeps the substitution.
    pub tangled: bool,
}

/// True when a translated expression calls one of Meristem's random functions.
pub(in crate::import::abop) fn draws_random(value: &str) -> bool {
    crate::vocabulary::FUNCTIONS
        .iter()
        .filter(|f| f.random)
        .any(|f| {
            value.match_indices(f.name).any(|(i, _)| {
                value[i + f.name.len()..].starts_with('(')
                    && !value[..i].ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_')
            })
        })
}

/// The byte index of `word` standing alone (not part of a longer name), at any depth.
fn find_word(text: &str, word: &str) -> Option<usize> {
    let bytes = text.as_bytes();
    let part = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    text.match_indices(word).map(|(i, _)| i).find(|&i| {
        let end = i + word.len();
        (i == 0 || !part(bytes[i - 1])) && (end >= bytes.len() || !part(bytes[end]))
    })
}

/// The formal parameters of a cpfg pattern (`S(a) < A(i,t) > B`: a, i, t), in order, once each.
pub(in crate::import::abop) fn formal_parameters(pattern: &str) -> Vec<String> {
    let mut names = Vec::new();
    let mut rest = pattern;
    while let Some(open) = rest.find('(') {
        let Some(close) = PARENTHESES.closing(rest, open) else {
            break;
        };
        for p in rest[open + 1..close].split(',') {
            let p = p.trim().to_string();
            if !p.is_empty() && !names.contains(&p) {
                names.push(p);
            }
        }
        rest = &rest[close + 1..];
    }
    names
}

/// The letters of a cpfg pattern's predecessor that an auxiliary module's name starts with
/// (`X` when it has none).
pub(in crate::import::abop) fn aux_letter(pattern: &str) -> String {
    let strict = top_level(pattern, "<").map_or(pattern, |i| &pattern[i + 1..]);
    let strict = top_level(strict, ">")
        .map_or(strict, |i| &strict[..i])
        .trim();
    let letter: String = strict
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric())
        .collect();
    if letter.is_empty() {
        "X".into()
    } else {
        letter
    }
}

impl Importer {
    /// Records the assignment `target = value` (value translated) when its value draws and a
    /// production's blocks are being read for draws; returns the name `target` then stands for.
    pub(in crate::import::abop) fn drawn(&mut self, target: &str, value: &str) -> Option<String> {
        let draws = self.cpfg.draws.as_mut()?;
        if !draws_random(value) {
            return None;
        }
        if draws
            .values
            .iter()
            .any(|(_, aux, _)| find_word(value, aux).is_some())
        {
            draws.tangled = true;
        }
        let aux = format!("{target}_d");
        draws
            .values
            .push((target.to_string(), aux.clone(), value.to_string()));
        Some(aux)
    }

    /// Whether the productions being read may draw block variables through an auxiliary module.
    pub(in crate::import::abop) fn may_stage_draws(&self) -> bool {
        self.flavour == super::super::Flavour::Cpfg
            && !self.lpfg.active
            && self.in_productions
            && !self.cpfg.has_decomposition
    }

    /// `pattern -> successor` with `guard` (condition text, translated) and `weight` for a
    /// production whose blocks drew `draws`: the production that writes the auxiliary module,
    /// and the decomposition production (kept for the end of the file) that turns it into
    /// `successor`. `None` when the condition or the weight reads a drawn value.
    pub(in crate::import::abop) fn staged(
        &mut self,
        pattern: &str,
        condition: Option<&str>,
        weight: Option<&str>,
        successor: &str,
        draws: &Draws,
    ) -> Result<Option<String>, String> {
        let reads_draw = |text: &str| {
            draws
                .values
                .iter()
                .any(|(_, aux, _)| find_word(text, aux).is_some())
        };
        if condition.is_some_and(reads_draw) || weight.is_some_and(reads_draw) {
            return Ok(None);
        }
        let letter = aux_letter(pattern);
        self.cpfg.stage_count += 1;
        let aux = format!("{letter}_d{}", self.cpfg.stage_count);
        let params = formal_parameters(pattern);
        let values: Vec<&str> = draws.values.iter().map(|(_, _, v)| v.as_str()).collect();
        let names: Vec<&str> = draws.values.iter().map(|(_, a, _)| a.as_str()).collect();
        let carried = |extra: &[&str]| {
            params
                .iter()
                .map(String::as_str)
                .chain(extra.iter().copied())
                .collect::<Vec<_>>()
                .join(",")
        };
        let mut text = self.pattern(pattern, 0)?;
        if let Some(c) = condition {
            text.push_str(&format!(" : {c}"));
        }
        text.push_str(" ->");
        if let Some(w) = weight {
            text.push_str(&format!(" ({w})"));
        }
        text.push_str(&format!(" {aux}({})", carried(&values)));
        let successor = if successor.is_empty() {
            "ε".to_string()
        } else {
            super::super::separate(successor)
        };
        self.cpfg
            .staged
            .push(format!("{aux}({}) -> {successor}", carried(&names)));
        self.declared.push(aux);
        Ok(Some(text))
    }

    /// The decomposition productions of the staged draws, in a section of their own (at
    /// `endlsystem`, or the end of the file).
    pub(in crate::import::abop) fn staged_lines(&mut self, n: usize) {
        if self.cpfg.staged.is_empty() {
            return;
        }
        self.out.comment(
            "cpfg's block variables that draw random numbers and its loops: each production above that has them writes an auxiliary module (its values drawn once, or its loop's variables), which this decomposition turns into cpfg's successor in the same step",
            n,
        );
        let section = crate::vocabulary::KeywordKind::Decomposition.written();
        self.out.line(section, n);
        if std::mem::take(&mut self.cpfg.staged_depth) {
            let depth = crate::vocabulary::KeywordKind::MaximumDepth.written();
            self.out
                .line(format!("{depth} {}", super::loops::LOOP_DEPTH), n);
        }
        for line in std::mem::take(&mut self.cpfg.staged) {
            self.out.line(line, n);
        }
        self.in_productions = false;
    }
}

#[cfg(test)]
mod tests {
    use super::{draws_random, formal_parameters};

    #[test]
    fn the_formal_parameters_of_a_pattern_are_every_module_s_in_order() {
        assert_eq!(
            formal_parameters("S(a) < A(i,t) > B(a, z)"),
            ["a", "i", "t", "z"]
        );
        assert!(formal_parameters("A").is_empty());
    }

    #[test]
    fn a_value_draws_when_it_calls_a_random_function_by_name() {
        assert!(draws_random("floor(n*betavariate(5,16))"));
        assert!(draws_random("uniform(0,1)+1"));
        assert!(!draws_random("n*my_uniform(2)"));
        assert!(!draws_random("n-1"));
    }
}
