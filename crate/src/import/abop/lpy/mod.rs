//! What only L-Py writes: Python around and inside the L-system. Assignments of numbers become
//! `#define`s, helper functions returning one expression are inlined, production bodies of
//! `if`/`elif`/`else` and `produce` become conditional productions ([`bodies`]), globals that
//! productions set become flags ([`flags`], [`globals`]); L-Py's long module names.

pub(super) mod axes;
pub(super) mod bodies;
pub(super) mod flags;
pub(super) mod globals;

use super::{is_identifier, split_top, top_level, Env, Importer, Line};
use crate::syntax::PARENTHESES;
use crate::vocabulary::{Command, DirectiveKind, Meaning};

/// L-Py's predefined modules with long names that have a Meristem command.
pub(in crate::import::abop) const LPY_NAMES: &[(&str, Meaning)] = &[
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
    ("LineTo", Meaning::Turtle(Command::LineTo)),
    ("LineRel", Meaning::Turtle(Command::LineRel)),
    ("OLineTo", Meaning::Turtle(Command::OrientedLineTo)),
    ("OLineRel", Meaning::Turtle(Command::OrientedLineRel)),
    ("SetHead", Meaning::Turtle(Command::SetHeading)),
    ("Frame", Meaning::Turtle(Command::Frame)),
    ("StartGC", Meaning::Turtle(Command::StartSmooth)),
    ("EndGC", Meaning::Turtle(Command::EndSmooth)),
    ("Cut", Meaning::Cut),
    ("GetPos", Meaning::Turtle(Command::QueryPosition)),
    ("GetHead", Meaning::Turtle(Command::QueryHeading)),
    ("GetUp", Meaning::Turtle(Command::QueryUp)),
    ("GetLeft", Meaning::Turtle(Command::QueryLeft)),
];

/// L-Py's predefined modules whose names start with `@` (its `predefinedmodules.cpp`): L-Py
/// reads them longest first, so `@gSetColor(3)` is `@g` then `SetColor(3)`.
const LPY_AT_NAMES: &str = "@2D @3D @B @D @Dd @Di @Gc @Ge @L @M @O @R @Tp @Ts @b @g @h @o @v";

/// The module name at `chars[start]`, an `@`, `~` or `?`, as L-Py reads it: one of its `@` names,
/// longest first; otherwise as [`super::modules::symbol_name`] reads any dialect's.
pub(in crate::import::abop) fn lpy_symbol_name(chars: &[char], start: usize) -> (String, usize) {
    let (name, end) = super::modules::symbol_name(chars, start);
    let known = LPY_AT_NAMES
        .split(' ')
        .filter(|at| name.starts_with(at))
        .max_by_key(|at| at.len());
    match known {
        Some(at) if at.len() < name.len() => (at.to_string(), start + at.chars().count()),
        _ => (name, end),
    }
}

/// L-Py's other predefined modules with names longer than a letter (its `predefinedmodules.cpp`):
/// a word among them is one module even undeclared; any other undeclared word is read letter by
/// letter, as L-Py reads it (`IB(1-x)` is `I` then `B(1-x)`).
pub(in crate::import::abop) const LPY_PREDEFINED: &[&str] = &[
    "GetRight",
    "GetFrame",
    "BP",
    "EP",
    "PP",
    "MoveRel",
    "Pinpoint",
    "PinpointRel",
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

/// A line of L-Py text that a Python string over several lines (`"""…"""`, a docstring)
/// opens, continues or closes: the string's text becomes a comment, and the line that opens it
/// keeps its code with the string closed there. `None` for any other line.
pub(in crate::import::abop) fn python_string_line<'a>(
    raw: &str,
    in_string: &mut Option<&'a str>,
) -> Option<Line> {
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

/// L-Py's literal values in a predecessor (`D(20, k)`): each becomes a parameter `v_litK`, with
/// the condition `v_litK == 20`. Returns the pattern so rewritten and the conditions.
pub(in crate::import::abop) fn literal_parameters(pattern: &str) -> (String, Vec<String>) {
    let mut out = String::new();
    let mut conditions = Vec::new();
    let mut rest = pattern;
    while let Some(open) = rest.find('(') {
        out.push_str(&rest[..=open]);
        let chars: Vec<char> = rest[open..].chars().collect();
        let Some(close) = PARENTHESES.closing_char(&chars, 0) else {
            break;
        };
        let inner: String = chars[1..close].iter().collect();
        let params: Vec<String> = split_top(&inner, ',')
            .into_iter()
            .map(|p| match p.trim().parse::<f64>() {
                Ok(v) if v.is_finite() => {
                    let name = format!("v_lit{}", conditions.len() + 1);
                    conditions.push(format!("{name} == {}", crate::import::number(v)));
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

/// `A(t) :` -> `Some("A(t)")` when the line is a Python production's header.
pub(in crate::import::abop) fn python_production_header(code: &str) -> Option<&str> {
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
pub(in crate::import::abop) fn inline_produce(code: &str) -> Option<(&str, &str)> {
    let i = top_level(code, ":")?;
    let successor = produce(code[i + 1..].trim())?;
    Some((code[..i].trim(), successor))
}

/// The successor of a `produce` statement.
pub(in crate::import::abop) fn produce(code: &str) -> Option<&str> {
    let rest = code.strip_prefix("produce")?;
    (rest.is_empty() || rest.starts_with(char::is_whitespace)).then(|| rest.trim())
}

impl Importer {
    /// An L-Py line that is no keyword and no production with an arrow: a production with a
    /// Python body (the lines from `i` to `block_end`), a one-line `pattern : produce …`, or other
    /// Python. Returns the index of the next line to read.
    pub(in crate::import::abop) fn python_statement(
        &mut self,
        line: &Line,
        all: &[Line],
        i: usize,
        block_end: usize,
    ) -> usize {
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

    /// L-Py's Python outside productions: `NAME = number expression` becomes a `#define`; other
    /// statements are reported (a block with its indented lines). Returns where to go on.
    pub(in crate::import::abop) fn python(
        &mut self,
        line: &Line,
        block: &[Line],
        block_end: usize,
        next: usize,
    ) -> usize {
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
            let flag = self.lpy.flag_steps.iter().find(|(f, _)| f == name).cloned();
            if let (true, Some((_, step))) = (assignment, flag) {
                let set = self
                    .lpy
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
            if assignment && is_time_step(name, value) {
                // L-Py's continuous-growth idiom: `dt` is the time a step covers.
                let written = DirectiveKind::Dt.written();
                self.out.line(format!("{written} {}", value.trim()), line.n);
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
        if imports_only_numbers(code) {
            // The names `math` and `random` bring are translated where they are used (and one
            // that is not gets its note there): importing them loses nothing.
            return next;
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
    pub(in crate::import::abop) fn helper(&mut self, code: &str, block: &[Line], n: usize) -> bool {
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
                self.lpy.helpers.push((name.clone(), params, e));
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
    pub(in crate::import::abop) fn tuple_assignment(&mut self, code: &str, n: usize) -> bool {
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

    /// The L-Py module name at `chars[start]`: the longest declared or predefined long name
    /// there, another predefined L-Py word before `(` (declared now, and reported once), or one
    /// letter. Returns it and the index after it.
    pub(in crate::import::abop) fn lpy_name(
        &mut self,
        chars: &[char],
        start: usize,
        n: usize,
    ) -> (String, usize) {
        // The word at `start`, the spaces after it and one more character: all that is read
        // here (the whole rest of a derived axiom, copied for each module, was quadratic).
        // A word longer than every name it could be is read letter by letter (L-Py's own
        // reading of `ABAB…`): it is never scanned further, or a derived axiom of a million
        // one-letter modules would be read in time growing with the square of its length.
        let longest = self
            .declared
            .iter()
            .map(String::len)
            .chain(LPY_NAMES.iter().map(|(long, _)| long.len()))
            .chain(LPY_PREDEFINED.iter().map(|name| name.len()))
            .max()
            .unwrap_or(1);
        let Some(word_end) = chars[start..]
            .iter()
            .take(longest + 1)
            .position(|c| !(c.is_ascii_alphanumeric() || *c == '_'))
            .map(|k| start + k)
            .or_else(|| (start + longest + 1 > chars.len()).then_some(chars.len()))
        else {
            return (chars[start].to_string(), start + 1);
        };
        let spaces_end = chars[word_end..]
            .iter()
            .position(|c| !c.is_whitespace())
            .map_or(chars.len(), |k| word_end + k);
        let rest: String = chars[start..(spaces_end + 1).min(chars.len())]
            .iter()
            .collect();
        let long = self
            .declared
            .iter()
            .map(String::as_str)
            .chain(LPY_NAMES.iter().map(|(long, _)| *long))
            .filter(|d| {
                rest.starts_with(d)
                    && !rest[d.len()..].starts_with(|c: char| c.is_ascii_alphanumeric())
            })
            .max_by_key(|d| d.len())
            .map(str::to_string);
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
                if !self.lpy.unknown_names.contains(&word) {
                    self.lpy.unknown_names.push(word.clone());
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
}

/// `dt = 0.1`: L-Py's time step, a number above 0, which becomes `#dt` (the value `dt` reads it).
fn is_time_step(name: &str, value: &str) -> bool {
    let is_dt = crate::vocabulary::value_named(name)
        .is_some_and(|v| v.value == crate::vocabulary::Value::Dt);
    is_dt && crate::number::parse_f64(value.trim()).is_some_and(|v| v.is_finite() && v > 0.0)
}

/// True for `import math`, `import random`, `from math import …` and `from random import …`:
/// Python's modules of numbers, whose functions the expression translator knows by name.
fn imports_only_numbers(code: &str) -> bool {
    const NUMBERS: [&str; 2] = ["math", "random"];
    let words: Vec<&str> = code.split_whitespace().collect();
    match words.as_slice() {
        ["from", module, "import", ..] => NUMBERS.contains(module),
        ["import", rest @ ..] if !rest.is_empty() => rest
            .join(" ")
            .split(',')
            .all(|m| NUMBERS.contains(&m.trim())),
        _ => false,
    }
}
