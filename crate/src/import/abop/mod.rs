//! The reader of ABOP's notation (*The Algorithmic Beauty of Plants*), as cpfg `.l` (the
//! Virtual Laboratory, with lpfg's L+C), and L-Py `.lpy` (OpenAlea) write it -> Meristem.
//!
//! All write `Axiom:`, `derivation length:`, `ignore:`/`consider:`, productions
//! `lc < pred > rc : cond --> succ`, `homomorphism`/`interpretation:`, `decomposition`,
//! `maximum depth:`, `endlsystem`: this module and its shared files read that ([`prepare`],
//! [`statements`], [`productions`], [`modules`], [`expressions`]). Each dialect adds its own:
//! cpfg ([`cpfg`]) runs the file through the C preprocessor (`#define`, `/* */`) and may put
//! statement blocks `{x = …;}` before and after a condition and a probability after the
//! successor (`--> succ : 0.3`); lpfg ([`lpfg`]) writes C blocks with `produce`; L-Py ([`lpy`])
//! is Python: `#` comments, `NAME = value` assignments before the L-system, productions whose
//! body is Python (`A(t) :` then `if t < 3: produce …`). The importer translates the notation,
//! straight-line statement blocks (substituted into the condition and successor), Python
//! assignments of numbers (as `#define`s), Python expressions (`**`, `and`, `x if c else y`,
//! trigonometry in radians), and production bodies made only of `if`/`elif`/`else` and
//! `produce` (one Meristem production per branch, in order: Meristem applies the first that
//! matches, as L-Py does). Anything else is reported and left out.

mod cpfg;
mod expressions;
mod lpfg;
mod lpy;
mod modules;
mod prepare;
mod productions;
mod statements;
#[cfg(test)]
mod tests;

use super::vlab::View;
use super::{Import, Output};
use crate::syntax::{PARENTHESES, PARENTHESES_AND_BRACES};
use cpfg::globals;
use lpy::flags;
use std::collections::HashMap;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Flavour {
    Cpfg,
    Lpy,
}

impl Flavour {
    fn tool(self) -> &'static str {
        match self {
            Flavour::Cpfg => "cpfg",
            Flavour::Lpy => "L-Py",
        }
    }
}

/// One line of code with its comment taken out.
#[derive(Clone, Debug)]
struct Line {
    n: usize,
    code: String,
    comment: String,
    indent: usize,
}

pub(super) fn import(text: &str, flavour: Flavour) -> Import {
    import_with(text, flavour, None, &|_| None)
}

/// Imports `text` with what the rest of its vlab object says (`view`: `None` for a file alone),
/// reading `#include`d files through `include`.
pub(super) fn import_with(
    text: &str,
    flavour: Flavour,
    view: Option<&View>,
    include: &dyn Fn(&str) -> Option<String>,
) -> Import {
    let new = |probe: bool, flag_steps: Vec<(String, Option<u32>)>| Importer {
        flavour,
        out: Output::default(),
        declared: Vec::new(),
        in_productions: true,
        noted: Vec::new(),
        axiom: false,
        cpfg: CpfgState {
            view: view.cloned(),
            ..CpfgState::default()
        },
        lpfg: LpfgState::default(),
        lpy: LpyState {
            probe,
            flag_steps,
            ..LpyState::default()
        },
    };
    // L-Py flags (see `flags.rs`): a first run marks where they are set; when it found any, the
    // model is derived to find when, and imported again with that.
    let mut importer = new(flavour == Flavour::Lpy, Vec::new());
    importer.run(text, include);
    if !importer.lpy.flags_written.is_empty() {
        let probe = importer.out.finish().text;
        let written = &importer.lpy.flags_written;
        let steps = written
            .iter()
            .zip(flags::first_steps(&probe, written))
            .filter_map(|(&k, step)| Some((importer.lpy.flags[k].name.clone(), step?)))
            .collect();
        importer = new(false, steps);
        importer.run(text, include);
    }
    let mut import = importer.out.finish();
    if uses_randomness(&import.text) {
        let tool = flavour.tool();
        let at = import.notes.iter().take_while(|n| n.line == 0).count();
        import.notes.insert(
            at,
            super::ImportNote {
                line: 0,
                message: format!("{tool} draws its random numbers with another generator than Meristem's: the same seed gives a different plant than in {tool} (the distribution of plants is the same)"),
            },
        );
    }
    import
}

/// True when a translation draws random numbers: a random function (`uniform(…)`, `normal(…)`,
/// …) or a stochastic production (`-> (0.3) succ`) on a line that is not a comment.
fn uses_randomness(text: &str) -> bool {
    let random: Vec<&str> = crate::vocabulary::FUNCTIONS
        .iter()
        .filter(|f| f.random)
        .map(|f| f.name)
        .collect();
    text.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .any(|code| {
            let weighted = code
                .match_indices("->")
                .any(|(i, _)| code[i + 2..].trim_start().starts_with('('));
            weighted
                || random.iter().any(|name| {
                    code.match_indices(name).any(|(i, _)| {
                        code[i + name.len()..].starts_with('(')
                            && !code[..i].ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_')
                    })
                })
        })
}

/// The translation of one file: what every dialect reads with ([`Output`], the names declared,
/// the section) and each dialect's own state.
struct Importer {
    flavour: Flavour,
    out: Output,
    /// Multi-letter module names (L-Py `module` declarations and names met in strings).
    declared: Vec<String>,
    /// Whether the section being read is the productions (not decomposition or homomorphism).
    in_productions: bool,
    /// The keys of the notes given once (see [`Importer::note_once`]).
    noted: Vec<String>,
    /// Whether an axiom was written.
    axiom: bool,
    cpfg: CpfgState,
    lpfg: LpfgState,
    lpy: LpyState,
}

/// What reading a cpfg file keeps.
#[derive(Default)]
struct CpfgState {
    /// cpfg predecessors of several letter modules (`AXIOM --> …`): the letters as written and
    /// the one Meristem module they become, longest first.
    words: Vec<(String, String)>,
    /// The lines of cpfg's `homomorphism` and `decomposition` sections that do not set their
    /// `maximum depth:` (cpfg's default is 1).
    default_depth: Vec<usize>,
    /// The vlab object's view and colours (cpfg, opened with its object).
    view: Option<View>,
    /// A turn without an angle was written (it turns by the view's angle increment).
    bare_turn: bool,
    /// A colour module was written.
    colour: bool,
    /// cpfg's global variables, arrays and `Start:`… blocks.
    globals: globals::Globals,
    /// While a production's blocks are read: the variables that draw random numbers.
    draws: Option<cpfg::draws::Draws>,
    /// The decomposition productions of the auxiliary modules of draws, for the end.
    staged: Vec<String>,
    /// How many auxiliary modules of draws were made (their names count).
    stage_count: usize,
    /// Whether the file has a decomposition section of its own.
    has_decomposition: bool,
    /// While a production's blocks are read: `Some` when a loop may be read, with the loop.
    loops: Option<Option<cpfg::loops::Loop>>,
    /// Lines to write after the production being read (a loop's productions).
    after: Vec<String>,
    /// The staged section holds a loop: its depth is raised.
    staged_depth: bool,
    /// A production of the file has a context of its own.
    other_contexts: bool,
    /// The `#consider` or `#ignore` line written: its output line, its directive, its names.
    context_list: Option<(usize, String, Vec<String>)>,
    /// The output line of the `maximum depth:` of the section being read, and its value.
    depth_line: Option<(usize, String)>,
    /// Where the object's functions are written (after the view's lines), and which of them
    /// (indices into the view's functions, in the order first read) the L-system reads, with
    /// their lines.
    functions_at: Option<usize>,
    used_functions: Vec<(usize, Vec<String>)>,
    /// The bytes of those lines.
    function_bytes: usize,
}

/// What reading an L+C (lpfg) file keeps.
#[derive(Default)]
struct LpfgState {
    /// Whether the `.l` is an L+C (lpfg) file: `module` declarations, `produce` in C blocks.
    active: bool,
    /// While an lpfg production's block is read: the successors it produces, each with the
    /// condition of the path to its `produce`.
    produced: Option<Vec<(Option<String>, String)>>,
    /// The conditions of the `if`s the statement being read is in (lpfg).
    path: Vec<String>,
    /// The `#define`d constants and their values (an lpfg surface id names one).
    constants: Vec<(String, f64)>,
}

/// What reading an L-Py file keeps.
#[derive(Default)]
struct LpyState {
    /// L-Py globals that nothing reads but text labels (`@L`, dropped): their `global`
    /// statements and the assignments to them in production bodies can be dropped.
    write_only: Vec<String>,
    /// L-Py globals that may be flags (see `flags.rs`).
    flags: Vec<flags::Flag>,
    /// Whether this run is the probe that finds when flags change (markers in the successors).
    probe: bool,
    /// The flags (indices into `flags`) whose setting the probe marked.
    flags_written: Vec<usize>,
    /// After the probe: each flag's name and the first step its setting production applies in
    /// (`None`: never within the derivation length).
    flag_steps: Vec<(String, Option<u32>)>,
    /// L-Py helper functions that return one expression: name, parameters, the expression
    /// (translated), inlined where they are called.
    helpers: Vec<(String, Vec<String>, String)>,
    /// Long names that are neither declared nor L-Py's (written as modules, reported once).
    unknown_names: Vec<String>,
}

/// The byte index of the first `token` outside brackets, braces and parentheses.
fn top_level(text: &str, token: &str) -> Option<usize> {
    PARENTHESES_AND_BRACES.find_str(text, token)
}

/// Splits at `sep` outside parentheses.
fn split_top(text: &str, sep: char) -> Vec<&str> {
    PARENTHESES
        .split(text, sep)
        .into_iter()
        .map(|(_, piece)| piece)
        .collect()
}

/// The production arrow: `-->` or `->` outside parentheses; (start, end).
fn arrow(code: &str) -> Option<(usize, usize)> {
    if let Some(i) = top_level(code, "-->") {
        // `- --> +` or `---> +`: the first '-' of "--->" is the predecessor.
        if i == 0 || !code[..i].trim().is_empty() {
            return Some((i, i + 3));
        }
        return Some((i + 1, i + 4));
    }
    top_level(code, "->").map(|i| (i, i + 2))
}

fn is_identifier(s: &str) -> bool {
    s.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// A `{ … }` statement block's bindings: each `name = expr;` in order.
type Env = HashMap<String, String>;

impl Importer {
    fn note(&mut self, line: usize, message: impl Into<String>) {
        self.out.note(line, message);
    }

    fn note_once(&mut self, key: &str, line: usize, message: impl Into<String>) {
        if !self.noted.iter().any(|k| k == key) {
            self.noted.push(key.to_string());
            self.out.note(line, message);
        }
    }
}

/// The module names of a translated module string (for `#ignore`, `#consider`).
fn module_names(modules: &str) -> Vec<String> {
    let (file, _) = crate::syntax::parse(&format!("axiom: {modules}"));
    file.axiom
        .map(|(m, _)| m.into_iter().map(|m| m.name).collect())
        .unwrap_or_default()
}

/// A string that starts with exactly two rolls is written `/ /…`, so that Meristem does not read
/// `//` after a space as a comment.
fn separate(s: &str) -> String {
    if s.starts_with("//") && !s.starts_with("///") {
        format!("/ {}", &s[1..])
    } else {
        s.to_string()
    }
}
