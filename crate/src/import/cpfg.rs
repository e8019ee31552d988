//! The common subset of cpfg `.l` (the Virtual Laboratory) and L-Py `.lpy` (OpenAlea) -> Meristem.
//!
//! Both write ABOP's notation: `Axiom:`, `derivation length:`, `ignore:`/`consider:`,
//! productions `lc < pred > rc : cond --> succ`, `homomorphism`/`interpretation:`,
//! `decomposition`, `maximum depth:`, `endlsystem`. cpfg runs the file through the C
//! preprocessor (`#define`, `/* */`) and may put statement blocks `{x = …;}` before and after a
//! condition and a probability after the successor (`--> succ : 0.3`); L-Py is Python: `#`
//! comments, `NAME = value` assignments before the L-system, productions whose body is Python
//! (`A(t) :` then `if t < 3: produce …`). The importer translates the notation, straight-line
//! statement blocks (substituted into the condition and successor), Python assignments of
//! numbers (as `#define`s), Python expressions (`**`, `and`, `x if c else y`, trigonometry in
//! radians), and production bodies made only of `if`/`elif`/`else` and `produce` (one Meristem
//! production per branch, in order: Meristem applies the first that matches, as L-Py does).
//! Anything else is reported and left out.

mod blocks;
mod cpp;
mod flags;
mod globals;
mod lpfg;
mod view;

use super::vlab::View;
use super::{Import, Output};
use crate::vocabulary::{module_named, name_of, Command, DirectiveKind, KeywordKind, Meaning};
use blocks::{closing, MAX_VALUE};
use flags::Flag;
use lpfg::{is_lpfg, lpfg_production_parts};
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

/// `180 / π`: L-Py's trigonometry is Python's, in radians; Meristem's is in degrees.
const DEGREES: &str = "57.2957795131";

/// L-Py's predefined modules with long names that have a Meristem command.
const LPY_NAMES: &[(&str, Meaning)] = &[
    ("TurnLeft", Meaning::Turtle(Command::TurnLeft)),
    ("TurnRight", Meaning::Turtle(Command::TurnRight)),
    ("PitchDown", Meaning::Turtle(Command::PitchDown)),
    ("PitchUp", Meaning::Turtle(Command::PitchUp)),
    ("RollLeft", Meaning::Turtle(Command::RollLeft)),
    ("RollRight", Meaning::Turtle(Command::RollRight)),
    ("TurnAround", Meaning::Turtle(Command::TurnAround)),
    ("RollToVert", Meaning::Turtle(Command::RollToVertical)),
    ("SetWidth", Meaning::Turtle(Command::Width)),
    ("SetColor", Meaning::Turtle(Command::SetColor)),
    ("IncColor", Meaning::Turtle(Command::SetColor)),
    ("Sphere", Meaning::Turtle(Command::Sphere)),
    ("MoveTo", Meaning::Turtle(Command::MoveTo)),
    ("StartGC", Meaning::Turtle(Command::StartSmooth)),
    ("EndGC", Meaning::Turtle(Command::EndSmooth)),
    ("Cut", Meaning::Cut),
    ("GetPos", Meaning::Turtle(Command::QueryPosition)),
    ("GetHead", Meaning::Turtle(Command::QueryHeading)),
    ("GetUp", Meaning::Turtle(Command::QueryUp)),
    ("GetLeft", Meaning::Turtle(Command::QueryLeft)),
];

/// L-Py's other predefined modules with names longer than a letter (its `predefinedmodules.cpp`):
/// a word among them is one module even undeclared; any other undeclared word is read letter by
/// letter, as L-Py reads it (`IB(1-x)` is `I` then `B(1-x)`).
const LPY_PREDEFINED: &[&str] = &[
    "GetRight",
    "GetFrame",
    "BP",
    "EP",
    "PP",
    "MoveRel",
    "LineTo",
    "OLineTo",
    "Pinpoint",
    "LineRel",
    "OLineRel",
    "PinpointRel",
    "SetHead",
    "EulerAngles",
    "Left",
    "Right",
    "Up",
    "Down",
    "RollL",
    "RollR",
    "iRollL",
    "iRollR",
    "RollToHorizontal",
    "Box",
    "Quad",
    "Circle",
    "Label",
    "IncWidth",
    "DecWidth",
    "DecColor",
    "InterpolateColors",
    "TextureBaseColor",
    "InterpolateTextureBaseColors",
    "DivScale",
    "MultScale",
    "SetScale",
    "surface",
    "PglShape",
    "Frame",
    "Arrow",
    "Elasticity",
    "Tropism",
    "SetContour",
    "SectionResolution",
    "SetGuide",
    "EndGuide",
    "Sweep",
    "PositionOnGuide",
    "TextureScale",
    "TextureUScale",
    "TextureVScale",
    "TextureVCoeff",
    "TextureTranslation",
    "TextureRotation",
    "TextureTransformation",
    "LeftReflection",
    "UpReflection",
    "HeadingReflection",
    "StartScreenProjection",
    "EndScreenProjection",
    "MouseIns",
    "newmodule",
];

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
        flags: Vec::new(),
        probe,
        flags_written: Vec::new(),
        flag_steps,
        in_productions: true,
        flavour,
        out: Output::default(),
        declared: Vec::new(),
        words: Vec::new(),
        write_only: Vec::new(),
        lpfg: false,
        default_depth: Vec::new(),
        produced: None,
        path: Vec::new(),
        unknown_names: Vec::new(),
        noted: Vec::new(),
        axiom: false,
        view: view.cloned(),
        helpers: Vec::new(),
        bare_turn: false,
        colour: false,
        globals: globals::Globals::default(),
    };
    // L-Py flags (see `flags.rs`): a first run marks where they are set; when it found any, the
    // model is derived to find when, and imported again with that.
    let mut importer = new(flavour == Flavour::Lpy, Vec::new());
    importer.run(text, include);
    if !importer.flags_written.is_empty() {
        let probe = importer.out.finish().text;
        let steps = importer
            .flags_written
            .iter()
            .filter_map(|&k| {
                let step = flags::first_step(&probe, &flags::marker(k))?;
                Some((importer.flags[k].name.clone(), step))
            })
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

struct Importer {
    flavour: Flavour,
    out: Output,
    /// Multi-letter module names (L-Py `module` declarations and names met in strings).
    declared: Vec<String>,
    /// cpfg predecessors of several letter modules (`AXIOM --> …`): the letters as written and
    /// the one Meristem module they become, longest first.
    words: Vec<(String, String)>,
    /// L-Py globals that nothing reads but text labels (`@L`, dropped): their `global`
    /// statements and the assignments to them in production bodies can be dropped.
    write_only: Vec<String>,
    /// The lines of cpfg's `homomorphism` and `decomposition` sections that do not set their
    /// `maximum depth:` (cpfg's default is 1).
    default_depth: Vec<usize>,
    /// L-Py globals that may be flags (see `flags.rs`).
    flags: Vec<flags::Flag>,
    /// Whether this run is the probe that finds when flags change (markers in the successors).
    probe: bool,
    /// The flags (indices into `flags`) whose setting the probe marked.
    flags_written: Vec<usize>,
    /// After the probe: each flag's name and the first step its setting production applies in
    /// (`None`: never within the derivation length).
    flag_steps: Vec<(String, Option<u32>)>,
    /// Whether the section being read is the productions (not decomposition or homomorphism).
    in_productions: bool,
    /// Whether the `.l` is an L+C (lpfg) file: `module` declarations, `produce` in C blocks.
    lpfg: bool,
    /// While an lpfg production's block is read: the successors it produces, each with the
    /// condition of the path to its `produce`.
    produced: Option<Vec<(Option<String>, String)>>,
    /// The conditions of the `if`s the statement being read is in (lpfg).
    path: Vec<String>,
    /// Long names that are neither declared nor L-Py's (written as modules, reported once).
    unknown_names: Vec<String>,
    noted: Vec<String>,
    axiom: bool,
    /// The vlab object's view and colours (cpfg, opened with its object).
    view: Option<View>,
    /// L-Py helper functions that return one expression: name, parameters, the expression
    /// (translated), inlined where they are called.
    helpers: Vec<(String, Vec<String>, String)>,
    /// A turn without an angle was written (it turns by the view's angle increment).
    bare_turn: bool,
    /// A colour module was written.
    colour: bool,
    /// cpfg's global variables, arrays and `Start:`… blocks.
    globals: globals::Globals,
}

/// Splits the text into lines without comments: cpfg's `/* … */` and `//`, L-Py's `#`.
fn lines(text: &str, flavour: Flavour) -> Vec<Line> {
    let mut result = Vec::new();
    let mut in_block = false;
    // L-Py: the triple quote of a Python string that runs over several lines.
    let mut in_string: Option<&str> = None;
    for (index, raw) in text.lines().enumerate() {
        if flavour == Flavour::Lpy {
            if let Some(line) = python_string_line(raw, &mut in_string) {
                result.push(Line {
                    n: index + 1,
                    ..line
                });
                continue;
            }
        }
        let mut code = String::new();
        let mut comment = String::new();
        let chars: Vec<char> = raw.chars().collect();
        let mut i = 0;
        let mut quote: Option<char> = None;
        while i < chars.len() {
            let c = chars[i];
            if in_block {
                if c == '*' && chars.get(i + 1) == Some(&'/') {
                    in_block = false;
                    i += 2;
                    comment.push(' ');
                    continue;
                }
                comment.push(c);
                i += 1;
                continue;
            }
            if let Some(q) = quote {
                code.push(c);
                if c == q {
                    quote = None;
                }
                i += 1;
                continue;
            }
            match flavour {
                Flavour::Cpfg => {
                    if c == '/' && chars.get(i + 1) == Some(&'*') {
                        in_block = true;
                        i += 2;
                        continue;
                    }
                    if c == '/' && chars.get(i + 1) == Some(&'/') {
                        comment.extend(&chars[i + 2..]);
                        break;
                    }
                }
                Flavour::Lpy => {
                    if c == '\'' || c == '"' {
                        quote = Some(c);
                    } else if c == '#' {
                        comment.extend(&chars[i + 1..]);
                        break;
                    }
                }
            }
            code.push(c);
            i += 1;
        }
        let indent = code.chars().take_while(|c| c.is_whitespace()).count();
        result.push(Line {
            n: index + 1,
            code: code.trim().to_string(),
            comment: comment.trim().to_string(),
            indent,
        });
    }
    result
}

/// A line of L-Py text that a Python string over several lines (`"""…"""`, a docstring)
/// opens, continues or closes: the string's text becomes a comment, and the line that opens it
/// keeps its code with the string closed there. `None` for any other line.
fn python_string_line<'a>(raw: &str, in_string: &mut Option<&'a str>) -> Option<Line> {
    if let Some(quote) = *in_string {
        let (text, code) = match raw.find(quote) {
            Some(end) => {
                *in_string = None;
                (&raw[..end], raw[end + quote.len()..].trim())
            }
            None => (raw, ""),
        };
        return Some(Line {
            n: 0,
            code: code.to_string(),
            comment: text.trim().to_string(),
            indent: raw.len() - raw.trim_start().len(),
        });
    }
    let quote: &'a str = ["\"\"\"", "'''"]
        .into_iter()
        .find(|q| raw.matches(q).count() % 2 == 1)?;
    let open = raw.find(quote)?;
    *in_string = Some(quote);
    let code = raw[..open].trim();
    let text = raw[open + quote.len()..].trim();
    // An assignment of the string (`__description__ = """…`) keeps it, closed on its first
    // line; a docstring is a comment.
    let (code, comment) = if code.ends_with('=') {
        (format!("{code} {quote}{text}{quote}"), String::new())
    } else {
        (code.to_string(), text.to_string())
    };
    Some(Line {
        n: 0,
        code,
        comment,
        indent: raw.len() - raw.trim_start().len(),
    })
}

/// cpfg's statement blocks `{ … }` may span lines: a line whose braces are not closed takes the
/// lines after it until they are.
fn join_blocks(lines: Vec<Line>, flavour: Flavour) -> Vec<Line> {
    if flavour != Flavour::Cpfg {
        return lines;
    }
    let mut joined: Vec<Line> = Vec::new();
    let mut open = 0i32;
    for line in lines {
        let delta = line.code.matches('{').count() as i32 - line.code.matches('}').count() as i32;
        match joined.last_mut() {
            Some(last) if open > 0 => {
                if !line.code.is_empty() {
                    last.code.push(' ');
                    last.code.push_str(&line.code);
                }
                if !line.comment.is_empty() {
                    last.comment.push(' ');
                    last.comment.push_str(&line.comment);
                }
            }
            _ => joined.push(line),
        }
        open = (open + delta).max(0);
    }
    joined
}

/// The functions a cpfg `#define` value may call and stay a number expression: Meristem's and
/// cpfg's own.
fn cpp_functions() -> Vec<String> {
    crate::vocabulary::FUNCTIONS
        .iter()
        .map(|f| f.name.to_string())
        .chain(
            ["func", "tfunc", "ran", "nran", "trunc", "fabs", "pow"]
                .iter()
                .map(|s| s.to_string()),
        )
        .collect()
}

/// True when a line starts with one of the notation's keywords (it is no part of a production).
fn starts_with_keyword(code: &str) -> bool {
    let lower = code.to_ascii_lowercase();
    let compact: String = lower.chars().filter(|c| !c.is_whitespace()).collect();
    code.starts_with('#')
        || section(&lower).is_some()
        // dialect: cpfg's keywords, without their spaces
        || "axiom: derivationlength ignore: consider: maximumdepth lsystem: endlsystem start: starteach: end: endeach: define: seed:"
            .split(' ')
        .any(|k| compact.starts_with(k))
}

/// cpfg productions whose head (predecessor, condition, statement block) spans lines: a line at
/// the margin without an arrow, then indented lines (or lines opening with `{`, `:` or the
/// arrow) up to the one with the arrow, as vlab objects write them:
/// `N(k) < I(b,m,v,c) : b==0 && m==2` / `\t{flux=…;} -->` / `\tI(b,1,flux,c)`.
fn join_production_heads(mut lines: Vec<Line>) -> Vec<Line> {
    let mut i = 0;
    while i < lines.len() {
        let a = &lines[i];
        if a.indent > 0
            || a.code.is_empty()
            || arrow(&a.code).is_some()
            || starts_with_keyword(&a.code)
        {
            i += 1;
            continue;
        }
        let mut run = Vec::new();
        let mut found = false;
        for (j, b) in lines.iter().enumerate().skip(i + 1) {
            if b.code.is_empty() {
                if b.comment.is_empty() {
                    break;
                }
                continue;
            }
            let continues = b.indent > 0
                || ["{", ":", "-->", "->"]
                    .iter()
                    .any(|t| b.code.starts_with(t));
            if starts_with_keyword(&b.code) || !continues || run.len() == 6 {
                break;
            }
            run.push(j);
            if arrow(&b.code).is_some() {
                found = true;
                break;
            }
        }
        if found {
            let taken: Vec<Line> = run.iter().rev().map(|&j| lines.remove(j)).collect();
            for b in taken.into_iter().rev() {
                let code = format!("{} {}", lines[i].code, b.code);
                lines[i].code = code;
                if !b.comment.is_empty() {
                    let comment = format!("{} {}", lines[i].comment, b.comment);
                    lines[i].comment = comment.trim().to_string();
                }
            }
        }
        i += 1;
    }
    lines
}

/// The lines that open a cpfg `homomorphism` or `decomposition` section with no `maximum
/// depth:` line before the next section.
fn sections_without_depth(all: &[Line]) -> Vec<usize> {
    let mut out = Vec::new();
    let mut open: Option<usize> = None;
    for line in all {
        let lower = line.code.to_ascii_lowercase();
        if let Some(s) = section(&lower) {
            out.extend(open.take());
            let word = lower.split(':').next().unwrap_or("").trim().to_string();
            if s == KeywordKind::Homomorphism.written() && word == "homomorphism"
                || s == KeywordKind::Decomposition.written()
            {
                open = Some(line.n);
            }
        // dialect: cpfg's keyword
        } else if keyword(&lower, &line.code, "maximum depth:").is_some() {
            open = None;
        } else if lower.trim() == KeywordKind::EndLSystem.written() {
            out.extend(open.take());
        }
    }
    out.extend(open);
    out
}

/// cpfg's axiom continued on the lines after `Axiom:` that are indented more than it (and are
/// no production): one line.
fn join_axiom_lines(mut lines: Vec<Line>) -> Vec<Line> {
    let mut i = 0;
    while i < lines.len() {
        let compact: String = lines[i]
            .code
            .chars()
            .filter(|c| !c.is_whitespace())
            .collect::<String>()
            .to_ascii_lowercase();
        // dialect: cpfg's keyword
        if compact.starts_with("axiom:") && arrow(&lines[i].code).is_none() {
            while i + 1 < lines.len()
                && !lines[i + 1].code.is_empty()
                && lines[i + 1].indent > lines[i].indent
                && arrow(&lines[i + 1].code).is_none()
                && !starts_with_keyword(&lines[i + 1].code)
            {
                let next = lines.remove(i + 1);
                lines[i].code = format!("{} {}", lines[i].code, next.code);
            }
        }
        i += 1;
    }
    lines
}

/// cpfg productions written over two lines: `pred : cond` then `--> succ` on the next line, or
/// `pred -->` then the successor (at any indentation) on the next.
fn join_two_line_productions(lines: Vec<Line>) -> Vec<Line> {
    let mut lines = join_production_heads(lines);
    let mut i = 0;
    while i < lines.len() {
        let next = (i + 1..lines.len()).find(|&j| !lines[j].code.is_empty());
        let Some(j) = next else { break };
        let (a, b) = (&lines[i].code, &lines[j].code);
        let arrow_next = b.starts_with("-->") || b.starts_with("->");
        let open_arrow =
            arrow(a).is_some_and(|(_, end)| a[end..].trim().is_empty()) && arrow(b).is_none();
        let joins = !a.is_empty()
            && !starts_with_keyword(a)
            && !starts_with_keyword(b)
            && ((arrow_next && arrow(a).is_none()) || open_arrow);
        if joins {
            // The joined line goes, so that the successor's own continuation lines (indented,
            // see `production_lines`) follow the production directly.
            let joined = lines.remove(j);
            lines[i].code = format!("{} {}", lines[i].code, joined.code);
            if !joined.comment.is_empty() {
                let comment = format!("{} {}", lines[i].comment, joined.comment);
                lines[i].comment = comment.trim().to_string();
            }
            // `pred : cond` + `-->` alone may now be an open arrow: look again.
            continue;
        }
        i += 1;
    }
    lines
}

/// The byte index of the first `token` outside brackets, braces and parentheses.
fn top_level(text: &str, token: &str) -> Option<usize> {
    let mut depth = 0i32;
    let bytes = text.as_bytes();
    for (i, c) in text.char_indices() {
        match c {
            '(' | '{' => depth += 1,
            ')' | '}' => depth -= 1,
            _ => {}
        }
        if depth == 0 && bytes[i..].starts_with(token.as_bytes()) {
            return Some(i);
        }
    }
    None
}

/// L-Py's literal values in a predecessor (`D(20, k)`): each becomes a parameter `v_litK`, with
/// the condition `v_litK == 20`. Returns the pattern so rewritten and the conditions.
fn literal_parameters(pattern: &str) -> (String, Vec<String>) {
    let mut out = String::new();
    let mut conditions = Vec::new();
    let mut rest = pattern;
    while let Some(open) = rest.find('(') {
        out.push_str(&rest[..=open]);
        let chars: Vec<char> = rest[open..].chars().collect();
        let Some(close) = matching(&chars, 0) else {
            break;
        };
        let inner: String = chars[1..close].iter().collect();
        let params: Vec<String> = split_top(&inner, ',')
            .into_iter()
            .map(|p| match p.trim().parse::<f64>() {
                Ok(v) if v.is_finite() => {
                    let name = format!("v_lit{}", conditions.len() + 1);
                    conditions.push(format!("{name} == {}", super::number(v)));
                    name
                }
                _ => p.to_string(),
            })
            .collect();
        out.push_str(&params.join(","));
        out.push(')');
        let consumed: usize = chars[..=close].iter().map(|c| c.len_utf8()).sum();
        rest = &rest[open + consumed..];
    }
    out.push_str(rest);
    (out, conditions)
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

    /// The file's lines ready to translate: comments split off, cpfg's preprocessor run, blocks
    /// and productions over several lines joined, globals and L-Py's module declarations read.
    fn prepare(&mut self, text: &str, include: &dyn Fn(&str) -> Option<String>) -> Vec<Line> {
        let mut all = lines(text, self.flavour);
        if self.flavour == Flavour::Cpfg {
            let functions = cpp_functions();
            let names: Vec<&str> = functions.iter().map(String::as_str).collect();
            let mut pre = cpp::Preprocessor::new(include, &names);
            all = pre.run(all, 0);
            for (n, message) in pre.notes {
                self.note(n, message);
            }
            all = join_blocks(all, self.flavour);
            if is_lpfg(&all) {
                all = self.lpfg_lines(all);
            }
            all = join_axiom_lines(join_two_line_productions(all));
            if !self.lpfg {
                self.default_depth = sections_without_depth(&all);
            }
            self.globals = globals::Globals::scan(&all);
            self.words(&all);
        }
        // L-Py's `module` declarations change how strings split into modules: read them first.
        if self.flavour == Flavour::Lpy {
            self.write_only = write_only_globals(&all);
            self.flags = flags::candidates(&all);
            for line in &all {
                if let Some(rest) = line.code.strip_prefix("module ") {
                    for item in rest.split(',') {
                        let name = item.split('(').next().unwrap_or("").trim();
                        if is_identifier(name) && name.len() > 1 {
                            self.declared.push(name.to_string());
                        }
                    }
                }
            }
        }
        all
    }

    /// cpfg's predecessors made of several modules that are letters without parameters
    /// (`AXIOM : c --> …`, five modules A X I O M): Meristem's predecessor is one module, so the
    /// letters written together become one declared module, with a note at the first
    /// production.
    fn words(&mut self, all: &[Line]) {
        for line in all {
            let Some((arrow_at, _)) = arrow(&line.code) else {
                continue;
            };
            let left = &line.code[..arrow_at];
            let left = top_level(left, ":").map_or(left, |i| &left[..i]);
            let strict = top_level(left, "<").map_or(left, |i| &left[i + 1..]);
            let strict = top_level(strict, ">")
                .map_or(strict, |i| &strict[..i])
                .trim();
            if strict.len() < 2
                || strict.len() > 32
                || !strict.chars().all(|c| c.is_ascii_alphabetic())
                || self.words.iter().any(|(w, _)| w == strict)
            {
                continue;
            }
            // Meristem reads a line that starts with `axiom :` as its axiom.
            let name = if strict.eq_ignore_ascii_case("axiom") {
                format!("{strict}_")
            } else {
                strict.to_string()
            };
            let letters: Vec<String> = strict.chars().map(String::from).collect();
            self.note(
                line.n,
                format!(
                    "cpfg's predecessor {strict} is {} modules ({}); Meristem's predecessor is one module, so {strict} written together (here, in the axiom and in successors) becomes one module {name} (#module): where no production for it applies, cpfg would rewrite the letters one by one, Meristem keeps it whole",
                    letters.len(),
                    letters.join(" ")
                ),
            );
            self.declared.push(name.clone());
            self.words.push((strict.to_string(), name));
        }
        self.words.sort_by_key(|w| std::cmp::Reverse(w.0.len()));
    }

    fn run(&mut self, text: &str, include: &dyn Fn(&str) -> Option<String>) {
        let all = self.prepare(text, include);
        self.out.comment(
            &format!("Imported from {} by meristem import.", self.flavour.tool()),
            0,
        );
        let module_line = self.out.len();
        self.out.line("", 0);
        self.view_lines();
        let mut ended = false;
        let mut i = 0;
        while i < all.len() {
            let line = all[i].clone();
            i += 1;
            if line.code.is_empty() {
                if !line.comment.is_empty() {
                    self.out.comment(&line.comment, line.n);
                }
                continue;
            }
            // The lines of a block: those indented more than its header.
            let block_end = {
                let mut j = i;
                while j < all.len() && (all[j].code.is_empty() || all[j].indent > line.indent) {
                    j += 1;
                }
                j
            };
            let before = self.out.len();
            i = self.statement(&line, &all, i, block_end, &mut ended);
            // A comment after code stays after its translation.
            if !line.comment.is_empty() {
                if self.out.len() > before && !self.out.last().starts_with("//") {
                    let last = self.out.len() - 1;
                    let text = format!(
                        "{} // {}",
                        self.out.last(),
                        super::defuse_comment(&line.comment)
                    );
                    self.out.replace(last, text);
                } else {
                    self.out.comment(&line.comment, line.n);
                }
            }
        }
        if !self.declared.is_empty() {
            self.out.replace(
                module_line,
                format!(
                    "{} {}",
                    DirectiveKind::Module.written(),
                    self.declared.join(" ")
                ),
            );
        }
        if !self.axiom {
            self.note(0, "no Axiom: line");
        }
        self.unknown_view();
    }

    /// Translates one statement (a line, or a production with the lines it takes); returns the
    /// index of the next line to read.
    fn statement(
        &mut self,
        line: &Line,
        all: &[Line],
        i: usize,
        block_end: usize,
        ended: &mut bool,
    ) -> usize {
        let code = line.code.as_str();
        if *ended {
            if self.flavour == Flavour::Lpy {
                return self.python(line, &all[i..block_end], block_end, i);
            }
            self.note_once(
                "after",
                line.n,
                "text after endlsystem (another L-system of the file) is not translated",
            );
            return i;
        }
        if self.flavour == Flavour::Cpfg && code.starts_with('#') {
            self.preprocessor(line);
            return i;
        }
        if self.keyword_statement(line, ended) {
            return i;
        }
        if self.lpfg {
            if let Some((pattern, body)) = lpfg_production_parts(code) {
                self.lpfg_production(pattern, body, line.n);
                return i;
            }
        }
        if arrow(code).is_some() {
            return self.production_lines(line, all, i);
        }
        if self.flavour == Flavour::Lpy {
            return self.python_statement(line, all, i, block_end);
        }
        self.note(
            line.n,
            format!("'{code}' is not part of the notation Meristem imports; skipped"),
        );
        i
    }

    /// Translates a line that starts with a keyword of the notation (`Axiom:`, `derivation
    /// length:`, `ignore:`, a section's name, `endlsystem` …) or that means nothing to Meristem
    /// (`lsystem:`, production groups, L-Py's `module` declarations, read before). Returns
    /// whether the line was one; sets `ended` at `endlsystem`.
    fn keyword_statement(&mut self, line: &Line, ended: &mut bool) -> bool {
        let code = line.code.as_str();
        let lower = code.to_ascii_lowercase();
        if keyword(&lower, code, "lsystem:").is_some() {
            return true;
        }
        if self.flavour == Flavour::Cpfg && self.global_block(code, line.n) {
            return true;
        }
        // dialect: cpfg's keyword
        if let Some(rest) = keyword(&lower, code, "derivation length:") {
            match self.expression(rest, &Env::new()) {
                Ok(e) => self.out.line(
                    format!("{} {e}", KeywordKind::DerivationLength.written()),
                    line.n,
                ),
                Err(why) => self.note(line.n, format!("derivation length: {why}")),
            }
            return true;
        }
        // dialect: cpfg's keyword (the random generator's seed)
        if let Some(rest) = keyword(&lower, code, "seed:") {
            match self.expression(rest, &Env::new()) {
                Ok(e) => self
                    .out
                    .line(format!("{} {e}", DirectiveKind::Seed.written()), line.n),
                Err(why) => self.note(line.n, format!("seed: {why}")),
            }
            return true;
        }
        // dialect: cpfg's keyword
        // dialect: cpfg's keyword (`AXIOM : c --> …` is a production for a module AXIOM)
        if let Some(rest) = keyword(&lower, code, "axiom:").filter(|_| arrow(code).is_none()) {
            self.axiom(rest, line.n);
            return true;
        }
        let lists = [
            ("ignore:", DirectiveKind::Ignore.written()),
            ("consider:", DirectiveKind::Consider.written()),
        ];
        if let Some((kw, directive)) = lists.iter().find(|(k, _)| lower.starts_with(k)) {
            self.module_list(kw, directive, &code[kw.len()..], line.n);
            return true;
        }
        // dialect: cpfg's keyword
        if let Some(rest) = keyword(&lower, code, "maximum depth:") {
            self.out.line(
                format!("{} {}", KeywordKind::MaximumDepth.written(), rest.trim()),
                line.n,
            );
            return true;
        }
        if let Some(section) = section(&lower) {
            self.in_productions = section == KeywordKind::Productions.written();
            self.out.line(section.clone(), line.n);
            // cpfg rewrites its homomorphism and decomposition to depth 1 unless the section
            // says `maximum depth:` (its parser's default); Meristem's default is deeper.
            if self.default_depth.contains(&line.n) {
                self.out
                    .line(format!("{} 1", KeywordKind::MaximumDepth.written()), line.n);
            }
            return true;
        }
        let end = KeywordKind::EndLSystem.written();
        if lower == end {
            self.out.line(end, line.n);
            *ended = true;
            return true;
        }
        if lower.starts_with("group") || lower == "endgroup" {
            self.note_once(
                "group",
                line.n,
                "L-Py's production groups are not translated: every group's productions are imported as one set",
            );
            return true;
        }
        self.flavour == Flavour::Lpy && code.starts_with("module ")
    }

    /// `Axiom: modules` (the text after the colon is `rest`).
    fn axiom(&mut self, rest: &str, n: usize) {
        let lpfg;
        let rest = if self.lpfg {
            match self.lpfg_symbols(rest, n) {
                Ok(text) => {
                    lpfg = text;
                    lpfg.as_str()
                }
                Err(why) => {
                    self.note(n, format!("the axiom: {why}"));
                    return;
                }
            }
        } else {
            rest
        };
        match self.modules(rest, &Env::new(), n) {
            Ok(m) => {
                self.axiom = true;
                let m = format!("{}{m}", self.initial_colour());
                self.out.line(
                    format!("{} {}", KeywordKind::Axiom.written(), separate(&m)),
                    n,
                );
            }
            Err(why) => self.note(n, format!("the axiom: {why}")),
        }
    }

    /// `ignore: modules` or `consider: modules` (the keyword `kw`, then `rest`) as Meristem's
    /// `directive` with the modules' names.
    fn module_list(&mut self, kw: &str, directive: &str, rest: &str, n: usize) {
        // The names listed draw nothing: a `+` here is no turn by the view's angle.
        let (bare_turn, colour) = (self.bare_turn, self.colour);
        let modules = self.modules(rest, &Env::new(), n);
        (self.bare_turn, self.colour) = (bare_turn, colour);
        match modules {
            Ok(m) => {
                let names = module_names(&m);
                if !names.is_empty() {
                    self.out.line(format!("{directive} {}", names.join(" ")), n);
                }
            }
            Err(why) => self.note(n, format!("{kw} {why}")),
        }
    }

    /// A production starting at `line`, which may go on on the lines after it from `i` (cpfg
    /// writes long successors so: lines indented more that have no arrow). Returns the index of
    /// the next line to read.
    fn production_lines(&mut self, line: &Line, all: &[Line], mut i: usize) -> usize {
        let mut text = line.code.clone();
        while i < all.len()
            && !all[i].code.is_empty()
            && all[i].indent > line.indent
            && arrow(&all[i].code).is_none()
        {
            text.push(' ');
            text.push_str(&all[i].code);
            i += 1;
        }
        self.production(&text, line.n);
        i
    }

    /// An L-Py line that is no keyword and no production with an arrow: a production with a
    /// Python body (the lines from `i` to `block_end`), a one-line `pattern : produce …`, or other
    /// Python. Returns the index of the next line to read.
    fn python_statement(&mut self, line: &Line, all: &[Line], i: usize, block_end: usize) -> usize {
        let code = line.code.as_str();
        if code.ends_with(':') && i <= all.len() {
            if let Some(rest) = python_production_header(code) {
                self.python_production(rest, &all[i..block_end], line.n);
                return block_end;
            }
        }
        if let Some((pattern, succ)) = inline_produce(code) {
            self.production(&format!("{pattern} --> {succ}"), line.n);
            return i;
        }
        self.python(line, &all[i..block_end], block_end, i)
    }

    /// cpfg's preprocessor lines: `#define NAME value` becomes Meristem's `#define`.
    fn preprocessor(&mut self, line: &Line) {
        let code = line.code.trim_start_matches('#').trim_start();
        if let Some(rest) = code.strip_prefix("define") {
            let rest = rest.trim();
            let name_end = rest
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(rest.len());
            let (name, value) = (&rest[..name_end], rest[name_end..].trim());
            if value.starts_with('(') && rest[name_end..].starts_with('(') {
                self.note(
                    line.n,
                    format!("#define {name}(…): macros with arguments are not translated"),
                );
                return;
            }
            if !is_identifier(name) || value.is_empty() {
                self.note(line.n, format!("'#{code}' defines no value; skipped"));
                return;
            }
            match self.expression(value, &Env::new()) {
                Ok(e) => self.out.line(
                    format!("{} {name} {e}", DirectiveKind::Define.written()),
                    line.n,
                ),
                Err(why) => self.note(line.n, format!("#define {name}: {why}")),
            }
            return;
        }
        let word = code.split_whitespace().next().unwrap_or("");
        self.note(
            line.n,
            format!("the C preprocessor's #{word} is not translated; the line is skipped"),
        );
    }

    /// L-Py's Python outside productions: `NAME = number expression` becomes a `#define`; other
    /// statements are reported (a block with its indented lines). Returns where to go on.
    fn python(&mut self, line: &Line, block: &[Line], block_end: usize, next: usize) -> usize {
        let code = line.code.as_str();
        if self.tuple_assignment(code, line.n) || self.helper(code, block, line.n) {
            return if block.is_empty() { next } else { block_end };
        }
        if let Some((name, value)) = code.split_once('=') {
            let name = name.trim();
            let value = value.trim();
            let assignment = is_identifier(name) && !value.starts_with('=');
            if assignment && name.starts_with("__") && name.ends_with("__") {
                let text = value.trim_matches(|c| c == '\'' || c == '"');
                self.out
                    .comment(&format!("{}: {text}", name.trim_matches('_')), line.n);
                return next;
            }
            let flag = self.flag_steps.iter().find(|(f, _)| f == name).cloned();
            if let (true, Some((_, step))) = (assignment, flag) {
                let set = self
                    .flags
                    .iter()
                    .find(|f| f.name == name)
                    .map(|f| f.set.clone());
                let text = match (step, set) {
                    (Some(s), Some(set)) => format!("(NumIt > {s} ? {set} : {value})"),
                    _ => value.to_string(),
                };
                self.out.line(
                    format!("{} {name} {text}", DirectiveKind::Define.written()),
                    line.n,
                );
                return next;
            }
            if assignment {
                match self.expression(value, &Env::new()) {
                    Ok(e) => self.out.line(
                        format!("{} {name} {e}", DirectiveKind::Define.written()),
                        line.n,
                    ),
                    Err(why) => {
                        self.note(line.n, format!("{name} = {value}: {why}; not translated"))
                    }
                }
                return next;
            }
        }
        let first = code
            .split(|c: char| !c.is_ascii_alphanumeric() && c != '_')
            .next();
        let message = match first.unwrap_or("") {
            "def" => format!(
                "the Python function '{}' is not translated",
                code[3..].split('(').next().unwrap_or("").trim()
            ),
            "import" | "from" => "Python imports are not translated".to_string(),
            _ => format!("the Python statement '{code}' is not translated"),
        };
        self.note(line.n, message);
        if block.is_empty() {
            next
        } else {
            block_end
        }
    }

    /// A Python function that returns one expression (`def long(x): return 1`, the `return` on
    /// its line or alone in its body): kept to be inlined where it is called. False for any
    /// other line.
    fn helper(&mut self, code: &str, block: &[Line], n: usize) -> bool {
        let Some(rest) = code.strip_prefix("def ") else {
            return false;
        };
        let Some((head, inline)) = rest.split_once(':') else {
            return false;
        };
        let Some((name, params)) = head
            .trim()
            .strip_suffix(')')
            .and_then(|h| h.split_once('('))
        else {
            return false;
        };
        let body: Vec<&str> = std::iter::once(inline.trim())
            .chain(block.iter().map(|l| l.code.as_str()))
            .filter(|c| !c.is_empty())
            .collect();
        let Some(value) = (match body.as_slice() {
            [only] => only.strip_prefix("return "),
            _ => None,
        }) else {
            return false;
        };
        let params: Vec<String> = params
            .split(',')
            .map(|p| p.trim().to_string())
            .filter(|p| !p.is_empty())
            .collect();
        if !is_identifier(name.trim()) || !params.iter().all(|p| is_identifier(p)) {
            return false;
        }
        let name = name.trim().to_string();
        match self.expression(value.trim(), &Env::new()) {
            Ok(e) => {
                let comment = format!(
                    "L-Py's function {name}({}) = {e}, inlined where it is called",
                    params.join(", ")
                );
                self.out.comment(&comment, n);
                self.helpers.push((name.clone(), params, e));
            }
            Err(why) => self.note(
                n,
                format!(
                    "the Python function '{}' returns {}: {why}; not translated",
                    name.trim(),
                    value.trim()
                ),
            ),
        }
        true
    }

    /// Python's `a, b = 1, 2`: one `#define` each. False for any other line.
    fn tuple_assignment(&mut self, code: &str, n: usize) -> bool {
        let Some((names, values)) = code.split_once('=') else {
            return false;
        };
        let names: Vec<&str> = names.split(',').map(str::trim).collect();
        let values = split_top(values.trim(), ',');
        let assigns = names.len() > 1
            && names.len() == values.len()
            && names.iter().all(|name| is_identifier(name))
            && !values[0].trim_start().starts_with('=');
        if !assigns {
            return false;
        }
        for (name, value) in names.iter().zip(values) {
            match self.expression(value.trim(), &Env::new()) {
                Ok(e) => self
                    .out
                    .line(format!("{} {name} {e}", DirectiveKind::Define.written()), n),
                Err(why) => self.note(
                    n,
                    format!("{name} = {}: {why}; not translated", value.trim()),
                ),
            }
        }
        true
    }

    /// `pred : {pre} cond {post} --> succ : probability` in Meristem's notation.
    fn production(&mut self, code: &str, n: usize) {
        let Some((start, end)) = arrow(code) else {
            return;
        };
        let (left, right) = (code[..start].trim(), code[end..].trim());
        if let Some(parts) = self.several_modules(left, right, n) {
            let mut texts = Vec::new();
            for (left, right) in parts {
                match self.production_text(&left, &right, n) {
                    Ok(text) => texts.push(text),
                    Err(why) => {
                        self.note(n, format!("{why}; the production is skipped"));
                        return;
                    }
                }
            }
            for text in texts {
                self.out.line(text, n);
            }
            return;
        }
        match self.production_text(left, right, n) {
            Ok(text) => self.out.line(text, n),
            Err(why) => self.note(n, format!("{why}; the production is skipped")),
        }
    }

    /// cpfg's predecessor of several modules (`F(v,n)#(w) --> F(v)#(w)@O`): Meristem's
    /// predecessor is one module, so it becomes one production per module, each with the others
    /// as context: the first gives the successor, the others erase their module (`F(v,n) >
    /// #(w) -> F(v)#(w)@O` and `F(v,n) < #(w) -> ε`), with a note. `None` when the predecessor
    /// is one module, or when the production draws a random number (its probability or a random
    /// condition would be drawn apart for each module).
    fn several_modules(
        &mut self,
        left: &str,
        right: &str,
        n: usize,
    ) -> Option<Vec<(String, String)>> {
        if self.flavour != Flavour::Cpfg {
            return None;
        }
        let (pattern, guard) = match top_level(left, ":") {
            Some(i) => (left[..i].trim(), Some(left[i + 1..].trim())),
            None => (left, None),
        };
        // The new contexts `<<`, `>>` are read with the pattern (see `new_contexts`).
        if pattern.contains("<<") || pattern.contains(">>") {
            return None;
        }
        let (before, rest) = match top_level(pattern, "<") {
            Some(i) => (pattern[..i].trim(), &pattern[i + 1..]),
            None => ("", pattern),
        };
        let (strict, after) = match top_level(rest, ">") {
            Some(i) => (rest[..i].trim(), rest[i + 1..].trim()),
            None => (rest.trim(), ""),
        };
        let modules = self.source_modules(strict)?;
        if modules.len() < 2
            || top_level(right, ":").is_some()
            || ["ran(", "nran("].iter().any(|r| left.contains(r))
        {
            return None;
        }
        let before = if before == "*" { "" } else { before };
        let after = if after == "*" { "" } else { after };
        self.note(
            n,
            format!(
                "cpfg's predecessor {strict} is {} modules; Meristem's predecessor is one module, so it becomes a production for {} with the others as its context and one for each other module that erases it there: the same unless two matches overlap or modules cpfg ignores stand between them",
                modules.len(),
                modules[0]
            ),
        );
        let parts = (0..modules.len())
            .map(|i| {
                let lc = format!("{before}{}", modules[..i].concat());
                let rc = format!("{}{after}", modules[i + 1..].concat());
                let mut head = String::new();
                if !lc.trim().is_empty() {
                    head.push_str(&format!("{lc} < "));
                }
                head.push_str(&modules[i]);
                if !rc.trim().is_empty() {
                    head.push_str(&format!(" > {rc}"));
                }
                if let Some(g) = guard {
                    head.push_str(&format!(" : {g}"));
                }
                let successor = if i == 0 {
                    right.to_string()
                } else {
                    "*".to_string()
                };
                (head, successor)
            })
            .collect();
        Some(parts)
    }

    /// The modules of a cpfg module string as written (`F(v,n)#(w)` → `F(v,n)`, `#(w)`); `None`
    /// when it holds a bracket or a parenthesis that is never closed.
    fn source_modules(&self, text: &str) -> Option<Vec<String>> {
        let chars: Vec<char> = text.chars().collect();
        let mut out = Vec::new();
        let mut i = 0;
        while i < chars.len() {
            let c = chars[i];
            if c.is_whitespace() {
                i += 1;
                continue;
            }
            if "[]{}<>".contains(c) {
                return None;
            }
            let start = i;
            i = if c == '@' || c == '~' || c == '?' {
                cpfg_symbol(&chars, i).1
            } else if let Some((word, _)) = self
                .words
                .iter()
                .find(|(w, _)| chars[i..].iter().take(w.len()).copied().eq(w.chars()))
            {
                i + word.chars().count()
            } else {
                i + 1
            };
            let mut j = i;
            while chars.get(j) == Some(&' ') {
                j += 1;
            }
            if chars.get(j) == Some(&'(') {
                i = matching(&chars, j)? + 1;
            }
            out.push(
                chars[start..i]
                    .iter()
                    .collect::<String>()
                    .trim()
                    .to_string(),
            );
        }
        Some(out)
    }

    /// The Meristem production of `left --> right`, or why it has none.
    fn production_text(&mut self, left: &str, right: &str, n: usize) -> Result<String, String> {
        let (pattern, guard) = match top_level(left, ":") {
            Some(i) => (left[..i].trim(), left[i + 1..].trim()),
            None => (left, ""),
        };
        let (pattern, literals) = match self.flavour {
            Flavour::Lpy => literal_parameters(pattern),
            Flavour::Cpfg => (pattern.to_string(), Vec::new()),
        };
        let pattern = pattern.as_str();
        let (env, condition) = self.guard(guard, n)?;
        // L-Py's `D(20, k)` matches a D whose first parameter is 20: a condition.
        let condition = if literals.is_empty() {
            condition
        } else {
            literals
                .into_iter()
                .chain(condition.map(|c| format!("({c})")))
                .reduce(|a, b| format!("{a} && {b}"))
        };
        // cpfg's probability after the successor: `--> succ : 0.3`.
        let (right, weight) = match top_level(right, ":") {
            Some(i) => {
                let weight = self
                    .expression(right[i + 1..].trim(), &env)
                    .map_err(|why| format!("the probability: {why}"))?;
                (right[..i].trim(), Some(weight))
            }
            None => (right, None),
        };
        let mut text = self.pattern(pattern, n)?;
        let successor = if right.is_empty() || right == "*" {
            String::new()
        } else {
            self.modules(right, &env, n)?
        };
        if let Some(c) = condition {
            text.push_str(&format!(" : {c}"));
        }
        text.push_str(" ->");
        if let Some(w) = weight {
            text.push_str(&format!(" ({w})"));
        }
        if successor.is_empty() {
            text.push_str(" ε");
        } else {
            text.push(' ');
            text.push_str(&separate(&successor));
        }
        Ok(text)
    }

    /// A production's guard (what stands between `:` and the arrow): statement blocks `{…}`
    /// before and after a condition. Returns the names the blocks bind and the condition in
    /// Meristem's terms (`None` when there is none or it is `*`).
    fn guard(&mut self, guard: &str, n: usize) -> Result<(Env, Option<String>), String> {
        let mut env = Env::new();
        let mut condition = String::new();
        let mut rest = guard;
        let mut post = None;
        while !rest.is_empty() {
            if let Some(inner) = rest.strip_prefix('{') {
                let close = closing(rest, 0).ok_or("a '{' block is never closed")? - 1;
                let block = &inner[..close];
                if condition.trim().is_empty() {
                    self.block(block, &mut env, n)?;
                } else {
                    post = Some(block.to_string());
                }
                rest = inner[close + 1..].trim_start();
            } else {
                let stop = rest.find('{').unwrap_or(rest.len());
                condition.push_str(&rest[..stop]);
                rest = &rest[stop..];
            }
        }
        let condition = condition.trim();
        let condition = if condition.is_empty() || condition == "*" {
            None
        } else {
            let translated = self
                .expression(condition, &env)
                .map_err(|why| format!("the condition {condition}: {why}"))?;
            Some(translated)
        };
        if let Some(block) = post {
            self.block(&block, &mut env, n)?;
        }
        Ok((env, condition))
    }

    /// A production's left side: contexts and predecessor (formal parameters are names).
    fn pattern(&mut self, pattern: &str, n: usize) -> Result<String, String> {
        let new_contexts = self.new_contexts(pattern, n);
        let pattern = new_contexts.as_str();
        let strict = {
            let after = top_level(pattern, "<").map_or(pattern, |i| &pattern[i + 1..]);
            top_level(after, ">").map_or(after, |i| &after[..i]).trim()
        };
        let (width, target) = match self.flavour {
            Flavour::Cpfg => ('#', "!"),
            Flavour::Lpy => ('_', "!"),
        };
        for (symbol, meristem) in [(width, target), (',', ";")] {
            if strict.starts_with(symbol) {
                self.note(
                    n,
                    format!(
                        "a production for {}'s '{symbol}' becomes one for Meristem's '{meristem}', which also stands for the dialect's own '{meristem}': it rewrites those modules too",
                        self.flavour.tool()
                    ),
                );
            }
        }
        let mut parts = Vec::new();
        let mut rest = pattern;
        if let Some(i) = top_level(rest, "<") {
            parts.push(self.modules(&rest[..i], &Env::new(), n)?);
            parts.push("<".into());
            rest = &rest[i + 1..];
        }
        if let Some(i) = top_level(rest, ">") {
            parts.push(self.modules(&rest[..i], &Env::new(), n)?);
            parts.push(">".into());
            parts.push(self.modules(&rest[i + 1..], &Env::new(), n)?);
        } else {
            parts.push(self.modules(rest, &Env::new(), n)?);
        }
        Ok(parts
            .into_iter()
            .map(|p| if p.is_empty() { "*".to_string() } else { p })
            .collect::<Vec<_>>()
            .join(" "))
    }

    /// The pattern with the new contexts `<<` and `>>` read as the ordinary `<` and `>`, with a
    /// note on what changes: the tool matches a new context on the string being produced (the
    /// neighbour already rewritten in this step, so a signal can cross the whole plant in one
    /// step); Meristem matches on the string of the step before, so a signal moves one module a
    /// step.
    fn new_contexts(&mut self, pattern: &str, n: usize) -> String {
        let mut out = pattern.to_string();
        for (new, old, side) in [("<<", "<", "left"), (">>", ">", "right")] {
            if top_level(&out, new).is_some() {
                self.note(
                    n,
                    format!(
                        "{}'s new {side} context '{new}' (matched on the string being produced in this step) becomes an ordinary {side} context '{old}' (matched on the string of the step before): a signal it carries moves one module a step instead of along the whole axis in one step, so the plant may differ",
                        self.flavour.tool()
                    ),
                );
                while let Some(i) = top_level(&out, new) {
                    out.replace_range(i..i + 2, old);
                }
            }
        }
        out
    }

    /// The condition of an `if c`/`elif c` header with the body's locals put in (`None` for
    /// `else`); a condition that cannot be translated is noted (the production is skipped).
    fn python_condition(
        &mut self,
        head: &str,
        names: &[String],
        values: &[String],
        n: usize,
    ) -> Result<Option<String>, ()> {
        if head.trim() == "else" {
            return Ok(None);
        }
        // `if(z == 1)` as well as `if z == 1`.
        let c = head
            .trim_start_matches("elif")
            .trim_start_matches("if")
            .trim();
        let c = cpp::substitute(c, names, values);
        // Checked here, translated with the production (translating it twice would read the
        // `^` that Python's `**` becomes as Python's bitwise or).
        match self.expression(&c, &Env::new()) {
            Ok(_) => Ok(Some(c)),
            Err(why) => {
                self.note(
                    n,
                    format!("the condition {c}: {why}; the production is skipped"),
                );
                Err(())
            }
        }
    }

    /// L-Py: a production with a Python body of `if`/`elif`/`else` and `produce`.
    fn python_production(&mut self, pattern: &str, body: &[Line], n: usize) {
        let mut branches: Vec<(Option<String>, String, usize)> = Vec::new();
        // The `if`/`elif`/`else:` headers the current line is nested in: their indentation and
        // condition (`None` for `else`, which the order of the productions already says).
        let mut open: Vec<(usize, Option<String>)> = Vec::new();
        let marked = self.flags_written.len();
        let owned = self.body_lines(body);
        let mut lines: Vec<&Line> = owned.iter().collect();
        let (names, values) = python_locals(&mut lines);
        let local = |text: &str| in_parentheses(text, &names, &values);
        for line in lines {
            while open
                .last()
                .is_some_and(|(indent, _)| *indent >= line.indent)
            {
                open.pop();
            }
            let code = &local(&line.code);
            let code = code.as_str();
            let (head, tail) = match code.find(':') {
                Some(i)
                    if ["if ", "if(", "elif ", "elif("]
                        .iter()
                        .any(|k| code.starts_with(k))
                        || code.starts_with("else") =>
                {
                    (&code[..i], code[i + 1..].trim())
                }
                _ => ("", code),
            };
            if !head.is_empty() {
                let Ok(condition) = self.python_condition(head, &names, &values, line.n) else {
                    return;
                };
                if tail.is_empty() {
                    open.push((line.indent, condition));
                    continue;
                }
                match produce(tail) {
                    Some(s) => branches.push((nested(&open, condition), s.to_string(), line.n)),
                    None => {
                        self.note(line.n, format!("the Python code '{tail}' is not translated; the production is skipped"));
                        return;
                    }
                }
                continue;
            }
            match produce(code) {
                Some(s) => branches.push((nested(&open, None), s.to_string(), line.n)),
                None => {
                    self.note(line.n, format!("the Python code '{code}' is not translated (Meristem imports bodies made of if, elif, else and produce); the production is skipped"));
                    return;
                }
            }
        }
        if branches.is_empty() {
            self.note(n, "a Python production that produces nothing; skipped");
            return;
        }
        for (condition, successor, line) in branches {
            let successor = if successor.trim().is_empty() {
                "*".to_string()
            } else {
                successor
            };
            let text = match condition {
                Some(c) => format!("{pattern} : {c} --> {successor}"),
                None => format!("{pattern} --> {successor}"),
            };
            self.production(&text, line);
        }
        // The probe's markers count the steps since they were written.
        for &k in &self.flags_written[marked..] {
            let m = flags::marker(k);
            self.out.line(format!("{m}(c) -> {m}(c+1)"), n);
        }
    }

    /// The lines of an L-Py body without its blank lines, without `global g` and assignments
    /// to g when nothing but a dropped label reads g (noted), and with a flag's setting taken out
    /// (see [`Importer::flag_lines`]).
    fn body_lines(&mut self, body: &[Line]) -> Vec<Line> {
        let mut lines: Vec<&Line> = body.iter().filter(|l| !l.code.is_empty()).collect();
        lines.retain(|line| {
            let dropped = global_write(&line.code, &self.write_only);
            if let Some(g) = &dropped {
                let code = line.code.clone();
                self.note(line.n, format!("the Python code '{code}' changes the global {g}, which nothing but text labels (@L, dropped) reads; dropped"));
            }
            dropped.is_none()
        });
        match self.flag_lines(&lines) {
            Some(owned) => owned,
            None => lines.into_iter().cloned().collect(),
        }
    }

    /// The lines of an L-Py body with the setting of a flag (`global m`, `m = 1`) taken out, and
    /// in the probe a marker put in the `produce` that follows it; `None` when the body sets no
    /// flag, or sets one this run cannot translate (the body is then read as it is).
    fn flag_lines(&mut self, lines: &[&Line]) -> Option<Vec<Line>> {
        let flags = self.flags.clone();
        let flag_of = |name: &str| flags.iter().position(|f| f.name == name);
        let mut out: Vec<Line> = Vec::new();
        let mut pending: Option<(usize, usize)> = None;
        let mut any = false;
        for line in lines {
            let code = line.code.as_str();
            if let Some(rest) = code.strip_prefix("global ") {
                if rest.split(',').all(|g| flag_of(g.trim()).is_some()) {
                    continue;
                }
            }
            if let Some((k, set)) = code.split_once('=').and_then(|(name, value)| {
                let k = flag_of(name.trim())?;
                (value.trim() == flags[k].set && !value.starts_with('=')).then_some((k, line))
            }) {
                if !self.probe && !self.flag_steps.iter().any(|(f, _)| *f == flags[k].name) {
                    return None;
                }
                pending = Some((k, set.indent));
                any = true;
                self.flag_note(k, set);
                continue;
            }
            let mut line = (*line).clone();
            if let Some((k, indent)) = pending.take() {
                let successor = line
                    .code
                    .strip_prefix("produce")
                    .filter(|_| line.indent == indent)?;
                if !self.in_productions {
                    return None;
                }
                if self.probe {
                    let m = flags::marker(k);
                    if !self.declared.contains(&m) {
                        self.declared.push(m.clone());
                    }
                    let successor = successor.trim();
                    let successor = if successor == "*" { "" } else { successor };
                    line.code = format!("produce {m}(0) {successor}");
                    self.flags_written.push(k);
                }
            }
            out.push(line);
        }
        (any && pending.is_none()).then_some(out)
    }

    /// The note for the setting of flag `k` at `line` (after the probe).
    fn flag_note(&mut self, k: usize, line: &Line) {
        let Flag { name, initial, set } = self.flags[k].clone();
        let Some((_, step)) = self.flag_steps.iter().find(|(f, _)| *f == name).cloned() else {
            return;
        };
        let code = &line.code;
        let when = match step {
            Some(s) => format!("deriving the model at import time (seeds 1 and 2 agree) shows that this branch first applies in step {s}, so {name} is {initial} up to that step and {set} after it; in that step itself, modules to the right of this one see {initial} here where L-Py gives them {set}"),
            None => format!("deriving the model at import time (seeds 1 and 2 agree) shows that this branch never applies within the derivation length, so {name} stays {initial}"),
        };
        self.note(
            line.n,
            format!("the Python code '{code}' sets the global {name}, which productions read; Meristem has no variables: {when}"),
        );
    }

    /// Translates an expression (cpfg's C, L-Py's Python) with `env`'s names substituted.
    fn expression(&mut self, text: &str, env: &Env) -> Result<String, String> {
        let text = text.trim();
        if self.flavour == Flavour::Lpy {
            // Python's conditional expression `a if c else b`.
            if let (Some(i), Some(e)) = (find_word(text, "if"), find_word(text, "else")) {
                if i < e {
                    let a = self.expression(&text[..i], env)?;
                    let c = self.expression(&text[i + 2..e], env)?;
                    let b = self.expression(&text[e + 4..], env)?;
                    return Ok(format!("({c}?{a}:{b})"));
                }
            }
        }
        let chars: Vec<char> = text.chars().collect();
        let mut out = String::new();
        let mut i = 0;
        while i < chars.len() {
            let c = chars[i];
            if c == '\'' || c == '"' {
                return Err("a string is not a number".into());
            }
            i = if c.is_ascii_digit()
                || (c == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit))
            {
                let end = number_end(&chars, i);
                out.extend(&chars[i..end]);
                end
            } else if c.is_ascii_alphabetic() || c == '_' {
                self.word(&chars, i, env, &mut out)?
            } else {
                self.operator(&chars, i, &mut out)?
            };
        }
        Ok(out)
    }

    /// Translates the name at `chars[start]` into `out`: a call with its arguments, a name bound
    /// in `env`, one of Python's words, or the name itself. Returns the index after it.
    fn word(
        &mut self,
        chars: &[char],
        start: usize,
        env: &Env,
        out: &mut String,
    ) -> Result<usize, String> {
        let mut i = start;
        while i < chars.len()
            && (chars[i].is_ascii_alphanumeric() || chars[i] == '_' || chars[i] == '.')
        {
            i += 1;
        }
        let mut word: String = chars[start..i].iter().collect();
        if self.flavour == Flavour::Lpy {
            for prefix in ["math.", "random.", "np.", "numpy."] {
                if let Some(w) = word.strip_prefix(prefix) {
                    word = w.to_string();
                }
            }
        }
        if word.contains('.') {
            return Err(format!("'{word}' is Python, not a number expression"));
        }
        let mut j = i;
        while j < chars.len() && chars[j] == ' ' {
            j += 1;
        }
        if chars.get(j) == Some(&'[') && self.flavour == Flavour::Cpfg {
            return self.array_read(chars, j, &word, env, out);
        }
        if chars.get(j) == Some(&'(') {
            let close = matching(chars, j).ok_or("a '(' is never closed")?;
            let inner: String = chars[j + 1..close].iter().collect();
            let mut args = Vec::new();
            for arg in split_top(&inner, ',') {
                if !arg.trim().is_empty() {
                    args.push(self.expression(arg, env)?);
                }
            }
            out.push_str(&self.call(&word, &args)?);
            return Ok(close + 1);
        }
        if let Some(value) = env.get(&word) {
            out.push_str(value);
            return Ok(i);
        }
        let replacement = match (self.flavour, word.as_str()) {
            (Flavour::Lpy, "and") => "&&".to_string(),
            (Flavour::Lpy, "or") => "||".to_string(),
            (Flavour::Lpy, "not") => "!".to_string(),
            (Flavour::Lpy, "True") => "1".to_string(),
            (Flavour::Lpy, "False") => "0".to_string(),
            (Flavour::Lpy, "pi") => "3.14159265359".to_string(),
            (Flavour::Lpy, "None") => return Err("None is not a number".into()),
            _ => word,
        };
        if replacement.chars().all(|c| c.is_ascii_alphabetic())
            && !out.is_empty()
            && out.ends_with(|c: char| c.is_ascii_alphanumeric())
        {
            out.push(' ');
        }
        out.push_str(&replacement);
        Ok(i)
    }

    /// cpfg's `name[i]`, `name[i][j]`… at `chars[j]` (the first `[`), with as many indices as
    /// the array has dimensions, into `out`. Returns the index after it.
    fn array_read(
        &mut self,
        chars: &[char],
        j: usize,
        word: &str,
        env: &Env,
        out: &mut String,
    ) -> Result<usize, String> {
        let wanted = self.array_dimensions(word).unwrap_or(1);
        let mut indices = Vec::new();
        let mut at = j;
        while indices.len() < wanted && chars.get(at) == Some(&'[') {
            let close = chars[at..]
                .iter()
                .position(|&c| c == ']')
                .map(|k| at + k)
                .ok_or("a '[' is never closed")?;
            let inner: String = chars[at + 1..close].iter().collect();
            indices.push(self.expression(&inner, env)?);
            at = close + 1;
            while chars.get(at) == Some(&' ') && indices.len() < wanted {
                at += 1;
            }
        }
        let value = self.array_value(word, &indices).ok_or_else(|| {
            format!("'{word}[…]' reads an array that cpfg's Start: or Define: block does not give as one list of values")
        })?;
        out.push_str(&value);
        Ok(at)
    }

    /// Translates the operator or punctuation at `chars[i]` into `out` (Python's `**` is `^`;
    /// what has no meaning in an expression is an error). Returns the index after it.
    fn operator(&self, chars: &[char], i: usize, out: &mut String) -> Result<usize, String> {
        let c = chars[i];
        let two: String = chars[i..(i + 2).min(chars.len())].iter().collect();
        match (self.flavour, two.as_str(), c) {
            (Flavour::Lpy, "**", _) => {
                out.push('^');
                Ok(i + 2)
            }
            (Flavour::Lpy, "//", _) => Err("Python's floor division // is not translated".into()),
            (Flavour::Lpy, _, '^') => Err("Python's ^ is a bitwise or, not a power".into()),
            (_, _, '[' | ']' | '{' | '}' | ';' | '`' | '$' | '@' | '#') => {
                Err(format!("'{c}' in an expression"))
            }
            _ => {
                out.push(c);
                Ok(i + 1)
            }
        }
    }

    /// A function call in Meristem's terms.
    fn call(&mut self, name: &str, args: &[String]) -> Result<String, String> {
        if let Some((_, params, body)) = self.helpers.iter().find(|(h, _, _)| h == name) {
            if params.len() != args.len() {
                return Err(format!(
                    "{name}(…) takes {} arguments, not {}",
                    params.len(),
                    args.len()
                ));
            }
            let args: Vec<String> = args.iter().map(|a| format!("({a})")).collect();
            return Ok(format!("({})", cpp::substitute(body, params, &args)));
        }
        let a = |k: usize| args.get(k).cloned().unwrap_or_default();
        let all = args.join(",");
        Ok(match (self.flavour, name) {
            (Flavour::Lpy, "sin" | "cos" | "tan") => format!("{name}(({})*{DEGREES})", a(0)),
            (Flavour::Lpy, "asin" | "acos" | "atan" | "atan2") => {
                format!("({name}({all})/{DEGREES})")
            }
            (Flavour::Lpy, "radians") => format!("(({})/{DEGREES})", a(0)),
            (Flavour::Lpy, "degrees") => format!("(({})*{DEGREES})", a(0)),
            (Flavour::Lpy, "random") if args.is_empty() => "uniform(0,1)".into(),
            // L-Py counts the steps from 0; Meristem's NumIt from 1.
            (Flavour::Lpy, "getIterationNb") if args.is_empty() => "(NumIt-1)".into(),
            (Flavour::Lpy, "randint") => format!("uniform_int({all})"),
            (Flavour::Lpy, "gauss" | "normalvariate") => format!("normal({all})"),
            (Flavour::Lpy, "expovariate") => format!("exponential({all})"),
            (Flavour::Lpy, "float") => format!("({})", a(0)),
            (Flavour::Lpy, "int") | (Flavour::Cpfg, "trunc") => {
                format!("(({0})<0?ceil({0}):floor({0}))", a(0))
            }
            (Flavour::Lpy, "pow") => format!("(({})^({}))", a(0), a(1)),
            (Flavour::Cpfg, "func") => return self.func(args),
            (Flavour::Cpfg, "tfunc") => {
                return Err(
                    "cpfg's tfunc(…) (a function of time from the animation's function file) is not translated".into(),
                )
            }
            (Flavour::Cpfg, "ran") => format!("uniform(0,{})", a(0)),
            (Flavour::Cpfg, "nran") => format!("normal({all})"),
            (_, "fabs") => format!("abs({all})"),
            _ => format!("{name}({all})"),
        })
    }

    /// Translates a module string; modules are written without spaces. Long because it is one
    /// scanner over the successor's characters, each kind of character an arm of it.
    fn modules(&mut self, text: &str, env: &Env, n: usize) -> Result<String, String> {
        let chars: Vec<char> = text.chars().collect();
        let mut out = String::new();
        let mut i = 0;
        // cpfg draws a generalized cylinder through the points where the turtle puts its
        // control points (@Gc, @Ge), moved there by f as well as F: an f before them in the
        // same successor moves along the cylinder, which Meristem's smooth axis draws only
        // along segments.
        let cylinder_end = (self.flavour == Flavour::Cpfg)
            .then(|| {
                // dialect: cpfg's control point and end of a generalized cylinder.
                ["@Gc", "@Ge"]
                    .iter()
                    .filter_map(|g| text.rfind(g))
                    .max()
                    .map(|b| text[..b].chars().count())
            })
            .flatten();
        while i < chars.len() {
            let c = chars[i];
            if c.is_whitespace() {
                i += 1;
                continue;
            }
            // cpfg's `=` in a right context skips the rest of the branch up to its `]`
            // (`[I(b)=]`): what Meristem's `]` in a pattern does.
            if c == '='
                && self.flavour == Flavour::Cpfg
                && chars[i + 1..].iter().find(|c| !c.is_whitespace()) == Some(&']')
            {
                i += 1;
                continue;
            }
            let (name, after) =
                if (c == '@' || c == '~' || c == '?') && self.flavour == Flavour::Cpfg {
                    cpfg_symbol(&chars, i)
                } else if c == '@' || c == '~' || c == '?' {
                    symbol_name(&chars, i)
                } else if c.is_ascii_alphabetic() && self.flavour == Flavour::Lpy {
                    self.lpy_name(&chars, i, n)
                } else if let Some((word, name)) = self
                    .words
                    .iter()
                    .find(|(w, _)| chars[i..].iter().take(w.len()).copied().eq(w.chars()))
                {
                    (name.clone(), i + word.len())
                } else {
                    (c.to_string(), i + 1)
                };
            let name = if name == "f" && cylinder_end.is_some_and(|end| i < end) {
                self.note_once(
                    "f@G",
                    n,
                    "cpfg's f before a control point of a generalized cylinder moves along the cylinder cpfg draws; Meristem's smooth axis follows segments only, so it becomes F",
                );
                "F".to_string()
            } else {
                name
            };
            i = after;
            // Parameters.
            let mut j = i;
            while j < chars.len() && chars[j] == ' ' {
                j += 1;
            }
            let mut params = Vec::new();
            let mut has_params = false;
            if chars.get(j) == Some(&'(') {
                let close = matching(&chars, j).ok_or("a '(' is never closed")?;
                let inner: String = chars[j + 1..close].iter().collect();
                if name == "@L" {
                    // A text label (`@L("%.f", c)`): Meristem draws no text.
                    let tool = self.flavour.tool();
                    self.note_once(
                        "@L",
                        n,
                        format!("{tool}'s @L draws a text label; Meristem draws no text, so the label is dropped"),
                    );
                    i = close + 1;
                    continue;
                }
                has_params = true;
                for arg in split_top(&inner, ',') {
                    params.push(self.expression(arg, env)?);
                }
                i = close + 1;
            }
            self.cpfg_module_notes(&name, n);
            out.push_str(&self.module(&name, params, has_params, n));
        }
        Ok(out)
    }

    /// The notes for cpfg's `?E` and `_`, which are kept as modules the turtle ignores.
    fn cpfg_module_notes(&mut self, name: &str, n: usize) {
        if name == "?E" && self.flavour == Flavour::Cpfg {
            self.note_once(
                name,
                n,
                "cpfg's ?E(…) asks the environment program (a light or space model run beside cpfg) for values; Meristem runs no environment program, so ?E is kept as a module whose parameters stay as the L-system writes them, and productions that read it see those values",
            );
        }
        if name == "_" && self.flavour == Flavour::Cpfg {
            self.note_once(
                name,
                n,
                "cpfg's _ is not a Meristem command; kept as a module the turtle ignores",
            );
        }
    }

    /// The L-Py module name at `chars[start]`: the longest declared or predefined long name
    /// there, another predefined L-Py word before `(` (declared now, and reported once), or one
    /// letter. Returns it and the index after it.
    fn lpy_name(&mut self, chars: &[char], start: usize, n: usize) -> (String, usize) {
        let rest: String = chars[start..].iter().collect();
        let candidates: Vec<String> = self
            .declared
            .iter()
            .cloned()
            .chain(LPY_NAMES.iter().map(|(long, _)| long.to_string()))
            .collect();
        let long = candidates
            .iter()
            .filter(|d| {
                rest.starts_with(d.as_str())
                    && !rest[d.len()..].starts_with(|c: char| c.is_ascii_alphanumeric())
            })
            .max_by_key(|d| d.len())
            .cloned();
        let word_len = rest
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(rest.len());
        match long {
            Some(name) => {
                let end = start + name.chars().count();
                (name, end)
            }
            // One of L-Py's other predefined modules followed by '(' (Meristem lacks it).
            None if word_len > 1
                && rest[word_len..].trim_start().starts_with('(')
                && LPY_PREDEFINED.contains(&&rest[..word_len]) =>
            {
                let word = rest[..word_len].to_string();
                if !self.unknown_names.contains(&word) {
                    self.unknown_names.push(word.clone());
                    self.declared.push(word.clone());
                    self.note(
                        n,
                        format!("'{word}' is not a module Meristem knows; kept as a module its turtle ignores (#module {word})"),
                    );
                }
                (word, start + word_len)
            }
            None => (chars[start].to_string(), start + 1),
        }
    }

    /// One module with its parameters, renamed where the dialect's meaning is Meristem's other
    /// symbol.
    fn module(&mut self, name: &str, params: Vec<String>, has_params: bool, n: usize) -> String {
        let with = |m: &str, p: &[String]| {
            if p.is_empty() {
                m.to_string()
            } else {
                format!("{m}({})", p.join(","))
            }
        };
        let tool = self.flavour.tool();
        let width = match self.flavour {
            Flavour::Cpfg => "#",
            Flavour::Lpy => "_",
        };
        if name == width {
            if has_params {
                return with("!", &params);
            }
            self.note_once(
                "width+",
                n,
                format!("{tool}'s '{width}' without a value widens by the width increment; Meristem has no such command; dropped"),
            );
            return String::new();
        }
        if let Some(text) = self.view_module(name, &params, has_params, n) {
            return text;
        }
        let query = name_of(Meaning::Turtle(Command::QueryPosition));
        if self.flavour == Flavour::Lpy && name == query && params.len() == 3 {
            // L-Py's turtle starts heading up along +Z and turns (`+`) in the Y-Z plane;
            // Meristem's heads along +Y and turns in the X-Y plane: L-Py's z is Meristem's y,
            // its y is Meristem's x, its x Meristem's z.
            self.note_once(
                query,
                n,
                "L-Py's turtle grows along +Z and turns towards Y, Meristem's grows along +Y and turns towards X: ?P(x,y,z) becomes ?P(y,z,x), so that each name reads the same axis of the plant; signs along the horizontal axes may differ",
            );
            let params = vec![params[1].clone(), params[2].clone(), params[0].clone()];
            return with(query, &params);
        }
        if name == "," {
            return if has_params {
                with(";", &params)
            } else {
                "'(-1)".into()
            };
        }
        if let Some(&(_, meaning)) = LPY_NAMES.iter().find(|(l, _)| *l == name) {
            return with(name_of(meaning), &params);
        }
        if name.starts_with('@') && module_named(name).is_none() {
            if !name[1..].chars().all(|c| c.is_ascii_alphabetic()) || name.len() == 1 {
                self.note_once(
                    name,
                    n,
                    format!("{tool}'s {name} is not a Meristem command; dropped"),
                );
                return String::new();
            }
            self.note_once(
                name,
                n,
                format!("{tool}'s {name} is not a Meristem command; kept as a module the turtle ignores"),
            );
        }
        if name.starts_with('~') && module_named(name).is_none() {
            self.note_once(
                name,
                n,
                format!("{name} names a surface from a file; Meristem draws only ~l and ~p, so it is kept as a module the turtle ignores"),
            );
        }
        if name.chars().count() > 1
            && name.chars().all(|c| c.is_ascii_alphanumeric())
            && !self.declared.iter().any(|d| d == name)
        {
            self.declared.push(name.to_string());
        }
        with(name, &params)
    }
}

/// `derivation length: 5` -> `Some(" 5")` (case-insensitive keyword).
fn keyword<'a>(lower: &str, code: &'a str, keyword: &str) -> Option<&'a str> {
    let compact: String = lower.chars().filter(|c| !c.is_whitespace()).collect();
    let key: String = keyword.chars().filter(|c| !c.is_whitespace()).collect();
    if !compact.starts_with(&key) {
        return None;
    }
    let colon = code.find(':')?;
    Some(&code[colon + 1..])
}

/// The section a line starts, in Meristem's words.
fn section(lower: &str) -> Option<String> {
    let word = lower.split(':').next().unwrap_or("").trim();
    let rest_ok = |w: &str| {
        let after = lower[w.len()..].trim_start_matches(':').trim();
        after.is_empty() || after == "no warnings"
    };
    match word {
        // cpfg's and L-Py's section words, and Meristem's section each starts.
        "homomorphism" if rest_ok("homomorphism") => Some(KeywordKind::Homomorphism),
        "interpretation" if rest_ok("interpretation") => Some(KeywordKind::Homomorphism),
        "decomposition" if rest_ok("decomposition") => Some(KeywordKind::Decomposition),
        "production" if rest_ok("production") => Some(KeywordKind::Productions),
        "productions" if rest_ok("productions") => Some(KeywordKind::Productions),
        _ => None,
    }
    .map(KeywordKind::written)
}

/// `A(t) :` -> `Some("A(t)")` when the line is a Python production's header.
fn python_production_header(code: &str) -> Option<&str> {
    let pattern = code.strip_suffix(':')?.trim();
    let first = pattern
        .split(|c: char| !c.is_ascii_alphanumeric() && c != '_')
        .next()?;
    let python = [
        "def", "if", "elif", "else", "for", "while", "class", "with", "try", "except", "finally",
    ];
    (!pattern.is_empty() && !python.contains(&first)).then_some(pattern)
}

/// `F(x) : produce F(x/3)` -> (`F(x)`, `F(x/3)`).
fn inline_produce(code: &str) -> Option<(&str, &str)> {
    let i = top_level(code, ":")?;
    let successor = produce(code[i + 1..].trim())?;
    Some((code[..i].trim(), successor))
}

/// The successor of a `produce` statement.
fn produce(code: &str) -> Option<&str> {
    let rest = code.strip_prefix("produce")?;
    (rest.is_empty() || rest.starts_with(char::is_whitespace)).then(|| rest.trim())
}

/// The index after the number that starts at `chars[start]` (digits, letters and dots, and a
/// sign after an exponent's `e`).
fn number_end(chars: &[char], start: usize) -> usize {
    let mut i = start;
    while i < chars.len()
        && (chars[i].is_ascii_alphanumeric()
            || chars[i] == '.'
            || ((chars[i] == '-' || chars[i] == '+') && matches!(chars[i - 1], 'e' | 'E')))
    {
        i += 1;
    }
    i
}

/// The module name at `chars[start]`, which is `@`, `~` or `?`: `@` and the letters after it
/// (or cpfg's one symbol, `@!`, `@#`), or `~` or `?` and one letter. Returns it and the index
/// after it.
fn symbol_name(chars: &[char], start: usize) -> (String, usize) {
    let mut i = start + 1;
    if chars[start] == '@' {
        while i < chars.len() && chars[i].is_ascii_alphabetic() {
            i += 1;
        }
        // cpfg's `@!`, `@#`: one symbol after the '@'.
        if i == start + 1 && i < chars.len() && !chars[i].is_whitespace() && chars[i] != '(' {
            i += 1;
        }
    } else if chars.get(i).is_some_and(char::is_ascii_alphabetic) {
        i += 1;
    }
    (chars[start..i].iter().collect(), i)
}

/// cpfg's `@`, `~` or `?` name at `chars[start]`, as [`symbol_name`] reads it, except that
/// cpfg's names of the generalized cylinder and texture (`@Gs`, `@Ge`, `@Gc`, `@Gt`, `@Gr`,
/// `@Tx`, `@Tf`) end after their two letters (`@GsF` is `@Gs` then `F`).
fn cpfg_symbol(chars: &[char], start: usize) -> (String, usize) {
    let (name, end) = symbol_name(chars, start);
    // dialect: cpfg's names
    for short in ["@Gs", "@Ge", "@Gc", "@Gt", "@Gr", "@Tx", "@Tf"] {
        if name.len() > short.len() && name.starts_with(short) {
            return (short.to_string(), start + short.len());
        }
    }
    (name, end)
}

/// The index of the ')' that closes the '(' at `open`.
fn matching(chars: &[char], open: usize) -> Option<usize> {
    let mut depth = 0;
    for (k, &c) in chars.iter().enumerate().skip(open) {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(k);
                }
            }
            _ => {}
        }
    }
    None
}

/// Splits at `sep` outside parentheses.
fn split_top(text: &str, sep: char) -> Vec<&str> {
    let mut parts = Vec::new();
    let mut depth = 0i32;
    let mut start = 0;
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            c if c == sep && depth == 0 => {
                parts.push(&text[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&text[start..]);
    parts
}

/// The condition of a branch nested in the `if` headers `open` (with its own, if any): the
/// conditions joined by `&&`.
fn nested(open: &[(usize, Option<String>)], own: Option<String>) -> Option<String> {
    let parts: Vec<String> = open
        .iter()
        .filter_map(|(_, c)| c.clone())
        .chain(own)
        .collect();
    match parts.len() {
        0 => None,
        1 => parts.into_iter().next(),
        _ => Some(
            parts
                .iter()
                .map(|c| format!("({c})"))
                .collect::<Vec<_>>()
                .join(" && "),
        ),
    }
}

/// The local assignments that open an L-Py body, before its first `if` or `produce`
/// (`p1 = min(1,(2*k+1)/k**2)`, `a += 0.1`), taken from `lines`: their names and values, which
/// are put where the names are used, as cpfg's statement blocks are. An `if`/`elif`/`else` whose
/// branches only assign (`if x == 1:` / `auxin = max_level` / `else:` / `auxin = min_level`)
/// gives each name it assigns a conditional value, `((c)?(a):(b))`. A random draw used in more
/// than one place stays (it would be drawn again in each), and the body is then skipped with its
/// note.
fn python_locals(lines: &mut Vec<&Line>) -> (Vec<String>, Vec<String>) {
    let mut names: Vec<String> = Vec::new();
    let mut values: Vec<String> = Vec::new();
    while let Some(line) = lines.first() {
        if let Some((taken, assigned)) = python_if_assignments(lines, &names, &values) {
            // Each use copies a value: a value that grows too long is not taken (see MAX_VALUE).
            if assigned.iter().any(|(_, v)| v.len() > MAX_VALUE) {
                break;
            }
            for (name, value) in assigned {
                bind(&mut names, &mut values, name, value);
            }
            lines.drain(..taken);
            continue;
        }
        let Some((name, value)) = python_local(&line.code) else {
            break;
        };
        let value = format!("({})", cpp::substitute(&value, &names, &values));
        let rest: String = lines[1..].iter().map(|l| format!("{}\n", l.code)).collect();
        let uses = rest.match_indices(&name).filter(|(i, _)| {
            let before = rest[..*i].chars().next_back();
            let after = rest[i + name.len()..].chars().next();
            !before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_')
                && !after.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_')
        });
        let random = ["random", "uniform", "gauss", "randint", "normal"]
            .iter()
            .any(|r| value.contains(r));
        if random && uses.count() > 1 || value.len() > MAX_VALUE {
            // Put in each place it is used, a random draw would be drawn again each time.
            break;
        }
        bind(&mut names, &mut values, name, value);
        lines.remove(0);
    }
    (names, values)
}

/// Binds `name` to `value` (already in terms of the earlier names): a name bound again takes
/// the new value in its place.
fn bind(names: &mut Vec<String>, values: &mut Vec<String>, name: String, value: String) {
    match names.iter().position(|n| *n == name) {
        Some(k) => values[k] = value,
        None => {
            names.push(name);
            values.push(value);
        }
    }
}

/// A branch of an L-Py `if`: its condition (`None` for else) and what it assigns.
type Branch = (Option<String>, Vec<(String, String)>);

/// An `if c:` at `lines[0]` followed by `elif c:`/`else:` at the same indentation, whose
/// branches hold only local assignments: how many lines it takes, and each name it assigns with
/// its conditional value (the value before the `if`, or the name itself, where a branch does not
/// assign it). `None` when `lines[0]` opens no such `if`.
fn python_if_assignments(
    lines: &[&Line],
    names: &[String],
    values: &[String],
) -> Option<(usize, Vec<(String, String)>)> {
    let head = lines.first()?;
    let indent = head.indent;
    let mut branches: Vec<Branch> = Vec::new();
    let mut k = 0;
    while let Some(line) = lines.get(k) {
        let code = line.code.as_str();
        let condition = if k == 0 {
            ["if ", "if("]
                .iter()
                .any(|p| code.starts_with(p))
                .then(|| &code[2..])?
        } else if line.indent == indent
            && ["elif ", "elif(", "else"]
                .iter()
                .any(|p| code.starts_with(p))
        {
            // `elif c:` and `else:` alike: four letters, then the condition (none for else).
            &code[4..]
        } else {
            break;
        };
        let condition = condition.trim().strip_suffix(':')?.trim();
        if branches.last().is_some_and(|(c, _)| c.is_none()) {
            break;
        }
        let mut assigned = Vec::new();
        k += 1;
        while let Some(inner) = lines.get(k).filter(|l| l.indent > indent) {
            let (name, value) = python_local(&inner.code)?;
            let earlier: Vec<String> = assigned
                .iter()
                .map(|(n, _): &(String, String)| n.clone())
                .collect();
            let earlier_values: Vec<String> = assigned.iter().map(|(_, v)| v.clone()).collect();
            let value = cpp::substitute(
                &cpp::substitute(&value, &earlier, &earlier_values),
                names,
                values,
            );
            assigned.push((name, format!("({value})")));
            k += 1;
        }
        if assigned.is_empty() {
            return None;
        }
        let condition = (!condition.is_empty())
            .then(|| format!("({})", cpp::substitute(condition, names, values)));
        branches.push((condition, assigned));
    }
    Some((k, conditional_values(&branches, names, values)))
}

/// Each name the branches of an `if` assign, with its conditional value: `((c)?(own):(rest))`,
/// a branch that does not assign it taking the value before the `if` (or the name itself).
fn conditional_values(
    branches: &[Branch],
    names: &[String],
    values: &[String],
) -> Vec<(String, String)> {
    let mut all: Vec<String> = branches
        .iter()
        .flat_map(|(_, a)| a.iter().map(|(n, _)| n.clone()))
        .collect();
    all.sort();
    all.dedup();
    all.into_iter()
        .map(|name| {
            let before = names
                .iter()
                .position(|n| *n == name)
                .map_or_else(|| name.clone(), |k| values[k].clone());
            let mut value = before.clone();
            for (condition, assigned) in branches.iter().rev() {
                let own = assigned
                    .iter()
                    .rev()
                    .find(|(n, _)| *n == name)
                    .map_or_else(|| before.clone(), |(_, v)| v.clone());
                value = match condition {
                    Some(c) => format!("({c}?{own}:{value})"),
                    None => own,
                };
            }
            (name, value)
        })
        .collect()
}

/// A Python local assignment `name = value` or `name += value` (and `-=`, `*=`, `/=`; not `==`):
/// the name and the value (`name + (value)` for `+=`).
fn python_local(code: &str) -> Option<(String, String)> {
    let (name, value) = code.split_once('=')?;
    let value = value.trim();
    let (name, op) = match name.trim_end().strip_suffix(['+', '-', '*', '/']) {
        Some(n) => (n.trim(), name.trim_end().chars().last()),
        None => (name.trim(), None),
    };
    if !is_identifier(name)
        || value.is_empty()
        || value.starts_with('=')
        || ["global", "produce", "nproduce", "return"].contains(&name)
    {
        return None;
    }
    Some(match op {
        Some(op) => (name.to_string(), format!("{name} {op} ({value})")),
        None => (name.to_string(), value.to_string()),
    })
}

/// The globals of an L-Py file (assigned at the top level or named by `global`) that nothing
/// reads: every use is a `global` statement, an assignment to it, or inside a text label `@L(…)`,
/// which is dropped.
fn write_only_globals(all: &[Line]) -> Vec<String> {
    let mut candidates: Vec<String> = Vec::new();
    for line in all {
        if let Some(rest) = line.code.strip_prefix("global ") {
            candidates.extend(rest.split(',').map(|g| g.trim().to_string()));
        }
    }
    candidates.retain(|g| is_identifier(g));
    candidates.sort();
    candidates.dedup();
    candidates.retain(|g| {
        all.iter().all(|line| {
            let code = line.code.as_str();
            if code.starts_with("global ") || global_write(code, std::slice::from_ref(g)).is_some()
            {
                return true;
            }
            !has_word(&without_labels(code), g)
        })
    });
    candidates
}

/// Whether `word` stands alone (not part of a longer name) anywhere in `text`.
fn has_word(text: &str, word: &str) -> bool {
    let b = text.as_bytes();
    text.match_indices(word).any(|(i, _)| {
        let end = i + word.len();
        (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'))
            && (end >= b.len() || !(b[end].is_ascii_alphanumeric() || b[end] == b'_'))
    })
}

/// `code` without its text labels `@L(…)`.
fn without_labels(code: &str) -> String {
    let mut out = code.to_string();
    while let Some(at) = out.find("@L(") {
        let chars: Vec<char> = out.chars().collect();
        let open = out[..at + 2].chars().count();
        let Some(close) = matching(&chars, open) else {
            break;
        };
        let end: usize = chars[..=close].iter().map(|c| c.len_utf8()).sum();
        out.replace_range(at..end, "");
    }
    out
}

/// The global of `globals` that `code` is about, when it is `global g` naming only such globals
/// or an assignment to one (`g = …`, `g += …`).
fn global_write(code: &str, globals: &[String]) -> Option<String> {
    if let Some(rest) = code.strip_prefix("global ") {
        let names: Vec<&str> = rest.split(',').map(str::trim).collect();
        return names
            .iter()
            .all(|g| globals.iter().any(|w| w == g))
            .then(|| names.join(", "));
    }
    let (name, _) = python_local(code)?;
    globals.contains(&name).then_some(name)
}

/// `text` (a successor) with each name replaced by its value inside parentheses (the modules'
/// parameters), never in the module names themselves.
fn in_parentheses(text: &str, names: &[String], values: &[String]) -> String {
    if names.is_empty() {
        return text.to_string();
    }
    let mut out = String::new();
    let mut depth = 0usize;
    let mut inside = String::new();
    for c in text.chars() {
        match c {
            '(' => {
                if depth == 0 {
                    out.push('(');
                } else {
                    inside.push('(');
                }
                depth += 1;
            }
            ')' if depth > 0 => {
                depth -= 1;
                if depth == 0 {
                    out.push_str(&cpp::substitute(&inside, names, values));
                    inside.clear();
                    out.push(')');
                } else {
                    inside.push(')');
                }
            }
            _ if depth > 0 => inside.push(c),
            _ => out.push(c),
        }
    }
    out.push_str(&inside);
    out
}

/// The byte index of `word` standing alone (not part of a longer name), outside parentheses.
fn find_word(text: &str, word: &str) -> Option<usize> {
    let bytes = text.as_bytes();
    let mut depth = 0i32;
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            _ => {}
        }
        if depth == 0 && text[i..].starts_with(word) {
            let before = i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
            let end = i + word.len();
            let after =
                end >= bytes.len() || !(bytes[end].is_ascii_alphanumeric() || bytes[end] == b'_');
            if before && after {
                return Some(i);
            }
        }
    }
    None
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

#[cfg(test)]
mod tests {
    use super::*;

    /// 200 chained `#define`s, each using the one before twice (through a macro with an
    /// argument, which is expanded), an `#if` on the last, and an axiom drawing it.
    fn define_chain(links: usize) -> String {
        let mut text = String::from("#define HALF(x) (x)/2\n#define C0 1\n");
        for i in 1..=links {
            text += &format!("#define C{i} HALF(C{} + C{})\n", i - 1, i - 1);
        }
        text += &format!(
            "Lsystem: 1\nderivation length: 1\nAxiom: A\n#if C{links} > 0.5\nA --> F(C{links})\n#else\nA --> F(7)\n#endif\nendlsystem\n"
        );
        text
    }

    #[test]
    fn chained_defines_are_expanded_once_each_not_as_doubling_text() {
        let links = 200;
        let text = define_chain(links);
        // The preprocessor alone: one expansion a link (HALF), none of a kept macro.
        let functions = cpp_functions();
        let names: Vec<&str> = functions.iter().map(String::as_str).collect();
        let none = |_: &str| None;
        let mut pre = cpp::Preprocessor::new(&none, &names);
        let out = pre.run(lines(&text, Flavour::Cpfg), 0);
        assert_eq!(pre.expansions, links, "{:?}", pre.notes);
        assert!(pre.notes.is_empty(), "{:?}", pre.notes);
        let kept: Vec<&str> = out
            .iter()
            .map(|l| l.code.as_str())
            .filter(|c| c.starts_with("#define"))
            .collect();
        assert_eq!(kept.len(), links + 1);
        assert_eq!(
            kept[links],
            format!("#define C{links} (C{} + C{})/2", links - 1, links - 1)
        );
        // The `#if` read C200's number (1), so the first production is the one kept.
        assert!(out
            .iter()
            .any(|l| l.code.trim() == format!("A --> F(C{links})")));
        assert!(!out.iter().any(|l| l.code.contains("F(7)")));

        // The whole import: linear in size, and the plant it gives draws F(1).
        let import = import(&text, Flavour::Cpfg);
        assert!(import.notes.is_empty(), "{:?}", import.notes);
        assert!(
            import.text.len() < 60 * links,
            "{} bytes for {links} links",
            import.text.len()
        );
        let built = crate::pipeline::build(&import.text, &crate::BuildOptions::default());
        let segments = &built.plant.skeleton.segments;
        assert_eq!(segments.len(), 1, "{}", import.text);
        let length = (segments[0].end - segments[0].start).length();
        assert!((length - 1.0).abs() < 1e-9, "{length}");
    }

    fn body(import: &Import) -> Vec<&str> {
        import
            .text
            .lines()
            .filter(|l| !l.starts_with("//") && !l.is_empty())
            .collect()
    }

    fn resolves(import: &Import) {
        let (file, d) = crate::syntax::parse(&import.text);
        let (_, r) = crate::model::resolve(&file);
        assert!(
            !crate::diagnostics::has_errors(&d) && !crate::diagnostics::has_errors(&r),
            "{}\n{d:?}{r:?}",
            import.text
        );
    }

    #[test]
    fn lpy_reads_undeclared_words_letter_by_letter_and_nests_its_ifs_and_locals() {
        let import = import(
            "Axiom: A(1)\nderivation length: 2\nproduction:\nA(x) :\n    p = min(1, x**2)\n    r = random()\n    if r <= p:\n        produce IB(1-x)\n    else:\n        produce A(x+p)\nB(x) :\n    if x >= 1:\n        if x < 3:\n            produce F(x)\n        else:\n            produce F(1)\n    else:\n        produce B(x+1)\nendlsystem\n",
            Flavour::Lpy,
        );
        resolves(&import);
        assert_eq!(
            body(&import)[3..],
            [
                // IB is I then B: Meristem reads undeclared letters one by one too.
                "A(x) : (uniform(0,1)) <= (min(1,x^2)) -> IB(1-x)",
                "A(x) -> A(x+(min(1,x^2)))",
                "B(x) : (x >= 1) && (x < 3) -> F(x)",
                "B(x) : x >= 1 -> F(1)",
                "B(x) -> B(x+1)",
                "endlsystem",
            ]
        );
        // It draws random numbers: one note says that the same seed gives another plant.
        assert_eq!(import.notes.len(), 1, "{:?}", import.notes);
        assert!(
            import.notes[0].line == 0
                && import.notes[0]
                    .message
                    .starts_with("L-Py draws its random numbers with another generator")
        );
        // A random draw used twice would be drawn again in each place: not translated.
        let twice = super::import(
            "Axiom: A\nderivation length: 2\nproduction:\nA :\n    r = random()\n    if r < 0.3: produce B\n    elif r < 0.6: produce C\nendlsystem\n",
            Flavour::Lpy,
        );
        assert!(twice.notes[0]
            .message
            .contains("'r = random()' is not translated"));
    }

    #[test]
    fn a_cpfg_define_continues_over_any_number_of_lines() {
        let import = import(
            "#define BOX [F(1) \\\n\t+(90)F(2) \\\n\t+(90)F(3)]\nLsystem: 1\nderivation length: 1\nAxiom: BOX A\nA --> FA\nendlsystem\n",
            Flavour::Cpfg,
        );
        resolves(&import);
        assert!(import.notes.is_empty(), "{:?}", import.notes);
        assert!(
            import.text.contains("axiom: [F(1)+(90)F(2)+(90)F(3)]A"),
            "{}",
            import.text
        );
    }

    #[test]
    fn cpfg_heads_over_several_lines_whole_branch_contexts_and_labels() {
        let import = import(
            "Lsystem: 1\nderivation length: 2\nAxiom: N(1)I(0)[I(2)A]I(3)\nN(k) < I(b) : b==0\n\t{f=k*2;} -->\n\tI(f)\nI(b) > [I(c)=]I(d) : b==0 --> I(c+d)@L(\" %.f\", b)\nendlsystem\n",
            Flavour::Cpfg,
        );
        resolves(&import);
        assert_eq!(
            body(&import)[2..],
            [
                "N(k) < I(b) : b==0 -> I((k*2))",
                "I(b) > [I(c)]I(d) : b==0 -> I(c+d)",
                "endlsystem"
            ]
        );
        assert_eq!(import.notes.len(), 1, "{:?}", import.notes);
        assert!(import.notes[0].message.contains("@L draws a text label"));
    }

    #[test]
    fn new_contexts_become_ordinary_contexts_with_a_note_that_says_what_changes() {
        for flavour in [Flavour::Lpy, Flavour::Cpfg] {
            let import = import(
                "Axiom: A B B\nderivation length: 2\nproduction:\nA << B --> A\nB >> A --> C\nA < B --> B\nendlsystem\n",
                flavour,
            );
            resolves(&import);
            let body = body(&import);
            assert!(body.contains(&"A < B -> A"), "{body:?}");
            assert!(body.contains(&"B > A -> C"), "{body:?}");
            let notes: Vec<&str> = import.notes.iter().map(|n| n.message.as_str()).collect();
            let new_context = |side: &str| {
                notes
                    .iter()
                    .filter(|m| {
                        m.contains(&format!("new {side} context"))
                            && m.contains("one module a step")
                    })
                    .count()
            };
            assert_eq!(
                (new_context("left"), new_context("right")),
                (1, 1),
                "{notes:?}"
            );
        }
    }

    #[test]
    fn cpfg_blocks_are_substituted_and_probabilities_become_weights() {
        let import = import(
            "#define STEPS 4 /* steps */\n#define R 1.3\nLsystem: 1\nderivation length: STEPS\nignore: +-/\nAxiom: #(0.05)A(0)\nA(t) : {t=t-1;} t>0 --> \n\tI(t)[+(45)A(t)]\nM(t) : 1 {x=0.5*R^t; x+=1;} --> I(x)M(t)\nF --> F[+F]F : 0.3\nB --> *\ndecomposition\nmaximum depth: 2\nhomomorphism: no warnings\nI(x) --> F(x)\nendlsystem\n",
            Flavour::Cpfg,
        );
        resolves(&import);
        assert_eq!(
            body(&import),
            [
                "#define STEPS 4 // steps",
                "#define R 1.3",
                "derivation length: STEPS",
                "#ignore + - /",
                "axiom: !(0.05)A(0)",
                "A(t) : (t-1)>0 -> I((t-1))[+(45)A((t-1))]",
                "M(t) : 1 -> I(((0.5*R^t)+(1)))M(t)",
                "F -> (0.3) F[+F]F",
                "B -> ε",
                "decomposition:",
                "maximum depth: 2",
                "homomorphism:",
                // cpfg's default depth, which the section does not change.
                "maximum depth: 1",
                "I(x) -> F(x)",
                "endlsystem",
            ]
        );
        // `F[+F]F` turns by the view file's angle, which a `.l` alone does not give; its
        // probability draws random numbers, with another generator than cpfg's.
        assert_eq!(import.notes.len(), 2, "{:?}", import.notes);
        assert!(import.notes[0].line == 0 && import.notes[0].message.contains("angle increment"));
        assert_eq!(
            import.notes[1].message,
            "cpfg draws its random numbers with another generator than Meristem's: the same seed gives a different plant than in cpfg (the distribution of plants is the same)"
        );
    }

    #[test]
    fn cpfg_if_blocks_become_conditional_values_and_printf_is_noted() {
        let import = import(
            "#define REL 1\nderivation length: 2\nAxiom: A(1,4)\nE : 1 {srand(1);} --> *\nA(x,w) : x<3\n\t{t = 2*x;\n\tif (REL) {t = t/2; w = 0;} else t = t+1;\n\tif (w<t) {w = t;}\n\tprintf(\"%f\", t);\n\tt - 1;\n\t} --> F(t)A(x+1,w)\nendlsystem\n",
            Flavour::Cpfg,
        );
        resolves(&import);
        assert!(
            import.text.contains(
                "A(x,w) : x<3 -> F(((REL)?((2*x)/2):((2*x)+1)))A(x+1,((((REL)?(0):w)<((REL)?((2*x)/2):((2*x)+1)))?(((REL)?((2*x)/2):((2*x)+1))):((REL)?(0):w)))"
            ),
            "{}",
            import.text
        );
        let said: Vec<(usize, &str)> = import
            .notes
            .iter()
            .map(|n| (n.line, n.message.as_str()))
            .collect();
        assert!(
            said.iter()
                .any(|(l, m)| *l == 4 && m.contains("'srand(1)' restarts")),
            "{said:?}"
        );
        assert!(
            said.iter()
                .any(|(l, m)| *l == 5 && m.starts_with("cpfg's printf")),
            "{said:?}"
        );
        assert!(
            said.iter()
                .any(|(l, m)| *l == 5 && m.contains("'t - 1' assigns nothing")),
            "{said:?}"
        );
        let b = crate::pipeline::build(&import.text, &crate::pipeline::BuildOptions::default());
        assert!(b.ok(), "{:?}", b.diagnostics);
        // A(1,4) → F(1)A(2,0) → F(1)F(2)A(3,0): two segments.
        assert_eq!(b.plant.stats.segments, 2);
        // A loop is not translated: the production is skipped with a note.
        let looped = super::import(
            "Axiom: A(1)\nA(x) : {while (x < 3) {x = x + 1;}} --> F(x)\n",
            Flavour::Cpfg,
        );
        assert!(
            looped
                .notes
                .iter()
                .any(|n| n.line == 2 && n.message.contains("is a loop")),
            "{:?}",
            looped.notes
        );
    }

    #[test]
    fn cpfg_arrays_of_two_dimensions_and_predecessors_of_several_letters() {
        let import = import(
            "#define N 3\nLsystem: 1\nDefine: { array len[2][N] = {1, 2, 3, 4, 5, 6}; }\nderivation length: 1\nAxiom: AXIOM\nAXIOM : 1 --> F(len[0][2])F(len[1][0])F(len[1][ 2 ])F(len[5][5])\nendlsystem\n",
            Flavour::Cpfg,
        );
        resolves(&import);
        assert!(import.text.contains("#module AXIOM_"), "{}", import.text);
        assert!(import.text.contains("axiom: AXIOM_"), "{}", import.text);
        assert_eq!(import.notes.len(), 1, "{:?}", import.notes);
        assert!(import.notes[0]
            .message
            .contains("becomes one module AXIOM_"));
        let b = crate::pipeline::build(&import.text, &crate::pipeline::BuildOptions::default());
        assert!(b.ok(), "{:?}", b.diagnostics);
        // len[0][2] = 3, len[1][0] = 4, len[1][2] = 6, and past the end the last value, 6.
        assert_eq!(b.derived_text(), "F(3)F(4)F(6)F(6)", "{}", import.text);
    }

    #[test]
    fn cpfg_predecessors_of_several_modules_become_contexts_and_axioms_continue() {
        let import = import(
            "derivation length: 1\nAxiom: [F(2,0)#(1)]\n\t[F(3,1)#(2)]\nF(v,n)#(w) : n == 0 --> F(v)#(w)@O\n",
            Flavour::Cpfg,
        );
        resolves(&import);
        let body = body(&import);
        assert!(
            body.contains(&"axiom: [F(2,0)!(1)][F(3,1)!(2)]"),
            "{body:?}"
        );
        assert!(
            body.contains(&"F(v,n) > !(w) : n == 0 -> F(v)!(w)@O"),
            "{body:?}"
        );
        assert!(body.contains(&"F(v,n) < !(w) : n == 0 -> ε"), "{body:?}");
        assert!(
            import
                .notes
                .iter()
                .any(|n| n.line == 4 && n.message.contains("is 2 modules")),
            "{:?}",
            import.notes
        );
        let b = crate::pipeline::build(&import.text, &crate::pipeline::BuildOptions::default());
        assert!(b.ok(), "{:?}", b.diagnostics);
        assert_eq!(b.derived_text(), "[F(2)!(1)@O][F(3,1)!(2)]");
    }

    #[test]
    fn cpfg_sections_without_a_depth_get_cpfgs_default_depth_one() {
        let import = import(
            "derivation length: 0\nAxiom: h\nhomomorphism\nh --> [F]f\nf --> [F]f\nendlsystem\n",
            Flavour::Cpfg,
        );
        resolves(&import);
        assert_eq!(
            body(&import),
            [
                "derivation length: 0",
                "axiom: h",
                "homomorphism:",
                "maximum depth: 1",
                "h -> [F]f",
                "f -> [F]f",
                "endlsystem"
            ]
        );
        let b = crate::pipeline::build(&import.text, &crate::pipeline::BuildOptions::default());
        // h is drawn once: its f is not rewritten again, as in cpfg.
        assert_eq!(b.plant.stats.segments, 1);
        let deeper = super::import(
            "Axiom: h\nhomomorphism\nmaximum depth: 3\nh --> [F]f\nendlsystem\n",
            Flavour::Cpfg,
        );
        assert!(!deeper.text.contains("maximum depth: 1"), "{}", deeper.text);
    }

    #[test]
    fn lpy_flags_set_by_a_production_become_defines_over_the_step() {
        let text = "m = 0\nAxiom: P(0)G\nderivation length: 6\nproduction:\nP(t) :\n    if t < 3: produce P(t+1)\n    else:\n        global m\n        m = 1\n        produce *\nG :\n    if m == 1: produce FG\nendlsystem\n";
        let import = import(text, Flavour::Lpy);
        resolves(&import);
        // P(0) → P(1) → P(2) → P(3) in three steps; the fourth erases it and sets m: from the
        // fifth step on, G grows an F a step (steps 5 and 6).
        assert!(
            import.text.contains("#define m (NumIt > 4 ? 1 : 0)"),
            "{}",
            import.text
        );
        assert!(!import.text.contains("ProbeMark"), "{}", import.text);
        assert_eq!(import.notes.len(), 1, "{:?}", import.notes);
        assert!(import.notes[0].message.contains("first applies in step 4"));
        let b = crate::pipeline::build(&import.text, &crate::pipeline::BuildOptions::default());
        assert_eq!(b.derived_text(), "FFG");
        // A flag set to two different values is not one: the body is skipped as before.
        let two = text.replace("    if m == 1", "    global m\n    m = 2\n    if m == 1");
        let import = super::import(&two, Flavour::Lpy);
        assert!(!import.text.contains("NumIt >"), "{}", import.text);
        assert!(
            import
                .notes
                .iter()
                .any(|n| n.message.contains("'global m' is not translated")),
            "{:?}",
            import.notes
        );
    }

    #[test]
    fn lpfg_blocks_produce_conditional_productions() {
        let import = import(
            "#include <lpfgall.h>\n#define PL 0.5\nderivation length: 3;\nmodule A(float);\nmodule Apex(float);\nAxiom: Right(5) SetWidth(0.15) A(1.2) Apex(0);\nproduction:\nApex(t):{ produce Apex(t+1); }\ndecomposition:\nA(t):\n{\n\tt = t - PL;\n\tif(t>0)\n\t\tproduce F(t) SB() Left(30) F(1) EB() A(t);\n\tfloat w = 2*t;\n\tproduce Sphere(w) Frobnicate(1);\n}\n",
            Flavour::Cpfg,
        );
        resolves(&import);
        let body = body(&import);
        assert!(body.contains(&"#module Apex"), "{body:?}");
        assert!(
            body.contains(&"axiom: -(5)!(0.15)A(1.2)Apex(0)"),
            "{body:?}"
        );
        assert!(body.contains(&"Apex(t) -> Apex(t+1)"), "{body:?}");
        assert!(
            body.contains(&"A(t) : (t - PL)>0 -> F((t - PL))[+(30)F(1)]A((t - PL))"),
            "{body:?}"
        );
        assert!(
            body.contains(&"A(t) : !((t - PL)>0) -> @O((2*(t - PL)))"),
            "{body:?}"
        );
        assert_eq!(import.notes.len(), 1, "{:?}", import.notes);
        assert!(import.notes[0]
            .message
            .contains("Frobnicate is not a Meristem command"));
        let b = crate::pipeline::build(&import.text, &crate::pipeline::BuildOptions::default());
        assert!(b.ok(), "{:?}", b.diagnostics);
        // A(1.2) → F(0.7)[+F]A(0.7) → F(0.7)[+F]F(0.2)[+F]A(0.2) → … @O(-0.6): four segments.
        assert_eq!(b.plant.stats.segments, 4, "{}", b.derived_text());
    }

    #[test]
    fn lpy_python_becomes_defines_and_conditional_productions() {
        let import = import(
            "import math\nR = 1.456\nh = (0.3*0.7) ** 0.5\n__authors__ = 'C. Godin'\n\nAxiom: _(0.01) ,(2) A(1)\nderivation length: 3\nproduction:\nA(s) --> F(s)[+(85)A(s/R)][-(85)A(s/R)]\nB(t) :\n    if t < 2 and not t == 1: produce B(t+1)\n    elif t == 2:\n        produce C(t if t > 1 else 0)\n    else: produce *\nF(x) : produce F(x/3.)+(60)F(x/3.)\ninterpretation:\nC(t) --> F(sin(t))\nendlsystem\ndef End():\n    print('x')\n",
            Flavour::Lpy,
        );
        resolves(&import);
        assert_eq!(
            body(&import),
            [
                "#define R 1.456",
                "#define h (0.3*0.7) ^ 0.5",
                "axiom: !(0.01);(2)A(1)",
                "derivation length: 3",
                "productions:",
                "A(s) -> F(s)[+(85)A(s/R)][-(85)A(s/R)]",
                "B(t) : t < 2 && ! t == 1 -> B(t+1)",
                "B(t) : t == 2 -> C((t > 1?t:0))",
                "B(t) -> ε",
                "F(x) -> F(x/3.)+(60)F(x/3.)",
                "homomorphism:",
                "C(t) -> F(sin((t)*57.2957795131))",
                "endlsystem",
            ]
        );
        let notes: Vec<(usize, &str)> = import
            .notes
            .iter()
            .map(|n| (n.line, n.message.as_str()))
            .collect();
        assert_eq!(notes.len(), 2, "{notes:?}");
        assert!(notes[0].0 == 1 && notes[0].1.contains("imports"));
        assert!(notes[1].0 == 19 && notes[1].1.contains("'End'"));
        assert!(import.text.contains("// authors: C. Godin"));
    }

    #[test]
    fn what_cannot_be_translated_is_reported_at_its_line() {
        let import = import(
            "#include \"x.h\"\n#define f(x) x\nAxiom: A(1)\nA(t) : {while (t>1) t=t-1;} t>0 --> B\nA(t) --> @c(1)~k(2)F(frob(1,t))\nendlsystem\nLsystem: 2\n",
            Flavour::Cpfg,
        );
        resolves(&import);
        let lines: Vec<usize> = import.notes.iter().map(|n| n.line).collect();
        // `#define f(x) x` is expanded where it is used (line 2 needs no note).
        assert_eq!(lines, [1, 4, 5, 5, 5, 7], "{:?}", import.notes);
        assert!(import
            .text
            .contains("// not imported: A(t) -> @c(1)~k(2)F(frob(1,t))"));
    }

    #[test]
    fn lpy_helpers_tuples_and_the_iteration_number_are_translated() {
        let import = import(
            "def long(x):\n  return 2*x\ndef alpha(x): return 30\nTOP, dr = 10, 0.02\nAxiom: A(1)\nderivation length: 3\nproduction:\nA(n) :\n  if(n < TOP): produce F(long(n))+(alpha(n))A(n+dr)\nB(n) --> B(getIterationNb())\nendlsystem\n",
            Flavour::Lpy,
        );
        resolves(&import);
        assert_eq!(
            body(&import),
            [
                "#define TOP 10",
                "#define dr 0.02",
                "axiom: A(1)",
                "derivation length: 3",
                "productions:",
                "A(n) : (n < TOP) -> F((2*(n)))+((30))A(n+dr)",
                "B(n) -> B((NumIt-1))",
                "endlsystem",
            ]
        );
        assert!(import.notes.is_empty(), "{:?}", import.notes);
        assert!(import
            .text
            .contains("// L-Py's function long(x) = 2*x, inlined where it is called"));
        let literal = super::import(
            "Axiom: D(20,1)\nderivation length: 2\nproduction:\nD(20,k) : k > 0 --> D(20,k+1)F\nD(x,k) --> D(x,k)\nendlsystem\n",
            Flavour::Lpy,
        );
        resolves(&literal);
        assert!(
            literal
                .text
                .contains("D(v_lit1,k) : v_lit1 == 20 && (k > 0) -> D(20,k+1)F"),
            "{}",
            literal.text
        );
    }

    #[test]
    fn lpy_bodies_with_other_code_are_skipped_whole() {
        let import = import(
            "Axiom: A(0)\nA(t) :\n    x = t + 1\n    produce A(x)\nA(t) :\n    nproduce B\n",
            Flavour::Lpy,
        );
        resolves(&import);
        // A local assignment before `produce` is put where it is used; `nproduce` is skipped.
        assert_eq!(body(&import), ["axiom: A(0)", "A(t) -> A((t + 1))"]);
        assert_eq!(import.notes.len(), 1, "{:?}", import.notes);
        assert!(import.notes[0].message.contains("nproduce B"));
    }

    #[test]
    fn odd_input_never_panics() {
        for text in [
            "",
            "Axiom:",
            "-->",
            "A --> B(",
            "A(t) : {x= --> B",
            "Axiom: A\nA :\n",
            "if",
            "x = 'a'\nAxiom: F(\"a\")",
            "Axiom: A\nA --> B : \n",
        ] {
            for flavour in [Flavour::Cpfg, Flavour::Lpy] {
                let import = import(text, flavour);
                let (file, _) = crate::syntax::parse(&import.text);
                if file.axiom.is_some() {
                    let (_, d) = crate::model::resolve(&file);
                    assert!(
                        !crate::diagnostics::has_errors(&d),
                        "{text:?}: {d:?}\n{}",
                        import.text
                    );
                }
            }
        }
    }
}
