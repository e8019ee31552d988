//! Reading an `.ls` file into its model ([`LsFile`]): the positional or the keyword format,
//! rules, and each string as Lparser's symbols ([`Tok`]) with their values.

use super::{
    Format, LsFile, Rule, Tok, DEFAULT_ANGLE, DEFAULT_RECURSION, DEFAULT_THICKNESS, VALUE_COMMANDS,
};
use crate::import::{leading_float, number, Output};

/// Whether the file uses the keyword format: its first content line starts with a keyword.
pub(super) fn format_of(text: &str) -> Format {
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

pub(super) const KEYWORDS: &[&str] = &[
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

pub(super) fn parse(text: &str, out: &mut Output) -> LsFile {
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
pub(super) fn split_comment(line: &str) -> (&str, &str) {
    match line.find('#') {
        Some(i) => (&line[..i], line[i + 1..].trim()),
        None => (line, ""),
    }
}

pub(super) fn without_spaces(s: &str) -> String {
    s.chars().filter(|c| !c.is_whitespace()).collect()
}

/// A comment worth carrying over: it says something (not a row of dashes).
pub(super) fn keep_comment(comment: &str) -> Option<String> {
    let c = comment.trim().trim_matches('-').trim();
    (c.chars().any(char::is_alphanumeric)).then(|| comment.trim().to_string())
}

/// The lines of an `.ls` file that hold code, read lazily: each as its 1-based number, its code
/// and the comment after it. A line that is only a `#` comment goes to `header` (when it says
/// something), in order.
fn code_lines<'a>(
    text: &'a str,
    header: &'a mut Vec<String>,
) -> impl Iterator<Item = (usize, &'a str, &'a str)> + 'a {
    text.lines().enumerate().filter_map(move |(index, raw)| {
        let trimmed = raw.trim();
        if trimmed.is_empty() {
            return None;
        }
        if let Some(comment) = trimmed.strip_prefix('#') {
            if let Some(c) = keep_comment(comment) {
                header.push(c);
            }
            return None;
        }
        let (code, comment) = split_comment(trimmed);
        Some((index + 1, code, comment))
    })
}

pub(super) fn parse_positional(text: &str, file: &mut LsFile, out: &mut Output) {
    let mut stage = 0;
    let mut ended = false;
    let mut header = Vec::new();
    for (n, code, comment) in code_lines(text, &mut header) {
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
    file.header.extend(header);
    if !ended && stage >= 4 {
        out.note(
            text.lines().count(),
            "no '@' end mark: Lparser reads rules up to a line starting with '@'; every rule line was read",
        );
    }
}

/// Reads the keyword format of Lparser 2 into `file`, line by line.
pub(super) fn parse_keywords(text: &str, file: &mut LsFile, out: &mut Output) {
    let mut noted: Vec<String> = Vec::new();
    let mut header = Vec::new();
    for (n, code, comment) in code_lines(text, &mut header) {
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
    file.header.extend(header);
}

/// Why a keyword of Lparser's program or output, not of the plant, is not translated (noted
/// once a file); `None` for the others.
pub(super) fn untranslated_keyword(keyword: &str) -> Option<String> {
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
pub(super) fn keyword_line(
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
pub(super) fn add_rule(file: &mut LsFile, code: &str, n: usize, comment: &str, out: &mut Output) {
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

/// Splits an Lparser string into symbols: a command of [`VALUE_COMMANDS`] followed by `(` takes
/// everything up to `)` as its value (`Get_value`); any other character is a symbol of its own.
pub(super) fn tokenize(code: &str, n: usize, out: &mut Output) -> Vec<Tok> {
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
