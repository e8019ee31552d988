//! Importers: other L-system notations translated into Meristem's language (text in, text out),
//! with a note for every construct that could not be translated, at its line.
//!
//! One module per dialect: [`green`] (Green's RL-systems), [`lparser`] (Laurens Lapré's Lparser
//! `.ls`, positional and keyword formats), [`abop`] (ABOP's notation as cpfg `.l`, lpfg and L-Py
//! `.lpy` write it). Each builds its output with an [`Output`], whose [`Output::finish`] checks the text
//! with Meristem's own parser and resolver: a line Meristem rejects is commented out and reported,
//! so an import never hands the editor a grammar with errors unless it has no axiom at all.
//! Like the rest of the core, nothing here does IO or panics on any input.
//!
//! L-Py models and lpfg's L+C are programs: when the hand translation of one falls short
//! ([`needs_python`]), the model is run by Python (the CLI runs `python3`, the studio Pyodide) and
//! [`import_derived`] turns the derived string into Meristem text ([`derived`]).

mod abop;
mod derived;
mod green;
mod lparser;
mod output;
#[cfg(test)]
mod test_support;
mod vlab;
mod zip;

pub use derived::{import_derived, needs_python, prefer_derived, DerivedRun};
pub use vlab::{import_files, import_object, python_main, ObjectFile, PythonMain};
pub use zip::{unzip, MAX_ENTRIES as MAX_OBJECT_FILES, MAX_TOTAL as MAX_OBJECT_BYTES};

use crate::maths;
use serde::{Deserialize, Serialize};

pub(crate) use output::{defuse_comment, Output};

/// A notation the importers read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Dialect {
    /// Green's RL-systems: `SYSTEM DECLARATIONS AXIOM RULES END.` (Lluch et al.).
    Green,
    /// Laurens Lapré's Lparser `.ls`, the positional (1.x-4.x) and the keyword (2.x) format.
    Lparser,
    /// cpfg `.l` (the Virtual Laboratory's plant simulator).
    Cpfg,
    /// L-Py `.lpy` (OpenAlea).
    Lpy,
}

impl Dialect {
    /// Every dialect, in the order of the documentation.
    pub const ALL: [Dialect; 4] = [
        Dialect::Green,
        Dialect::Lparser,
        Dialect::Cpfg,
        Dialect::Lpy,
    ];

    /// The name used by `--from` and the wasm boundary: `green`, `lparser`, `cpfg`, `lpy`.
    pub fn name(self) -> &'static str {
        match self {
            Dialect::Green => "green",
            Dialect::Lparser => "lparser",
            Dialect::Cpfg => "cpfg",
            Dialect::Lpy => "lpy",
        }
    }

    /// The dialect of a name (case-insensitive), or `None`.
    pub fn from_name(name: &str) -> Option<Dialect> {
        Dialect::ALL
            .into_iter()
            .find(|d| d.name().eq_ignore_ascii_case(name.trim()))
    }
}

/// Something the importer could not translate (or translated only approximately), at a 1-based
/// line of the imported text (0 when it concerns the whole file).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ImportNote {
    pub line: usize,
    pub message: String,
}

/// The result of an import: Meristem text, and the notes.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Import {
    pub text: String,
    pub notes: Vec<ImportNote>,
}

impl Import {
    /// True when nothing could be imported: the text has no axiom to derive.
    pub fn is_empty(&self) -> bool {
        crate::syntax::parse(&self.text).0.axiom.is_none()
    }
}

/// Translates `text`, written in `dialect`, into Meristem's language.
pub fn import(text: &str, dialect: Dialect) -> Import {
    match dialect {
        Dialect::Green => green::import(text),
        Dialect::Lparser => lparser::import(text),
        Dialect::Cpfg => abop::import(text, abop::Flavour::Cpfg),
        Dialect::Lpy => abop::import(text, abop::Flavour::Lpy),
    }
}

/// Guesses the dialect of a file from its name's extension (`.ls` Lparser, `.l` cpfg, `.lpy`
/// L-Py), else from its content (Green's `SYSTEM … RULES … END.`, Lparser's keywords or its
/// numeric header and `@` end mark, L-Py's `production:`/`interpretation:` sections or Python
/// assignments, cpfg's `Lsystem:`). `None` for Meristem's own `.lsys` and for text that is none of
/// these. `file_name` may be empty.
pub fn detect(text: &str, file_name: &str) -> Option<Dialect> {
    let lower = file_name.to_ascii_lowercase();
    let extension = lower.rsplit_once('.').map(|(_, e)| e).unwrap_or("");
    match extension {
        "ls" => return Some(Dialect::Lparser),
        "l" => return Some(Dialect::Cpfg),
        "lpy" => return Some(Dialect::Lpy),
        "lsys" => return None,
        _ => {}
    }
    let lines: Vec<&str> = text.lines().map(str::trim).collect();
    let upper = |l: &&str| l.to_ascii_uppercase();
    if lines.iter().any(|l| upper(l) == "RULES")
        && lines
            .iter()
            .any(|l| upper(l) == "SYSTEM" || upper(l).starts_with("SYSTEM "))
    {
        return Some(Dialect::Green);
    }
    let content: Vec<&str> = lines
        .iter()
        .copied()
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .collect();
    let keyword = |l: &&str| {
        let word = l.split_whitespace().next().unwrap_or("");
        matches!(word, "recursion" | "rule" | "axiom" | "angle" | "thickness")
    };
    if content.iter().filter(|l| keyword(l)).count() >= 2
        && content.iter().any(|l| l.starts_with("rule "))
    {
        return Some(Dialect::Lparser);
    }
    let numeric = |l: &str| {
        l.split(|c: char| c.is_whitespace() || c == '#')
            .next()
            .is_some_and(|w| w.parse::<f64>().is_ok())
    };
    if content.len() >= 4
        && content[..3].iter().all(|l| numeric(l))
        && content.iter().any(|l| l.starts_with('@'))
    {
        return Some(Dialect::Lparser);
    }
    let has = |prefix: &str| {
        lines
            .iter()
            .any(|l| l.to_ascii_lowercase().starts_with(prefix))
    };
    let python_assignment = lines.iter().any(|l| {
        l.split_once('=').is_some_and(|(left, right)| {
            let name = left.trim();
            !right.starts_with('=')
                && !name.is_empty()
                && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
                && !name.starts_with(|c: char| c.is_ascii_digit())
        })
    });
    // dialect: cpfg's and L-Py's keyword
    if has("axiom:") {
        if has("production:") || has("interpretation:") || has("def ") || python_assignment {
            return Some(Dialect::Lpy);
        }
        // dialect: cpfg's
        if has("lsystem:") || has("derivation length") || has("#define") {
            return Some(Dialect::Cpfg);
        }
    }
    None
}

/// `sscanf("%f")`: the number at the start of `s` (after spaces), if any.
pub(crate) fn leading_float(s: &str) -> Option<f64> {
    let s = s.trim_start();
    let b = s.as_bytes();
    let mut i = 0;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    let digits_start = i;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    if i < b.len() && b[i] == b'.' {
        i += 1;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
    }
    if i == digits_start || (i == digits_start + 1 && b[digits_start] == b'.') {
        return None;
    }
    let mantissa_end = i;
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        let exp_digits = j;
        while j < b.len() && b[j].is_ascii_digit() {
            j += 1;
        }
        if j > exp_digits {
            i = j;
        }
    }
    s[..i]
        .parse::<f64>()
        .ok()
        .or_else(|| s[..mantissa_end].parse().ok())
        .filter(|v| v.is_finite())
}

/// A number as Meristem text: shortest round trip of the value rounded to 12 significant digits
/// (so `0.8 * 0.9` prints `0.72`), integers without a fraction.
pub(crate) fn number(value: f64) -> String {
    if !value.is_finite() {
        return "0".into();
    }
    if value == 0.0 {
        return "0".into();
    }
    let digits = 12 - 1 - maths::log10(value.abs()).floor() as i32;
    let rounded = if (0..=300).contains(&digits) {
        let scale = 10f64.powi(digits);
        let r = (value * scale).round() / scale;
        if r.is_finite() {
            r
        } else {
            value
        }
    } else {
        value
    };
    format!("{rounded}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dialect_names_round_trip() {
        for d in Dialect::ALL {
            assert_eq!(Dialect::from_name(d.name()), Some(d));
            assert_eq!(Dialect::from_name(&d.name().to_uppercase()), Some(d));
        }
        assert_eq!(Dialect::from_name("lsys"), None);
    }

    #[test]
    fn detection_uses_the_extension_then_the_content() {
        assert_eq!(detect("", "tree.LS"), Some(Dialect::Lparser));
        assert_eq!(detect("", "a/b/plant.l"), Some(Dialect::Cpfg));
        assert_eq!(detect("", "x.lpy"), Some(Dialect::Lpy));
        assert_eq!(detect("SYSTEM\nAXIOM\nRULES\nEND.", "x.lsys"), None);
        assert_eq!(
            detect("SYSTEM\nAXIOM\n A\nRULES\n A -> B\nEND.", ""),
            Some(Dialect::Green)
        );
        assert_eq!(
            detect("recursion 5\naxiom F\nrule F = FF\n", "tree.txt"),
            Some(Dialect::Lparser)
        );
        assert_eq!(
            detect("# c\n5\n20\n10 # t\nF\nF=FF\n@\n", ""),
            Some(Dialect::Lparser)
        );
        assert_eq!(
            detect("a = 3\nAxiom: A\nproduction:\nA --> B\n", ""),
            Some(Dialect::Lpy)
        );
        assert_eq!(
            detect("Lsystem: 1\nAxiom: A\nA --> B\nendlsystem\n", ""),
            Some(Dialect::Cpfg)
        );
        assert_eq!(detect("axiom: F\nF -> FF\n", "plain.txt"), None);
    }

    #[test]
    fn numbers_print_short() {
        assert_eq!(number(0.8 * 0.9), "0.72");
        assert_eq!(number(1.0), "1");
        assert_eq!(number(1.0 / 0.9), "1.11111111111");
        assert_eq!(number(343.774677078494), "343.774677078");
        assert_eq!(number(-2.5), "-2.5");
        assert_eq!(number(1e-7), "0.0000001");
        assert_eq!(number(f64::NAN), "0");
    }

    #[test]
    fn finish_comments_out_what_meristem_rejects_and_says_so() {
        let mut out = Output::default();
        out.line("axiom: A", 1);
        out.line("A -> B(frob(1))", 2);
        out.line("B -> [", 3);
        let import = out.finish();
        assert!(import.text.contains("// not imported: A -> B(frob(1))"));
        assert!(import.text.contains("// not imported: B -> ["));
        assert_eq!(
            import.notes.iter().map(|n| n.line).collect::<Vec<_>>(),
            [2, 3]
        );
        assert!(import.notes[0].message.contains("unknown function 'frob'"));
        let (file, d) = crate::syntax::parse(&import.text);
        assert!(d.is_empty() && crate::model::resolve(&file).1.is_empty());
    }

    #[test]
    fn finish_reports_a_missing_axiom_once() {
        let mut out = Output::default();
        out.line("A -> B", 4);
        let import = out.finish();
        assert!(import.is_empty());
        assert_eq!(import.notes.len(), 1);
        assert_eq!(import.notes[0].line, 0);
    }
}
