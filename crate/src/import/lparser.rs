//! Lparser `.ls` (Laurens Lapré's L-System Parser/Mutator) -> Meristem.
//!
//! Two file formats: the positional one of Lparser 1.x-4.x (recursion depth, basic angle and
//! thickness on the first three lines, then the axiom, then rules `X=…` up to a line starting
//! with `@`; `#` starts a comment) and the keyword one of Lparser 2.x (`recursion`, `angle`,
//! `thickness`, `min_thickness`, `color`, `axiom`, `rule X = …`, …). Every meaning below is taken
//! from the two sources found: Lparser 2.1's `L_init`/`L_draw` (`Lparser2.c` in jvail/L-System)
//! and the port of the positional-format Lparser in K-3D (`modules/lsystem/l_parser.cpp`).
//!
//! Lparser rewrites characters; its turtle keeps a current length, angle and thickness that
//! `' " ; : ! ?` multiply. Meristem's turtle has no such state, so the importer threads it
//! through parameters: every symbol with a rule carries the length, angle and thickness in force
//! where it stands (only those its expansion reads), and every drawing command gets explicit
//! values — which turns the file into the parametric L-system it implies (ABOP p. 56 style).
//! A symbol whose expansion changes the state for the symbols after it (`S='(.8)!(.9)`,
//! `F='(1.3)F'(.77)`) multiplies their values by the net factor of its expansion after the steps
//! left, `MaxIt - NumIt`; the factor is exact when it follows a fixed law (constant after some
//! steps, or geometric), and reported otherwise. The derived string has one module per Lparser
//! symbol that means something (scaling commands are absorbed into parameters, inert characters
//! dropped); a `homomorphism:` section turns the symbols Meristem cannot draw directly into
//! turtle commands (widths, `Z`, `~`, `t`).

use super::{number, Import, Output};
use crate::vocabulary::{DirectiveKind, KeywordKind};
use std::collections::HashMap;

/// Lparser 2.1's defaults (`static` initialisers of `Lparser2.c`).
const DEFAULT_RECURSION: f64 = 1.0;
const DEFAULT_ANGLE: f64 = 45.0;
const DEFAULT_THICKNESS: f64 = 100.0;
/// `~` without a value turns by up to 6 *radians* (`r = (r32) 6.0`, no degree conversion).
const TILDE_DEFAULT_DEGREES: f64 = 6.0 * 180.0 / std::f64::consts::PI;
/// `t` without a value: `tr = 0.2`.
const TROPISM_DEFAULT: f64 = 0.2;
/// Meristem width units per model unit of Lparser diameter (length × thickness) when the plant
/// cannot be measured (see [`measure_width_scale`]).
const WIDTH_SCALE: f64 = 10.0;
/// The largest string, and the most steps, the importer derives to measure the plant.
const MEASURE_MODULES: usize = 1_000_000;
const MEASURE_STEPS: u32 = 64;
/// The positional format's Lparser (4.x, as its K-3D and L-Neuron ports show) draws `F` 100
/// units long (`dis = 100.0`), so its explicit lengths `F(20)` are in those units; Meristem's
/// translation takes `F` as 1.
const POSITIONAL_LENGTH_UNIT: f64 = 0.01;
/// Commands that read a `(value)` right after them (`next == '('` in `L_draw`).
const VALUE_COMMANDS: &str = "+-~t&^<>!?:;'\"ZFfgzc";
/// Characters that keep themselves (Lparser's default rules `+=+` … `_=_`); any other character
/// without a rule becomes `_` after one step, and nothing draws it.
const SELF_RULES: &str = "+-&^<>%|!?:;'\"c[]{}FftgZz*$~.0123456789()_";
/// Structural characters whose rules the importer ignores.
const NOT_REWRITABLE: &str = "[](){}.";
/// Steps for which the net scaling of each expansion is computed to find its law.
const NET_SAMPLES: usize = 40;

const L: usize = 0;
const A: usize = 1;
const T: usize = 2;
const PARAM_NAMES: [&str; 3] = ["len", "ang", "wid"];

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    Positional,
    Keyword,
}

/// One symbol of an Lparser string: a character and the value in `(…)` after a command.
#[derive(Clone, Debug, PartialEq)]
struct Tok {
    ch: char,
    value: Option<f64>,
    /// The characters between the parentheses, as written.
    written: String,
}

#[derive(Clone, Debug)]
struct Rule {
    pred: char,
    succ: Vec<Tok>,
    line: usize,
    comment: String,
}

#[derive(Debug)]
struct LsFile {
    format: Format,
    recursion: f64,
    recursion_line: usize,
    angle: f64,
    thickness: f64,
    thickness_line: usize,
    min_thickness: f64,
    axiom: Vec<Tok>,
    axiom_line: usize,
    axiom_comment: String,
    rules: Vec<Rule>,
    colors: Vec<(usize, [f64; 3])>,
    header: Vec<String>,
}

pub(super) fn import(text: &str) -> Import {
    let mut out = Output::default();
    let file = parse(text, &mut out);
    if file.axiom_line == 0 {
        out.note(0, "no axiom found");
        return out.finish();
    }
    Translator::new(&file, &mut out).write();
    out.finish()
}

/// Whether the file uses the keyword format: its first content line starts with a keyword.
fn format_of(text: &str) -> Format {
    for line in text.lines() {
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        let word = t
            .split(|c: char| c.is_whitespace() || c == '#')
            .next()
            .unwrap_or("")
            .to_ascii_lowercase();
        return if KEYWORDS.contains(&word.as_str()) {
            Format::Keyword
        } else {
            Format::Positional
        };
    }
    Format::Positional
}

const KEYWORDS: &[&str] = &[
    "recursion",
    "mutation",
    "angle",
    "thickness",
    "min_thickness",
    "switch_yz",
    "trace",
    "poly_limit",
    "no_wait",
    "shape",
    "color",
    "axiom",
    "rule",
];

fn parse(text: &str, out: &mut Output) -> LsFile {
    let mut file = LsFile {
        format: format_of(text),
        recursion: DEFAULT_RECURSION,
        recursion_line: 0,
        angle: DEFAULT_ANGLE,
        thickness: DEFAULT_THICKNESS,
        thickness_line: 0,
        min_thickness: 0.0,
        axiom: Vec::new(),
        axiom_line: 0,
        axiom_comment: String::new(),
        rules: Vec::new(),
        colors: Vec::new(),
        header: Vec::new(),
    };
    match file.format {
        Format::Positional => parse_positional(text, &mut file, out),
        Format::Keyword => parse_keywords(text, &mut file, out),
    }
    file
}

/// Splits a line at its first `#`: (code, comment).
fn split_comment(line: &str) -> (&str, &str) {
    match line.find('#') {
        Some(i) => (&line[..i], line[i + 1..].trim()),
        None => (line, ""),
    }
}

fn without_spaces(s: &str) -> String {
    s.chars().filter(|c| !c.is_whitespace()).collect()
}

/// A comment worth carrying over: it says something (not a row of dashes).
fn keep_comment(comment: &str) -> Option<String> {
    let c = comment.trim().trim_matches('-').trim();
    (c.chars().any(char::is_alphanumeric)).then(|| comment.trim().to_string())
}

fn parse_positional(text: &str, file: &mut LsFile, out: &mut Output) {
    let mut stage = 0;
    let mut ended = false;
    let mut last_line = 0;
    for (index, raw) in text.lines().enumerate() {
        let n = index + 1;
        last_line = n;
        let trimmed = raw.trim();
        if trimmed.is_empty() {
            continue;
        }
        if let Some(comment) = trimmed.strip_prefix('#') {
            if let Some(c) = keep_comment(comment) {
                file.header.push(c);
            }
            continue;
        }
        let (code, comment) = split_comment(trimmed);
        let code = without_spaces(code);
        if code.is_empty() {
            continue;
        }
        let number_or = |what: &str, default: f64, out: &mut Output| match leading_float(&code) {
            Some(v) => v,
            None => {
                out.note(
                    n,
                    format!(
                        "expected the {what} (a number) on this line; Lparser's default {} is used",
                        number(default)
                    ),
                );
                default
            }
        };
        match stage {
            0 => {
                file.recursion = number_or("recursion depth", DEFAULT_RECURSION, out);
                file.recursion_line = n;
            }
            1 => file.angle = number_or("basic angle", DEFAULT_ANGLE, out),
            2 => {
                file.thickness = number_or("thickness", DEFAULT_THICKNESS, out);
                file.thickness_line = n;
            }
            3 => {
                file.axiom = tokenize(&code, n, out);
                file.axiom_line = n;
                file.axiom_comment = comment.to_string();
            }
            _ => {
                if code.starts_with('@') {
                    ended = true;
                    break;
                }
                add_rule(file, &code, n, comment, out);
            }
        }
        stage += 1;
    }
    if !ended && stage >= 4 {
        out.note(
            last_line,
            "no '@' end mark: Lparser reads rules up to a line starting with '@'; every rule line was read",
        );
    }
}

/// Reads the keyword format of Lparser 2 into `file`, line by line.
fn parse_keywords(text: &str, file: &mut LsFile, out: &mut Output) {
    let mut noted: Vec<String> = Vec::new();
    for (index, raw) in text.lines().enumerate() {
        let n = index + 1;
        let trimmed = raw.trim();
        if trimmed.is_empty() {
            continue;
        }
        if let Some(comment) = trimmed.strip_prefix('#') {
            if let Some(c) = keep_comment(comment) {
                file.header.push(c);
            }
            continue;
        }
        let (code, comment) = split_comment(trimmed);
        let code = code.trim();
        let (keyword, command) = match code.find(char::is_whitespace) {
            Some(i) => (&code[..i], code[i..].trim()),
            None => (code, ""),
        };
        let keyword = keyword.to_ascii_lowercase();
        if let Some(message) = untranslated_keyword(&keyword) {
            if !noted.contains(&keyword) {
                noted.push(keyword);
                out.note(n, message);
            }
            continue;
        }
        keyword_line(file, &keyword, command, comment, n, out);
    }
}

/// Why a keyword of Lparser's program or output, not of the plant, is not translated (noted
/// once a file); `None` for the others.
fn untranslated_keyword(keyword: &str) -> Option<String> {
    Some(match keyword {
        "mutation" => "'mutation': Lparser edits the rules at random before deriving (insert, replace, append, swap directions and sizes); Meristem derives the rules as written".into(),
        "switch_yz" => "'switch_yz' only swaps the y and z axes of Lparser's VRML output; Meristem always grows the axiom's heading up the screen".into(),
        "shape" => "'shape' chooses blocks or attached cylinders in Lparser's output; Meristem draws every segment as a tube".into(),
        "poly_limit" => "'poly_limit' stops Lparser's drawing after that many polygons; not translated (Meristem limits the string with #max_modules)".into(),
        "trace" | "no_wait" => format!("'{keyword}' is an option of the Lparser program, not of the plant; ignored"),
        _ => return None,
    })
}

/// One line `keyword command # comment` of the keyword format (line `n`) read into `file`.
fn keyword_line(
    file: &mut LsFile,
    keyword: &str,
    command: &str,
    comment: &str,
    n: usize,
    out: &mut Output,
) {
    let float = |out: &mut Output, default: f64| match leading_float(command) {
        Some(v) => v,
        None => {
            out.note(
                n,
                format!(
                    "'{keyword}' needs a number; Lparser's default {} is used",
                    number(default)
                ),
            );
            default
        }
    };
    match keyword {
        "recursion" => {
            // `sscanf(command, "%d", &lev)`: a whole number.
            file.recursion =
                leading_float(command).map_or_else(|| float(out, DEFAULT_RECURSION), |v| v.trunc());
            file.recursion_line = n;
        }
        "angle" => file.angle = float(out, DEFAULT_ANGLE),
        "thickness" => {
            file.thickness = float(out, DEFAULT_THICKNESS);
            file.thickness_line = n;
        }
        "min_thickness" => file.min_thickness = float(out, 0.0),
        "color" => {
            let numbers: Vec<f64> = command
                .split_whitespace()
                .filter_map(leading_float)
                .collect();
            match numbers.as_slice() {
                [i, r, g, b, ..] if *i >= 0.0 && *i < 100.0 => {
                    file.colors.push((*i as usize, [*r / 255.0, *g / 255.0, *b / 255.0]));
                }
                _ => out.note(
                    n,
                    "'color' needs an index from 0 to 99 and red, green, blue from 0 to 255; ignored",
                ),
            }
        }
        "axiom" => {
            file.axiom = tokenize(&without_spaces(command), n, out);
            file.axiom_line = n;
            file.axiom_comment = comment.to_string();
        }
        "rule" => add_rule(file, &without_spaces(command), n, comment, out),
        _ => out.note(
            n,
            format!("unknown keyword '{keyword}' (Lparser stops with an error here); the line is skipped"),
        ),
    }
}

/// Adds a rule `X=…`: the predecessor is the first character, the successor everything after
/// the first `=`.
fn add_rule(file: &mut LsFile, code: &str, n: usize, comment: &str, out: &mut Output) {
    let Some((left, right)) = code.split_once('=') else {
        out.note(n, format!("'{code}' is not a rule 'X=…'; skipped"));
        return;
    };
    let Some(pred) = left.chars().next() else {
        out.note(n, "a rule without a predecessor; skipped");
        return;
    };
    if left.chars().count() > 1 {
        out.note(
            n,
            format!("only the first character of '{left}' names the rule, as in Lparser: the rule is for '{pred}'"),
        );
    }
    file.rules.push(Rule {
        pred,
        succ: tokenize(right, n, out),
        line: n,
        comment: comment.to_string(),
    });
}

/// `sscanf("%f")`: the number at the start of `s` (after spaces), if any.
fn leading_float(s: &str) -> Option<f64> {
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

/// Splits an Lparser string into symbols: a command of [`VALUE_COMMANDS`] followed by `(` takes
/// everything up to `)` as its value (`Get_value`); any other character is a symbol of its own.
fn tokenize(code: &str, n: usize, out: &mut Output) -> Vec<Tok> {
    let chars: Vec<char> = code.chars().collect();
    let mut toks = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        if VALUE_COMMANDS.contains(ch) && chars.get(i + 1) == Some(&'(') {
            let close = chars[i + 2..].iter().position(|&c| c == ')');
            let end = close.map_or(chars.len(), |j| i + 2 + j);
            let inner: String = chars[i + 2..end].iter().collect();
            if close.is_none() {
                out.note(n, format!("'{ch}(' is never closed by ')'"));
            }
            let value = match inner.trim().parse::<f64>() {
                Ok(v) if v.is_finite() => v,
                _ => {
                    let v = leading_float(&inner).unwrap_or(0.0);
                    out.note(
                        n,
                        format!(
                            "'{ch}({inner})': not a number; Lparser reads {} (sscanf)",
                            number(v)
                        ),
                    );
                    v
                }
            };
            toks.push(Tok {
                ch,
                value: Some(value),
                written: inner,
            });
            i = end + 1;
        } else {
            toks.push(Tok {
                ch,
                value: None,
                written: String::new(),
            });
            i += 1;
        }
    }
    toks
}

/// The component a scaling command multiplies, and by how much.
fn factor(tok: &Tok) -> Option<(usize, f64)> {
    let (comp, default) = match tok.ch {
        '\'' => (L, 0.9),
        '"' => (L, 1.0 / 0.9),
        ':' => (A, 0.9),
        ';' => (A, 1.0 / 0.9),
        '!' => (T, 0.7),
        '?' => (T, 1.0 / 0.7),
        _ => return None,
    };
    Some((comp, tok.value.unwrap_or(default)))
}

/// The state components a command reads when it draws or turns.
fn reads(ch: char, has_value: bool) -> [bool; 3] {
    match ch {
        'F' | 'Z' => [!has_value, false, true],
        'f' | 'z' | 'g' => [!has_value, false, false],
        '+' | '-' | '&' | '^' | '<' | '>' => [false, !has_value, false],
        _ => [false; 3],
    }
}

/// The net scaling of an expansion as a function of the steps left, r.
#[derive(Clone, Debug, PartialEq)]
enum Net {
    Neutral,
    /// `prefix[r]` for r < prefix.len(), then `base * ratio^(r - prefix.len())`.
    Law {
        prefix: Vec<f64>,
        base: f64,
        ratio: f64,
    },
    Irregular,
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1e-300)
}

fn classify(s: &[f64]) -> Net {
    if s.iter().all(|&v| close(v, 1.0)) {
        return Net::Neutral;
    }
    if s.iter().any(|v| !v.is_finite()) {
        return Net::Irregular;
    }
    for k in 0..s.len().saturating_sub(8) {
        let ratio = if s[k] == 0.0 { 1.0 } else { s[k + 1] / s[k] };
        let fits = (k..s.len()).all(|r| close(s[r], s[k] * ratio.powi((r - k) as i32)));
        if fits {
            return Net::Law {
                prefix: s[..k].to_vec(),
                base: s[k],
                ratio: if close(ratio, 1.0) { 1.0 } else { ratio },
            };
        }
    }
    Net::Irregular
}

/// The Meristem expression of a net factor for a symbol written at step `NumIt` (rewritten
/// `MaxIt - NumIt` more times).
fn net_expr(net: &Net) -> Option<String> {
    let Net::Law {
        prefix,
        base,
        ratio,
    } = net
    else {
        return None;
    };
    let k = prefix.len();
    let left = if k == 0 {
        "(MaxIt-NumIt)".to_string()
    } else {
        format!("(MaxIt-NumIt-{k})")
    };
    let tail = if *ratio == 1.0 {
        number(*base)
    } else if close(*base, 1.0) {
        format!("{}^{left}", number(*ratio))
    } else {
        format!("{}*{}^{left}", number(*base), number(*ratio))
    };
    Some(match k {
        0 => tail,
        1 => format!("(NumIt<MaxIt?{tail}:{})", number(prefix[0])),
        _ => {
            let mut chain = String::from("(");
            for (r, v) in prefix.iter().enumerate() {
                chain.push_str(&format!("MaxIt-NumIt<{}?{}:", r + 1, number(*v)));
            }
            chain.push_str(&tail);
            chain.push(')');
            chain
        }
    })
}

/// A product `coef × factors…`, for parameter expressions.
#[derive(Clone, Debug)]
struct Prod {
    coef: f64,
    factors: Vec<String>,
}

impl Prod {
    fn constant(v: f64) -> Self {
        Prod {
            coef: v,
            factors: Vec::new(),
        }
    }
    fn name(name: &str) -> Self {
        Prod {
            coef: 1.0,
            factors: vec![name.to_string()],
        }
    }
    fn times(&self, v: f64) -> Self {
        Prod {
            coef: self.coef * v,
            factors: self.factors.clone(),
        }
    }
    fn times_expr(&mut self, e: String) {
        self.factors.push(e);
    }
    fn is_constant(&self, v: f64) -> bool {
        self.factors.is_empty() && close(self.coef, v)
    }
    fn render(&self) -> String {
        if self.factors.is_empty() || self.coef == 0.0 {
            return number(self.coef);
        }
        let mut counted: Vec<(&String, usize)> = Vec::new();
        for f in &self.factors {
            match counted.iter_mut().find(|(g, _)| *g == f) {
                Some((_, n)) => *n += 1,
                None => counted.push((f, 1)),
            }
        }
        let mut s = counted
            .iter()
            .map(|(f, n)| match n {
                1 => (*f).clone(),
                // `^` is right-associative: (x^y)^n needs its parentheses.
                n => format!("({f})^{n}"),
            })
            .collect::<Vec<_>>()
            .join("*");
        if !close(self.coef, 1.0) {
            s.push('*');
            s.push_str(&number(self.coef));
        }
        s
    }
}

/// What the homomorphism section must define.
#[derive(Default)]
struct Uses {
    forward: bool,
    half: bool,
    tilde: bool,
    tropism: bool,
}

struct Translator<'f, 'o> {
    file: &'f LsFile,
    out: &'o mut Output,
    /// The rule of each rewritten character (the first one, as Lparser's rule table keeps).
    rule_of: HashMap<char, usize>,
    used: [bool; 3],
    start: [f64; 3],
    needs: HashMap<char, [bool; 3]>,
    nets: HashMap<char, [Net; 3]>,
    uses: Uses,
    noted: Vec<String>,
    /// Where the `#define width_scale` line is, once written.
    width_line: Option<usize>,
}

impl<'f, 'o> Translator<'f, 'o> {
    fn new(file: &'f LsFile, out: &'o mut Output) -> Self {
        let mut rule_of = HashMap::new();
        for (i, rule) in file.rules.iter().enumerate() {
            if NOT_REWRITABLE.contains(rule.pred) {
                out.note(
                    rule.line,
                    format!(
                        "a rule for '{}' would rewrite the string's structure; not translated",
                        rule.pred
                    ),
                );
                continue;
            }
            if let Some(&first) = rule_of.get(&rule.pred) {
                let first: &Rule = &file.rules[first];
                out.note(
                    rule.line,
                    format!(
                        "a second rule for '{}': Lparser uses the first one (line {}); this one is skipped",
                        rule.pred, first.line
                    ),
                );
                continue;
            }
            rule_of.insert(rule.pred, i);
        }
        // Lparser rewrites every character, the digits of a value too.
        let digits: Vec<char> = rule_of
            .keys()
            .copied()
            .filter(char::is_ascii_digit)
            .collect();
        let strings = std::iter::once((file.axiom_line, &file.axiom))
            .chain(file.rules.iter().map(|r| (r.line, &r.succ)));
        for (line, toks) in strings {
            if let Some(t) = toks
                .iter()
                .find(|t| t.written.chars().any(|c| digits.contains(&c)))
            {
                out.note(
                    line,
                    format!(
                        "'{}({})': Lparser's rules for digits rewrite the digits of values too; Meristem keeps the value",
                        t.ch, t.written
                    ),
                );
            }
        }
        let mut used = [false; 3];
        let all = file
            .rules
            .iter()
            .flat_map(|r| r.succ.iter())
            .chain(file.axiom.iter());
        for tok in all {
            if let Some((comp, _)) = factor(tok) {
                used[comp] = true;
            }
        }
        let mut t = Translator {
            file,
            out,
            rule_of,
            used,
            start: [1.0, file.angle, file.thickness / 100.0],
            needs: HashMap::new(),
            nets: HashMap::new(),
            uses: Uses::default(),
            noted: Vec::new(),
            width_line: None,
        };
        t.compute_needs();
        t.compute_nets();
        t
    }

    fn rule(&self, ch: char) -> Option<&'f Rule> {
        let file: &'f LsFile = self.file;
        self.rule_of.get(&ch).map(|&i| &file.rules[i])
    }

    fn ruled(&self, ch: char) -> bool {
        self.rule_of.contains_key(&ch)
    }

    fn mask(&self, r: [bool; 3]) -> [bool; 3] {
        [
            r[0] && self.used[0],
            r[1] && self.used[1],
            r[2] && self.used[2],
        ]
    }

    /// The components each rewritten symbol must carry: those its expansion reads (fixpoint).
    fn compute_needs(&mut self) {
        let preds: Vec<char> = self.rule_of.keys().copied().collect();
        for &p in &preds {
            // Left in the final string, a rewritten command acts as that command.
            let own = self.mask(reads(p, false));
            self.needs.insert(p, own);
        }
        loop {
            let mut changed = false;
            for &p in &preds {
                let Some(rule) = self.rule(p) else { continue };
                let mut need = self.needs[&p];
                for tok in &rule.succ {
                    let r = match self.needs.get(&tok.ch) {
                        Some(n) => *n,
                        None => self.mask(reads(tok.ch, tok.value.is_some())),
                    };
                    for c in 0..3 {
                        need[c] |= r[c];
                    }
                }
                if need != self.needs[&p] {
                    self.needs.insert(p, need);
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
    }

    /// The net scaling of each rewritten symbol's expansion, per component, as a law of the
    /// steps left (computed for [`NET_SAMPLES`] steps, then classified).
    fn compute_nets(&mut self) {
        let preds: Vec<char> = self.rule_of.keys().copied().collect();
        let own = |p: char| -> [f64; 3] {
            let mut v = [1.0; 3];
            if let Some((c, f)) = factor(&Tok {
                ch: p,
                value: None,
                written: String::new(),
            }) {
                v[c] = f;
            }
            v
        };
        let mut samples: HashMap<char, Vec<[f64; 3]>> =
            preds.iter().map(|&p| (p, vec![own(p)])).collect();
        for r in 1..NET_SAMPLES {
            let mut next = HashMap::new();
            for &p in &preds {
                let mut v = [1.0; 3];
                let mut depth = 0i32;
                for tok in &self.rule(p).map_or(&[][..], |rule| &rule.succ[..]).to_vec() {
                    match tok.ch {
                        '[' => depth += 1,
                        ']' => depth = (depth - 1).max(0),
                        _ if depth > 0 => {}
                        ch if samples.contains_key(&ch) => {
                            let s = samples[&ch][r - 1];
                            for c in 0..3 {
                                v[c] *= s[c];
                            }
                        }
                        _ => {
                            if let Some((c, f)) = factor(tok) {
                                v[c] *= f;
                            }
                        }
                    }
                }
                next.insert(p, v);
            }
            for (p, v) in next {
                if let Some(s) = samples.get_mut(&p) {
                    s.push(v);
                }
            }
        }
        for &p in &preds {
            let s = &samples[&p];
            let nets = [0, 1, 2].map(|c| {
                if !self.used[c] {
                    return Net::Neutral;
                }
                let series: Vec<f64> = s.iter().map(|v| v[c]).collect();
                classify(&series)
            });
            self.nets.insert(p, nets);
        }
    }

    /// The Meristem name of a rewritten symbol.
    fn name_of(ch: char) -> String {
        if ch.is_ascii_alphabetic() {
            if "FfZzgctG".contains(ch) {
                format!("{ch}_r")
            } else {
                ch.to_string()
            }
        } else if ch.is_ascii_digit() {
            format!("D_{ch}")
        } else {
            format!("Q_{}", ch as u32)
        }
    }

    /// True when something after a symbol, before the end of its branch, reads the turtle's
    /// state (inert characters do not).
    fn has_followers(&self, rest: &[Tok]) -> bool {
        for t in rest {
            if t.ch == ']' {
                return false;
            }
            let command = VALUE_COMMANDS.contains(t.ch) || "[{}.|%$".contains(t.ch);
            if self.ruled(t.ch) || command {
                return true;
            }
        }
        false
    }

    fn note_once(&mut self, key: &str, line: usize, message: String) {
        if !self.noted.iter().any(|k| k == key) {
            self.noted.push(key.to_string());
            self.out.note(line, message);
        }
    }

    /// A rewritten symbol's pattern or occurrence: its name and the components it carries.
    fn module(&self, ch: char, state: &[Prod; 3]) -> String {
        let need = self.needs.get(&ch).copied().unwrap_or([false; 3]);
        let params: Vec<String> = (0..3)
            .filter(|&c| need[c])
            .map(|c| state[c].render())
            .collect();
        let name = Self::name_of(ch);
        if params.is_empty() {
            name
        } else {
            format!("{name}({})", params.join(","))
        }
    }

    /// Translates an Lparser string whose state starts as `state`.
    fn string(&mut self, toks: &[Tok], mut state: [Prod; 3], line: usize) -> String {
        let mut s = String::new();
        let mut stack: Vec<[Prod; 3]> = Vec::new();
        let mut polygon = 0usize;
        for (index, tok) in toks.iter().enumerate() {
            if self.ruled(tok.ch) {
                if let Some(v) = tok.value {
                    self.note_once(
                        &format!("value {line} {}", tok.ch),
                        line,
                        format!(
                            "'{}({})': '{}' has a rule, and Lparser keeps '({})' as plain characters after its expansion; the value is dropped",
                            tok.ch,
                            number(v),
                            tok.ch,
                            number(v)
                        ),
                    );
                }
                s.push_str(&self.module(tok.ch, &state));
                let nets = self.nets.get(&tok.ch).cloned();
                let irregular = nets.iter().flatten().position(|n| *n == Net::Irregular);
                if let Some(c) = irregular.filter(|_| self.has_followers(&toks[index + 1..])) {
                    let what = ["lengths", "angles", "thicknesses"][c];
                    let p = tok.ch;
                    let rule_line = self.rule(p).map_or(line, |r| r.line);
                    self.note_once(
                        &format!("irregular {p}"),
                        rule_line,
                        format!(
                            "the expansion of '{p}' scales the {what} of the symbols after it by a factor that follows no simple law of the step; the translation does not carry it (symbols after '{p}', as on line {line}, keep the {what} before it)"
                        ),
                    );
                }
                for (c, net) in nets.iter().flatten().enumerate() {
                    if let Some(e) = net_expr(net) {
                        state[c].times_expr(e);
                    }
                }
                continue;
            }
            match tok.ch {
                '[' => {
                    stack.push(state.clone());
                    s.push('[');
                }
                ']' => {
                    if let Some(saved) = stack.pop() {
                        state = saved;
                    }
                    s.push(']');
                }
                '{' => {
                    polygon += 1;
                    s.push('{');
                }
                '}' => {
                    polygon = polygon.saturating_sub(1);
                    s.push('}');
                }
                'F' | 'Z' if polygon > 0 => {
                    self.note_once(
                        &format!("polygon {line}"),
                        line,
                        format!(
                            "'{}' inside '{{…}}': Lparser draws a segment there and records no vertex; Meristem records a vertex and draws nothing",
                            tok.ch
                        ),
                    );
                    s.push_str(&self.terminal(tok, &state, line));
                }
                _ => {
                    if let Some((c, f)) = factor(tok) {
                        state[c] = state[c].times(f);
                    } else {
                        s.push_str(&self.terminal(tok, &state, line));
                    }
                }
            }
        }
        s
    }

    /// One symbol without a rule (or a rewritten command left in the final string).
    fn terminal(&mut self, tok: &Tok, state: &[Prod; 3], line: usize) -> String {
        let unit = match self.file.format {
            Format::Positional => POSITIONAL_LENGTH_UNIT,
            Format::Keyword => 1.0,
        };
        let length = |half: bool| match tok.value {
            Some(v) => Prod::constant(v * unit),
            None if half => state[L].times(0.5),
            None => state[L].clone(),
        };
        let turn = |m: char, this: &Self| match tok.value {
            Some(v) => format!("{m}({})", number(v)),
            None if !this.used[A] => m.to_string(),
            None => format!("{m}({})", state[A].render()),
        };
        match tok.ch {
            'F' | 'Z' => {
                if tok.ch == 'F' {
                    self.uses.forward = true;
                } else {
                    self.uses.half = true;
                }
                format!(
                    "{}({},{})",
                    tok.ch,
                    length(tok.ch == 'Z').render(),
                    state[T].render()
                )
            }
            'f' | 'z' | 'g' => {
                let len = length(tok.ch == 'z');
                let m = if tok.ch == 'g' { 'g' } else { 'f' };
                if len.is_constant(1.0) && tok.value.is_none() {
                    m.to_string()
                } else {
                    format!("{m}({})", len.render())
                }
            }
            '+' | '-' | '&' | '^' => turn(tok.ch, self),
            '<' => turn('\\', self),
            '>' => turn('/', self),
            '|' => "|".into(),
            '.' => ".".into(),
            '%' => "/(180)".into(),
            '$' => {
                self.note_once(
                    "$",
                    line,
                    "'$' is translated as Meristem's '$' (roll so that the left vector is horizontal); after Lparser's '$' its frame is mirrored and its left and up vectors are not unit vectors, so its later '+' and '-' turn the other way and by distorted angles unless the heading is horizontal".into(),
                );
                "$".into()
            }
            '~' => {
                self.uses.tilde = true;
                let r = match tok.value {
                    Some(v) => v,
                    None => {
                        self.note_once(
                            "~",
                            line,
                            format!(
                                "'~' without a value: Lparser's source turns by up to 6 radians ({}°, surely meant as 6°) about each axis; translated as written, '~({})'",
                                number(TILDE_DEFAULT_DEGREES),
                                number(TILDE_DEFAULT_DEGREES)
                            ),
                        );
                        TILDE_DEFAULT_DEGREES
                    }
                };
                format!("~({})", number(r))
            }
            't' => {
                self.uses.tropism = true;
                self.note_once(
                    "t",
                    line,
                    "'t' (gravity) bends the heading by tr·sin(angle to the vertical) as Lparser does, but towards the ground (Meristem's tropism, @Ts); Lparser bends about the turtle's left vector, which points that way only after '$'".into(),
                );
                format!("t({})", number(tok.value.unwrap_or(TROPISM_DEFAULT)))
            }
            'c' => match tok.value {
                Some(v) => format!(";({})", number(v.trunc())),
                None => ";".into(),
            },
            ch if ch.is_ascii_alphabetic() && !SELF_RULES.contains(ch) => {
                // Any other letter without a rule becomes '_' after one step and never draws.
                String::new()
            }
            ch if !ch.is_ascii() => {
                self.note_once(
                    &format!("char {ch}"),
                    line,
                    format!("'{ch}' is not an Lparser symbol; dropped"),
                );
                String::new()
            }
            _ => String::new(),
        }
    }

    fn params(&self, ch: char) -> [Prod; 3] {
        let need = self.needs.get(&ch).copied().unwrap_or([false; 3]);
        [0, 1, 2].map(|c| {
            if need[c] {
                Prod::name(PARAM_NAMES[c])
            } else {
                Prod::constant(self.start[c])
            }
        })
    }

    /// Writes the translation: the header, the `#width_scale` and palette, the axiom and the
    /// productions, the homomorphism that draws what Meristem's turtle does not, and finally the
    /// width scale measured on the plant.
    fn write(mut self) {
        self.header();
        // The axiom and rules first (they decide what the homomorphism needs).
        let axiom = self.axiom();
        let productions = self.productions();
        let commands = self.command_productions();
        if self.uses.forward || self.uses.half {
            self.width_scale_placeholder();
        }
        self.palette();
        let file = self.file;
        self.out
            .line(format!("axiom: {}", separate(&axiom)), file.axiom_line);
        if !file.axiom_comment.is_empty() {
            self.out.comment(&file.axiom_comment, file.axiom_line);
        }
        for (text, line, comment) in productions {
            match keep_comment(&comment) {
                Some(c) => self
                    .out
                    .line(format!("{text} // {}", super::defuse_comment(&c)), line),
                None => self.out.line(text, line),
            }
        }
        self.homomorphism(commands);
        if let Some(at) = self.width_line {
            self.measure_width(at);
        }
    }

    /// Where the translation comes from, the file's header comments, `#iterations` (a
    /// fractional recursion rounded up, with a note) and `#angle`.
    fn header(&mut self) {
        let file = self.file;
        let format = match file.format {
            Format::Positional => "positional format",
            Format::Keyword => "keyword format of Lparser 2",
        };
        self.out.comment(
            &format!("Imported from Lparser ({format}) by meristem import."),
            0,
        );
        for c in &file.header {
            self.out.comment(c, 0);
        }
        let mut depth = file.recursion.max(0.0);
        if depth.fract() != 0.0 {
            self.out.note(
                file.recursion_line,
                format!(
                    "fractional recursion {}: Lparser grows the last step partly (its lengths, angles and thicknesses scaled by {}); Meristem derives {} whole steps",
                    number(depth),
                    number(depth.fract()),
                    number(depth.ceil())
                ),
            );
            depth = depth.ceil();
        }
        self.out.line(
            format!(
                "{} {}",
                DirectiveKind::Iterations.written(),
                number(depth.min(1e6))
            ),
            file.recursion_line,
        );
        self.out.line(
            format!("{} {}", DirectiveKind::Angle.written(), number(file.angle)),
            0,
        );
    }

    /// The axiom in Meristem's modules, starting with Lparser's first colour.
    fn axiom(&mut self) -> String {
        let file = self.file;
        let start = self.start.map(Prod::constant);
        let axiom = self.string(&file.axiom, start, file.axiom_line);
        if file.axiom.first().map(|t| t.ch) != Some('c') {
            return format!(";(2){axiom}"); // Lparser starts with colour 2
        }
        axiom
    }

    /// Each rule as a production, in the file's order: (text, line, comment).
    fn productions(&mut self) -> Vec<(String, usize, String)> {
        let file = self.file;
        let mut preds: Vec<(usize, char)> = self.rule_of.iter().map(|(&c, &i)| (i, c)).collect();
        preds.sort();
        let mut productions = Vec::new();
        for (i, ch) in preds {
            let rule = &file.rules[i];
            let params = self.params(ch);
            let lhs = self.module(ch, &params);
            let rhs = self.string(&rule.succ, params, rule.line);
            productions.push((production(&lhs, &rhs), rule.line, rule.comment.clone()));
        }
        productions
    }

    /// For each command that has a rule (and so stays a module of its own in the derived
    /// string), the homomorphism production that draws it: (text, line).
    fn command_productions(&mut self) -> Vec<(String, usize)> {
        let file = self.file;
        let mut commands = Vec::new();
        for (ch, i) in self.sorted_rules() {
            let is_command = VALUE_COMMANDS.contains(ch) || "|%$".contains(ch);
            if !is_command {
                continue;
            }
            let params = self.params(ch);
            let lhs = self.module(ch, &params);
            let rhs = self.terminal(
                &Tok {
                    ch,
                    value: None,
                    written: String::new(),
                },
                &params,
                file.rules[i].line,
            );
            commands.push((production(&lhs, &rhs), file.rules[i].line));
        }
        commands
    }

    /// `#define width_scale` with a default value, replaced once the plant is measured
    /// ([`Translator::measure_width`]), and a note on what it means.
    fn width_scale_placeholder(&mut self) {
        let thickness_line = self.file.thickness_line;
        self.out.note(
            thickness_line,
            "thickness: Lparser draws each segment as thick as its length times the thickness, in model units; Meristem's widths are in width units (1/300 of the plant's size), so the translation writes width_scale × length × thickness with width_scale measured on the plant at the file's depth: at other depths the plant's size changes and the widths with it",
        );
        self.width_line = Some(self.out.len());
        self.out.line(
            format!(
                "{} width_scale {}",
                DirectiveKind::Define.written(),
                number(WIDTH_SCALE)
            ),
            thickness_line,
        );
    }

    /// The `homomorphism:` section, when anything needs one: widths, `Z`, `~` and `t` as
    /// Meristem draws them, and the productions of `commands` that have rules.
    fn homomorphism(&mut self, commands: Vec<(String, usize)>) {
        let width = if self.file.min_thickness > 0.0 {
            format!(
                "width_scale*max(x*t,{})",
                number(self.file.min_thickness / 100.0)
            )
        } else {
            "width_scale*x*t".to_string()
        };
        let mut homomorphism = Vec::new();
        if self.uses.forward {
            homomorphism.push(format!("F(x,t) -> !({width})F(x)"));
        }
        if self.uses.half {
            homomorphism.push(format!("Z(x,t) -> !({width})F(x)"));
        }
        if self.uses.tilde {
            homomorphism
                .push("~(r) -> +(uniform(-r,r))&(uniform(-r,r))/(uniform(-r,r))".to_string());
        }
        if self.uses.tropism {
            homomorphism.push("t(e) -> @Ts(e)G(0)@Ts(0)".to_string());
        }
        if homomorphism.is_empty() && commands.is_empty() {
            return;
        }
        self.out.line(KeywordKind::Homomorphism.written(), 0);
        self.out.comment(
            "How Lparser draws what Meristem's turtle does not: widths, Z (half length), ~ (random turn), t (gravity).",
            0,
        );
        for h in homomorphism {
            self.out.line(h, 0);
        }
        for (text, line) in commands {
            self.out.line(text, line);
        }
    }

    /// Replaces the `#define width_scale` line at `at` with the scale measured on the translated
    /// plant, or notes that it could not be measured.
    fn measure_width(&mut self, at: usize) {
        match measure_width_scale(&self.out.text()) {
            Some(scale) => self.out.replace(
                at,
                format!(
                    "{} width_scale {} // width units per model unit: Lparser's thicknesses at the file's depth",
                    DirectiveKind::Define.written(),
                    number(scale)
                ),
            ),
            None => {
                self.out.note(
                    self.file.thickness_line,
                    format!("the plant could not be measured at its depth (too large to derive, or it draws nothing): width_scale is {}, tune it", number(WIDTH_SCALE)),
                );
            }
        }
    }

    fn sorted_rules(&self) -> Vec<(char, usize)> {
        let mut v: Vec<(char, usize)> = self.rule_of.iter().map(|(&c, &i)| (c, i)).collect();
        v.sort_by_key(|&(_, i)| i);
        v
    }

    /// Lparser's colour table, with the file's `color` entries, as `#color` lines (runs of one
    /// colour as one flat ramp).
    fn palette(&mut self) {
        let mut table = [[0.5; 3]; 100];
        let defaults: &[(usize, [f64; 3])] = match self.file.format {
            // Lparser 2.1, Add_default_colors.
            Format::Keyword => &[
                (2, [0.8, 0.4, 0.4]),
                (3, [0.8, 0.8, 0.4]),
                (4, [0.4, 0.8, 0.4]),
                (5, [0.4, 0.8, 0.8]),
                (6, [0.4, 0.4, 0.8]),
                (7, [0.8, 0.4, 0.8]),
                (8, [0.2, 0.5, 0.2]),
                (9, [0.2, 0.5, 0.5]),
                (10, [0.2, 0.2, 0.5]),
                (11, [0.5, 0.2, 0.5]),
                (12, [0.6, 0.2, 0.2]),
                (13, [0.5, 0.5, 0.5]),
                (14, [0.75, 0.75, 0.75]),
                (15, [1.0, 1.0, 1.0]),
            ],
            // The Lparser 4 code's VRML colours ("translate colors from lparser to RGB").
            Format::Positional => &[
                (1, [0.3, 0.3, 0.3]),
                (2, [0.8, 0.4, 0.4]),
                (3, [0.8, 0.8, 0.4]),
                (4, [0.4, 0.8, 0.4]),
                (5, [0.4, 0.8, 0.8]),
                (6, [0.4, 0.4, 0.8]),
                (7, [0.8, 0.4, 0.8]),
                (8, [0.2, 0.5, 0.2]),
                (9, [0.2, 0.5, 0.5]),
                (10, [0.2, 0.2, 0.5]),
                (11, [0.5, 0.2, 0.5]),
                (12, [0.6, 0.2, 0.2]),
                (13, [0.5, 0.5, 0.5]),
                (14, [0.7, 0.7, 0.7]),
                (15, [0.9, 0.9, 0.9]),
            ],
        };
        for &(i, c) in defaults.iter().chain(self.file.colors.iter()) {
            table[i] = c;
        }
        let byte = |v: f64| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
        let rgb = |c: [f64; 3]| format!("{} {} {}", byte(c[0]), byte(c[1]), byte(c[2]));
        self.out
            .comment("Lparser's colour table (indices 0 to 99).", 0);
        let mut i = 0;
        while i < table.len() {
            let mut j = i;
            while j + 1 < table.len() && rgb(table[j + 1]) == rgb(table[i]) {
                j += 1;
            }
            let c = rgb(table[i]);
            if j == i {
                self.out
                    .line(format!("{} {i} {c}", DirectiveKind::Color.written()), 0);
            } else {
                self.out.line(
                    format!("{} {i} {j} {c} {c}", DirectiveKind::Color.written()),
                    0,
                );
            }
            i = j + 1;
        }
    }
}

/// Meristem's width unit is relative: 1/300 of the diagonal of the plant's bounding box (see
/// `mesh`). Lparser draws a segment `length × thickness` thick in model units, so the width in
/// Meristem's units is that times `300 / diagonal`: the importer derives the translated grammar
/// at its own depth (at most [`MEASURE_STEPS`] steps and [`MEASURE_MODULES`] modules) and measures the diagonal as the mesh
/// does. `None` when that fails.
fn measure_width_scale(text: &str) -> Option<f64> {
    let (file, diagnostics) = crate::syntax::parse(text);
    if crate::diagnostics::has_errors(&diagnostics) {
        return None;
    }
    let (model, diagnostics) = crate::model::resolve(&file);
    let mut model = model.filter(|_| !crate::diagnostics::has_errors(&diagnostics))?;
    model.settings.max_modules = model.settings.max_modules.min(MEASURE_MODULES);
    if model.settings.iterations > MEASURE_STEPS {
        return None;
    }
    let options = crate::derive::DeriveOptions {
        steps: model.settings.iterations,
        seed: None,
    };
    let derivation = crate::derive::derive(&model, &options).ok()?;
    let skeleton = crate::turtle::interpret(&model, derivation.turtle_string());
    let diagonal = crate::mesh::skeleton_diagonal(&skeleton);
    let fraction = match crate::mesh::MeshOptions::default().width_unit {
        crate::mesh::WidthUnit::Relative(f) => f,
        crate::mesh::WidthUnit::Absolute(_) => return None,
    };
    (diagonal > 0.0 && diagonal.is_finite()).then(|| 1.0 / (fraction * diagonal))
}

/// `lhs -> rhs`, written so that a successor starting with `//` is not read as a comment.
fn production(lhs: &str, rhs: &str) -> String {
    if rhs.is_empty() {
        format!("{lhs} -> ε")
    } else {
        format!("{lhs} -> {}", separate(rhs))
    }
}

/// Meristem reads `//` after a space as a comment unless it is part of a run of three or more
/// slashes, so a string that starts with exactly two rolls is written `/ /…` (whitespace between
/// modules is insignificant).
fn separate(s: &str) -> String {
    let slashes = s.chars().take_while(|&c| c == '/').count();
    if slashes == 2 {
        format!("/ {}", &s[1..])
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(text: &str) -> Import {
        import(text)
    }

    fn body(import: &Import) -> Vec<String> {
        import
            .text
            .lines()
            .filter(|l| !l.starts_with("//") && !l.starts_with("#color"))
            .map(str::to_string)
            .collect()
    }

    fn check_resolves(import: &Import) {
        let (file, d) = crate::syntax::parse(&import.text);
        let (_, r) = crate::model::resolve(&file);
        assert!(
            !crate::diagnostics::has_errors(&d) && !crate::diagnostics::has_errors(&r),
            "{}\n{d:?}\n{r:?}",
            import.text
        );
    }

    #[test]
    fn leading_float_reads_like_sscanf() {
        assert_eq!(leading_float(".8)"), Some(0.8));
        assert_eq!(leading_float("  -12.5e1x"), Some(-125.0));
        assert_eq!(leading_float("1e"), Some(1.0));
        assert_eq!(leading_float("abc"), None);
        assert_eq!(leading_float("."), None);
    }

    #[test]
    fn values_belong_to_commands_only() {
        let mut out = Output::default();
        let toks = tokenize("F(2)A(3)c(12)", 1, &mut out);
        let chars: Vec<char> = toks.iter().map(|t| t.ch).collect();
        assert_eq!(chars, ['F', 'A', '(', '3', ')', 'c']);
        assert_eq!(toks[0].value, Some(2.0));
        assert_eq!(toks[5].value, Some(12.0));
    }

    #[test]
    fn the_laws_of_net_factors() {
        assert_eq!(classify(&[1.0; 20]), Net::Neutral);
        let mut macro_ = vec![1.0];
        macro_.extend([0.72; 19]);
        assert_eq!(
            classify(&macro_),
            Net::Law {
                prefix: vec![1.0],
                base: 0.72,
                ratio: 1.0
            }
        );
        assert_eq!(
            net_expr(&classify(&macro_)).unwrap(),
            "(NumIt<MaxIt?0.72:1)"
        );
        let geometric: Vec<f64> = (0..20).map(|r| 1.001f64.powi(r)).collect();
        assert_eq!(
            net_expr(&classify(&geometric)).unwrap(),
            "1.001^(MaxIt-NumIt)"
        );
        let odd: Vec<f64> = (0..20).map(|r| 1.0 + (r % 3) as f64).collect();
        assert_eq!(classify(&odd), Net::Irregular);
    }

    #[test]
    fn a_positional_file_becomes_a_parametric_l_system() {
        // ABOP p. 56's monopodial tree as Lparser writes it.
        let import = run("# tree\n10\n45\n15\n#\nc(12)FFAL\n#\nA=F[&'(.8)!BL]>(137)'!(.9)A\nB=F[-'(.8)!(.9)$CL]'!(.9)C\nC=F[+'(.8)!(.9)$BL]'!(.9)B\nL=~c(8){+(30)f(20)-(120)f(20)-(120)f(20)}\n@\n");
        check_resolves(&import);
        let body = body(&import);
        assert!(body.contains(&"#iterations 10".to_string()), "{body:?}");
        assert!(
            body.contains(&"axiom: ;(12)F(1,0.15)F(1,0.15)A(1,0.15)L".to_string()),
            "{body:?}"
        );
        assert!(
            body.contains(
                &"A(len,wid) -> F(len,wid)[&B(len*0.8,wid*0.7)L]/(137)A(len*0.9,wid*0.9)"
                    .to_string()
            ),
            "{body:?}"
        );
        // The positional format's lengths are in units of 100 (its F).
        assert!(
            body.contains(
                &"L -> ~(343.774677078);(8){+(30)f(0.2)-(120)f(0.2)-(120)f(0.2)}".to_string()
            ),
            "{body:?}"
        );
        assert!(body.contains(&"F(x,t) -> !(width_scale*x*t)F(x)".to_string()));
        let messages: Vec<&str> = import.notes.iter().map(|n| n.message.as_str()).collect();
        assert!(messages.iter().any(|m| m.contains("6 radians")));
        assert!(messages.iter().any(|m| m.starts_with("'$'")));
    }

    #[test]
    fn macros_and_growth_rules_scale_what_follows() {
        let import = run("3\n30\n40\nA\nA=FSFA\nS='(.8)!(.9)\nF='(1.3)F'(.77)\n@\n");
        check_resolves(&import);
        let body = body(&import);
        // S's effect comes one step after it is written; F's compounds 1.3 × 0.77 every step.
        for line in [
            "S -> ε",
            "A(len,wid) -> F_r(len,wid)SF_r(len*1.001^(MaxIt-NumIt)*(NumIt<MaxIt?0.8:1),wid*(NumIt<MaxIt?0.9:1))A(len*(1.001^(MaxIt-NumIt))^2*(NumIt<MaxIt?0.8:1),wid*(NumIt<MaxIt?0.9:1))",
            "F_r(len,wid) -> F_r(len*1.3,wid)",
            "F_r(len,wid) -> F(len,wid)",
        ] {
            assert!(body.iter().any(|l| l == line), "{line} not in {body:#?}");
        }
    }

    #[test]
    fn the_keyword_format_reads_its_keywords() {
        let import = run("recursion 2\nangle 20\nthickness 50\nmin_thickness 5\nshape 1\ncolor 3 255 0 0\naxiom F\nrule F = F[+F]  # branch\nmutation 3\nfoo 1\n");
        check_resolves(&import);
        let text = &import.text;
        assert!(text.contains("#iterations 2\n#angle 20\n"), "{text}");
        assert!(text.contains("#color 3 255 0 0"), "{text}");
        assert!(text.contains("\nF_r -> F_r[+F_r] // branch\n"), "{text}");
        assert!(text.contains("max(x*t,0.05)"), "{text}");
        let lines: Vec<usize> = import.notes.iter().map(|n| n.line).collect();
        assert!(
            lines.contains(&5) && lines.contains(&9) && lines.contains(&10),
            "{:?}",
            import.notes
        );
    }

    #[test]
    fn successors_starting_with_two_rolls_are_not_comments() {
        let import = run("1\n30\n10\nA\nA=>>F\n@\n");
        check_resolves(&import);
        assert!(import.text.contains("A -> / /F(1,0.1)"), "{}", import.text);
    }

    #[test]
    fn nothing_panics_on_odd_input() {
        for text in [
            "",
            "@",
            "x\ny\nz\n",
            "1\n2\n3\nF(\n@",
            "1\n2\n3\nF\n[=]\n(=F\nF=F)\nF=G\n=\nF\n",
            "recursion\nrule\naxiom\ncolor 200 1 2 3\n",
            "3\n3\n3\nA\nA=]]A[[\n@\n",
            "99999999999\n1e308\n-5\nFé\n@\n",
        ] {
            let import = run(text);
            let (file, _) = crate::syntax::parse(&import.text);
            if file.axiom.is_some() {
                let (_, r) = crate::model::resolve(&file);
                assert!(
                    !crate::diagnostics::has_errors(&r),
                    "{text:?}\n{}\n{r:?}",
                    import.text
                );
            }
        }
    }
}
