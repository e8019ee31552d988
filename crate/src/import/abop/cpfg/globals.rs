//! cpfg's global statements: the blocks `Start:`, `StartEach:`, `EndEach:`, `End:` and `Define:`
//! (`Start: {srand(5); n = 0;}`), their variables and arrays (`array turn[3] = {0, 45, -45};`).
//!
//! Meristem has no variables, so a variable becomes a `#define` of its start value; one that a
//! `StartEach:` or `EndEach:` block steps by a constant becomes a `#define` over `NumIt` (the
//! step's number), which is exactly its value during that step; any other change is noted. An
//! array becomes a choice by index, written where the array is read.

use super::super::{Env, Importer, Line};
use crate::import::number;
use crate::syntax::BRACES;
use crate::vocabulary::DirectiveKind;

/// Which block a statement is in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(in crate::import::abop) enum BlockKind {
    Start,
    StartEach,
    EndEach,
    End,
    Define,
}

impl BlockKind {
    fn named(keyword: &str) -> Option<BlockKind> {
        Some(match keyword {
            "start" => BlockKind::Start,
            "starteach" => BlockKind::StartEach,
            "endeach" => BlockKind::EndEach,
            "end" => BlockKind::End,
            "define" => BlockKind::Define,
            _ => return None,
        })
    }

    fn written(self) -> &'static str {
        match self {
            BlockKind::Start => "Start:",
            BlockKind::StartEach => "StartEach:",
            BlockKind::EndEach => "EndEach:",
            BlockKind::End => "End:",
            BlockKind::Define => "Define:",
        }
    }
}

/// What the global blocks of a file say, read before the file is translated.
#[derive(Clone, Debug, Default)]
pub(in crate::import::abop) struct Globals {
    /// Variables a `StartEach:`/`EndEach:` block steps by a constant: name, step, and whether
    /// after the step (`EndEach:`).
    steps: Vec<(String, String, bool)>,
    /// Variables assigned by any statement other than their start value or such a step.
    changed: Vec<String>,
    /// Variables a `StartEach:` block sets from other variables alone (`p = (2*n+1.0)/(n*n)`,
    /// where `n` is stepped): their value during each step is a `#define` of that expression.
    derived: Vec<(String, String)>,
    /// Every variable assigned in a block.
    pub names: Vec<String>,
    /// Arrays: name, the sizes of their dimensions after the first, and their values (translated
    /// when their block is).
    pub arrays: Vec<(String, Vec<String>, Vec<String>)>,
}

/// `Start: {…}` → the block kind and the statements inside the braces.
pub(in crate::import::abop) fn block(code: &str) -> Option<(BlockKind, Vec<String>)> {
    let colon = code.find(':')?;
    let keyword: String = code[..colon]
        .chars()
        .filter(|c| !c.is_whitespace())
        .collect::<String>()
        .to_ascii_lowercase();
    let kind = BlockKind::named(&keyword)?;
    let body = code[colon + 1..].trim();
    let body = body.strip_prefix('{').unwrap_or(body);
    let body = body.strip_suffix('}').unwrap_or(body);
    Some((kind, statements(body)))
}

/// Statements split at `;` outside braces.
fn statements(body: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut start = 0;
    for (i, c, depth) in BRACES.depths(body) {
        if c == ';' && depth <= 0 {
            out.push(body[start..i].trim().to_string());
            start = i + 1;
        }
    }
    out.push(body[start..].trim().to_string());
    out.retain(|s| !s.is_empty());
    out
}

/// `x = x + 0.5`, `x += 0.5`, `x++` (and `-`) → (x, the step as an expression).
fn step(statement: &str) -> Option<(String, String)> {
    let s: String = statement.chars().filter(|c| !c.is_whitespace()).collect();
    if let Some(name) = s.strip_suffix("++") {
        return Some((name.to_string(), "1".into()));
    }
    if let Some(name) = s.strip_suffix("--") {
        return Some((name.to_string(), "-1".into()));
    }
    for (op, sign) in [("+=", ""), ("-=", "-")] {
        if let Some((name, d)) = s.split_once(op) {
            return constant(d).then(|| (name.to_string(), format!("{sign}{d}")));
        }
    }
    let (name, value) = s.split_once('=')?;
    for (op, sign) in [('+', ""), ('-', "-")] {
        if let Some(d) = value.strip_prefix(&format!("{name}{op}")) {
            return constant(d).then(|| (name.to_string(), format!("{sign}{d}")));
        }
    }
    None
}

/// A number, or an expression of numbers and names (`1/DEL`): names that are variables of the
/// global blocks are ruled out after the scan ([`Globals::scan`]).
fn constant(text: &str) -> bool {
    text.parse::<f64>().is_ok_and(f64::is_finite)
        || (!text.is_empty()
            && text
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || "_.+-*/() ".contains(c)))
}

/// The names (words that start with a letter or `_`) in an expression.
fn words(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut word = String::new();
    for c in text.chars().chain(std::iter::once(' ')) {
        if c.is_ascii_alphanumeric() || c == '_' {
            word.push(c);
        } else if !word.is_empty() {
            if !word.starts_with(|c: char| c.is_ascii_digit()) {
                out.push(std::mem::take(&mut word));
            }
            word.clear();
        }
    }
    out
}

/// The variable an assignment statement sets (`x = …`, `x += …`, `x++`).
fn assigned(statement: &str) -> Option<String> {
    let s = statement.trim();
    let end = s
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(s.len());
    let (name, rest) = (&s[..end], s[end..].trim_start());
    let assigns = (rest.starts_with('=') && !rest.starts_with("=="))
        || ["+=", "-=", "*=", "/=", "++", "--"]
            .iter()
            .any(|op| rest.starts_with(op));
    (!name.is_empty() && assigns && name != "array").then(|| name.to_string())
}

impl Globals {
    /// Reads the global blocks of the whole file.
    pub fn scan(lines: &[Line]) -> Globals {
        let mut g = Globals::default();
        for line in lines {
            let Some((kind, statements)) = block(&line.code) else {
                continue;
            };
            for s in &statements {
                if let Some(rest) = s.strip_prefix("array") {
                    let name: String = rest
                        .trim_start()
                        .chars()
                        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                        .collect();
                    g.names.push(name);
                    continue;
                }
                let Some(name) = assigned(s) else { continue };
                if !g.names.contains(&name) {
                    g.names.push(name.clone());
                }
                let stepped = matches!(kind, BlockKind::StartEach | BlockKind::EndEach)
                    .then(|| step(s))
                    .flatten();
                let plain = s
                    .split_once('=')
                    .filter(|(t, v)| t.trim() == name && !v.starts_with('='))
                    .map(|(_, v)| v.trim().to_string());
                let assigned_before = g.steps.iter().any(|(x, _, _)| *x == name)
                    || g.derived.iter().any(|(x, _)| *x == name);
                match (kind, stepped) {
                    (BlockKind::Start | BlockKind::Define, _) => {}
                    (_, Some((n, d))) if !assigned_before => {
                        g.steps.push((n, d, kind == BlockKind::EndEach))
                    }
                    (BlockKind::StartEach, None)
                        if !assigned_before
                            && plain.as_ref().is_some_and(|v| !words(v).contains(&name)) =>
                    {
                        g.derived.push((name, plain.unwrap_or_default()))
                    }
                    _ => g.changed.push(name),
                }
            }
        }
        // A step or a derived value that reads a variable that changes otherwise is no constant.
        loop {
            // Variables set only at the start are constants; stepped ones are not for a step.
            let unsteady = |e: &str, g: &Globals| words(e).iter().any(|w| g.changed.contains(w));
            let before = g.changed.len();
            let steps = std::mem::take(&mut g.steps);
            for (x, d, after) in steps {
                let moving = |w: &String| {
                    g.changed.contains(w)
                        || g.steps.iter().any(|(y, _, _)| y == w)
                        || g.derived.iter().any(|(y, _)| y == w)
                        || *w == x
                };
                if words(&d).iter().any(moving) {
                    g.changed.push(x);
                } else {
                    g.steps.push((x, d, after));
                }
            }
            let derived = std::mem::take(&mut g.derived);
            for (x, v) in derived {
                if g.changed.contains(&x) {
                    continue;
                }
                if unsteady(&v, &g) {
                    g.changed.push(x);
                } else {
                    g.derived.push((x, v));
                }
            }
            if g.changed.len() == before {
                break;
            }
        }
        g
    }

    /// True for a variable of the global blocks.
    pub fn is_global(&self, name: &str) -> bool {
        self.names.iter().any(|n| n == name)
    }
}

/// The most values of an array: each read of it writes them all, in a choice by index.
const MAX_ARRAY_VALUES: usize = 1_000;

impl Importer {
    /// Translates a global block at line `n`; false when the line is none.
    pub(in crate::import::abop) fn global_block(&mut self, code: &str, n: usize) -> bool {
        let Some((kind, statements)) = block(code) else {
            return false;
        };
        for s in statements {
            if let Err(why) = self.global_statement(kind, &s, n) {
                self.note(n, why);
            }
        }
        true
    }

    fn global_statement(&mut self, kind: BlockKind, s: &str, n: usize) -> Result<(), String> {
        let compact: String = s.chars().filter(|c| !c.is_whitespace()).collect();
        if let Some(seed) = compact
            .strip_prefix("srand(")
            .and_then(|r| r.strip_suffix(')'))
        {
            let value = self.expression(seed, &Env::new())?;
            self.out
                .line(format!("{} {value}", DirectiveKind::Seed.written()), n);
            return Ok(());
        }
        if compact.starts_with("printf(") {
            self.note_once(
                "printf",
                n,
                "cpfg's printf prints to the console; it is not translated (the plant is the same)",
            );
            return Ok(());
        }
        if let Some(rest) = s.strip_prefix("array") {
            return self.array(rest);
        }
        let Some(name) = assigned(s) else {
            return Err(format!(
                "cpfg's {} statement '{s}' is not translated: Meristem has no statements, so what it does is missing",
                kind.written()
            ));
        };
        if let Some((_, value)) = self
            .cpfg
            .globals
            .derived
            .iter()
            .find(|(x, _)| *x == name)
            .cloned()
        {
            return match kind {
                // The start value is never read: each step sets it first.
                BlockKind::Start | BlockKind::Define => Ok(()),
                _ => {
                    let value = self.expression(&value, &Env::new())?;
                    self.out.line(
                        format!("{} {name} ({value})", DirectiveKind::Define.written()),
                        n,
                    );
                    Ok(())
                }
            };
        }
        match kind {
            BlockKind::Start | BlockKind::Define => self.start_value(&name, s, n),
            _ if self.cpfg.globals.steps.iter().any(|(x, _, _)| *x == name)
                && !self.cpfg.globals.changed.contains(&name) =>
            {
                Ok(())
            }
            _ => Err(format!(
                "cpfg's {} statement '{s}' changes the variable {name} during the derivation; Meristem has no variables, so {name} keeps its start value",
                kind.written()
            )),
        }
    }

    /// `name = value` in `Start:`: a `#define` of the start value, or of its value at each step
    /// when a `StartEach:`/`EndEach:` block steps it by a constant.
    fn start_value(&mut self, name: &str, s: &str, n: usize) -> Result<(), String> {
        let Some((_, value)) = s.split_once('=') else {
            return Err(format!("'{s}' is not translated"));
        };
        let value = self.expression(value, &Env::new())?;
        let step = self
            .cpfg
            .globals
            .steps
            .iter()
            .find(|(x, _, _)| x == name)
            .cloned();
        let text = match step {
            Some((_, d, after)) if !self.cpfg.globals.changed.iter().any(|c| c == name) => {
                let steps = if after { "(NumIt-1)" } else { "NumIt" };
                format!("({value})+({d})*{steps}")
            }
            _ => value,
        };
        self.out.line(
            format!("{} {name} {text}", DirectiveKind::Define.written()),
            n,
        );
        Ok(())
    }

    /// `array name[k] = {a, b, …}` (after `array`); with more dimensions, `array name[k][m] =
    /// {…}` lists the values row after row, as C does.
    fn array(&mut self, rest: &str) -> Result<(), String> {
        let rest = rest.trim();
        let name: String = rest
            .chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect();
        let after = &rest[name.len()..];
        let open = after
            .find('{')
            .ok_or(format!("array {name} has no values"))?;
        let mut sizes = Vec::new();
        let mut dims = after[..open].trim();
        while let Some(inner) = dims.strip_prefix('[') {
            let close = inner
                .find(']')
                .ok_or(format!("array {name}: a '[' is never closed"))?;
            sizes.push(self.expression(&inner[..close], &Env::new())?);
            dims = inner[close + 1..].trim_start();
        }
        if sizes.is_empty() {
            return Err(format!("array {name} has no size"));
        }
        let close = after.rfind('}').unwrap_or(after.len());
        let listed = super::super::split_top(&after[open + 1..close.max(open + 1)], ',');
        // Each read of the array writes all its values (issue 50, 6: a million values made a
        // production of 2.5 GB).
        if listed.len() > MAX_ARRAY_VALUES {
            return Err(format!(
                "array {name} has {} values, more than the {MAX_ARRAY_VALUES} Meristem writes where an array is read: it is not translated, and the productions that read it are left out",
                listed.len()
            ));
        }
        let mut values = Vec::new();
        for v in listed {
            if !v.trim().is_empty() {
                values.push(self.expression(v, &Env::new())?);
            }
        }
        if values.is_empty() {
            return Err(format!("array {name} has no values"));
        }
        // The sizes of the dimensions after the first: what one step of each index skips.
        sizes.remove(0);
        self.cpfg.globals.arrays.push((name, sizes, values));
        Ok(())
    }

    /// The sizes (after the first) and the values of the array `name`, if it is an array.
    fn array_named(&self, name: &str) -> Option<(&[String], &[String])> {
        let (_, sizes, values) = self
            .cpfg
            .globals
            .arrays
            .iter()
            .find(|(a, _, _)| a == name)?;
        Some((sizes, values))
    }

    /// How many indices the array `name` takes, if it is an array.
    pub(in crate::import::abop) fn array_dimensions(&self, name: &str) -> Option<usize> {
        let (sizes, _) = self.array_named(name)?;
        Some(sizes.len() + 1)
    }

    /// `name[i][j]…` read from an array: the value at the index (truncated, as C does; the last
    /// value past the end, the first before it). The indices of an array of several dimensions
    /// give one index into its values, row after row, as C lays them out. The value is chosen by
    /// halving the range of indices, so that the choice nests as deep as the logarithm of the
    /// number of values.
    pub(in crate::import::abop) fn array_value(
        &self,
        name: &str,
        indices: &[String],
    ) -> Option<String> {
        let (sizes, values) = self.array_named(name)?;
        if indices.len() != sizes.len() + 1 || values.is_empty() {
            return None;
        }
        let mut index = String::new();
        for (k, i) in indices.iter().enumerate() {
            if k + 1 < indices.len() {
                index = format!("({index}floor({i}))*({})+", sizes[k]);
            } else {
                index.push_str(&format!("({i})"));
            }
        }
        fn pick(values: &[String], lo: usize, hi: usize, index: &str) -> String {
            if hi - lo == 1 {
                return values[lo].clone();
            }
            let mid = (lo + hi) / 2;
            format!(
                "(({index})<{}?{}:{})",
                number(mid as f64),
                pick(values, lo, mid, index),
                pick(values, mid, hi, index)
            )
        }
        Some(format!("({})", pick(values, 0, values.len(), &index)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_and_steps_are_read() {
        let (kind, s) = block("Start: {srand(5); n = 0; array a[2] = {1, 2};}").expect("block");
        assert_eq!(kind, BlockKind::Start);
        assert_eq!(s, ["srand(5)", "n = 0", "array a[2] = {1, 2}"]);
        assert_eq!(step("n = n + 1"), Some(("n".into(), "1".into())));
        assert_eq!(step("T += 0.5"), Some(("T".into(), "0.5".into())));
        assert_eq!(step("n = n * 2"), None);
        assert_eq!(assigned("x == 1"), None);
        assert_eq!(assigned("x += 1").as_deref(), Some("x"));
        assert_eq!(step("n=n+1/DEL"), Some(("n".into(), "1/DEL".into())));
    }

    #[test]
    fn a_start_each_value_of_stepped_variables_is_a_define_over_the_step() {
        let text = "#define DEL 16\nLsystem: 1\nStart: {n=1; c=2;}\nStartEach: {p=(2*n+1.0)/(n*n); q=1-p; r=c*2;}\nEndEach: {n=n+1/DEL; s=s*2;}\nStartEach: {t=s;}\nderivation length: 3\nAxiom: A\nA : ran(1) < p --> FA\nendlsystem\n";
        let import = crate::import::import(text, crate::import::Dialect::Cpfg);
        let defines: Vec<&str> = import
            .text
            .lines()
            .filter(|l| l.starts_with("#define"))
            .collect();
        assert_eq!(
            defines,
            [
                "#define DEL 16",
                "#define n (1)+(1/DEL)*(NumIt-1)",
                "#define c 2",
                "#define p ((2*n+1.0)/(n*n))",
                "#define q (1-p)",
                "#define r (c*2)",
            ]
        );
        // s doubles (no step by a constant), so t, set from it, changes too: both noted.
        let noted: Vec<&str> = import.notes.iter().map(|n| n.message.as_str()).collect();
        assert!(
            noted
                .iter()
                .any(|m| m.contains("'s=s*2' changes the variable s")),
            "{noted:?}"
        );
        assert!(
            noted
                .iter()
                .any(|m| m.contains("'t=s' changes the variable t")),
            "{noted:?}"
        );
    }
}
