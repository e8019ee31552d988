//! The line-oriented parser. Each line is a directive, an axiom, or a production; a line that
//! cannot be read yields a diagnostic and parsing resumes at the next line.

use super::ast::{Directive, ModuleSyntax, ProductionSyntax, SourceFile, Span};
use super::comments::blank_comments;
use crate::diagnostics::Diagnostic;

/// `@` names of LANGUAGE.md sections 6 and 7, matched longest first so that `@GcF` is `@Gc F`.
const AT_NAMES: &[&str] = &[
    "@Pendulum",
    "@Repeat",
    "@Switch",
    "@Prune",
    "@Gc",
    "@Ge",
    "@Tp",
    "@Ts",
    "@M",
    "@O",
    "@v",
];

/// Parses a grammar. Always returns a (possibly partial) [`SourceFile`] and every diagnostic found.
pub fn parse(source: &str) -> (SourceFile, Vec<Diagnostic>) {
    let (text, mut diagnostics) = blank_comments(source);
    let mut file = SourceFile::default();
    let lines = split_lines(&text);

    // `#module` declarations change how every line is split into modules, so read them first.
    let mut declared: Vec<String> = Vec::new();
    for &(_, line) in &lines {
        if let Some(rest) = line.trim_start().strip_prefix("#module") {
            if rest.is_empty() || rest.starts_with(char::is_whitespace) {
                declared.extend(rest.split_whitespace().map(str::to_string));
            }
        }
    }
    declared.sort_by_key(|name| std::cmp::Reverse(name.len()));
    let scanner = ModuleScanner {
        declared: &declared,
    };

    for (start, line) in lines {
        let lead = line.len() - line.trim_start().len();
        let content = line.trim();
        if content.is_empty() {
            continue;
        }
        let at = start + lead;
        let span = at..at + content.len();
        if let Some(after_hash) = content.strip_prefix('#') {
            parse_directive(after_hash, at, &mut file, &mut diagnostics);
        } else if let Some((keyword, rest_at)) = keyword(content) {
            let rest = &content[rest_at..];
            let rest_start = at + rest_at;
            match keyword {
                Keyword::Axiom => {
                    let modules = scanner.scan(rest, rest_start, &mut diagnostics);
                    check_brackets(&modules, &mut diagnostics);
                    if let Some((_, previous)) = &file.axiom {
                        diagnostics.push(Diagnostic::warning(
                            "E0104",
                            span.clone(),
                            format!(
                                "a second axiom replaces the one at byte {}; a grammar has one axiom",
                                previous.start
                            ),
                        ));
                    }
                    file.axiom = Some((modules, span));
                }
                Keyword::DerivationLength => {
                    let trimmed = rest.trim();
                    let args_at = rest_start + (rest.len() - rest.trim_start().len());
                    file.directives.push(Directive {
                        name: "iterations".into(),
                        name_span: at..rest_start,
                        args: trimmed.to_string(),
                        args_span: args_at..args_at + trimmed.len(),
                    });
                }
                Keyword::Unsupported(name) => diagnostics.push(Diagnostic::error(
                    "E0190",
                    at..rest_start,
                    format!("'{name}' sections are part of the language but not implemented yet"),
                )),
            }
        } else {
            if let Some(p) = parse_production(content, at, &scanner, &mut diagnostics) {
                file.productions.push(p);
            }
        }
    }
    (file, diagnostics)
}

/// Lines with the byte offset at which each starts (`\r\n` endings are handled by `trim`).
fn split_lines(text: &str) -> Vec<(usize, &str)> {
    let mut lines = Vec::new();
    let mut start = 0;
    for line in text.split('\n') {
        lines.push((start, line));
        start += line.len() + 1;
    }
    lines
}

enum Keyword {
    Axiom,
    DerivationLength,
    Unsupported(&'static str),
}

/// Recognises `axiom:`, `ω:`, `derivation length:` and the section keywords; returns the keyword
/// and the byte offset just after its colon.
fn keyword(content: &str) -> Option<(Keyword, usize)> {
    let colon = content.find(':')?;
    let word = content[..colon].trim().to_ascii_lowercase();
    let kw = match word.as_str() {
        "axiom" | "ω" => Keyword::Axiom,
        "derivation length" => Keyword::DerivationLength,
        "homomorphism" => Keyword::Unsupported("homomorphism:"),
        "decomposition" => Keyword::Unsupported("decomposition:"),
        "maximum depth" => Keyword::Unsupported("maximum depth:"),
        _ => return None,
    };
    Some((kw, colon + 1))
}

fn parse_directive(
    after_hash: &str,
    at: usize,
    file: &mut SourceFile,
    diagnostics: &mut Vec<Diagnostic>,
) {
    let name_len = after_hash
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(after_hash.len());
    if name_len == 0 {
        diagnostics.push(Diagnostic::error(
            "E0103",
            at..at + 1,
            "expected a directive name after '#'",
        ));
        return;
    }
    let name = &after_hash[..name_len];
    let rest = &after_hash[name_len..];
    let args = rest.trim();
    let args_at = at + 1 + name_len + (rest.len() - rest.trim_start().len());
    file.directives.push(Directive {
        name: name.to_string(),
        name_span: at..at + 1 + name_len,
        args: args.to_string(),
        args_span: args_at..args_at + args.len(),
    });
}

/// Finds the production arrow: `->`, `-->` or `→`. Returns (start, end) byte offsets in `content`.
fn find_arrow(content: &str) -> Option<(usize, usize)> {
    let ascii = content.find("->");
    let unicode = content.find('→');
    match (ascii, unicode) {
        (Some(a), Some(u)) if u < a => Some((u, u + '→'.len_utf8())),
        (Some(a), _) => {
            // `X --> Y` is one arrow, but in `- -> +` or `-->+` the first '-' is the predecessor.
            if a > 0 && content.as_bytes()[a - 1] == b'-' && !content[..a - 1].trim().is_empty() {
                Some((a - 1, a + 2))
            } else {
                Some((a, a + 2))
            }
        }
        (None, Some(u)) => Some((u, u + '→'.len_utf8())),
        (None, None) => None,
    }
}

fn parse_production(
    content: &str,
    at: usize,
    scanner: &ModuleScanner,
    diagnostics: &mut Vec<Diagnostic>,
) -> Option<ProductionSyntax> {
    let span = at..at + content.len();
    let Some((arrow_start, arrow_end)) = find_arrow(content) else {
        diagnostics.push(Diagnostic::error(
            "E0105",
            span,
            "expected a production 'predecessor -> successor', a directive '#…' or 'axiom: …'",
        ));
        return None;
    };
    let mut lhs = &content[..arrow_start];
    let mut lhs_at = at;
    let mut label = None;

    // A label is an identifier of two or more characters before a ':' (`p1: X -> …`).
    if let Some(colon) = lhs.find(':') {
        let candidate = lhs[..colon].trim();
        let is_ident = candidate.len() >= 2
            && candidate
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_')
            && candidate.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            && !scanner.declared.iter().any(|d| d == candidate);
        if is_ident {
            label = Some(candidate.to_string());
            lhs_at += colon + 1;
            lhs = &lhs[colon + 1..];
        }
    }
    let pred_span = lhs_at..at + arrow_start;
    for (token, what, code) in [
        ('<', "left contexts ('<')", "E0191"),
        ('>', "right contexts ('>')", "E0191"),
        (':', "conditions (':')", "E0192"),
        ('(', "parameters ('(…)')", "E0193"),
    ] {
        if let Some(i) = lhs.find(token) {
            diagnostics.push(Diagnostic::error(
                code,
                lhs_at + i..lhs_at + i + 1,
                format!("{what} are part of the language but not implemented yet"),
            ));
            return None;
        }
    }
    let mut local = Vec::new();
    let predecessor = scanner.scan(lhs, lhs_at, &mut local);
    diagnostics.extend(local);
    let predecessor = match predecessor.len() {
        1 => predecessor.into_iter().next()?,
        0 => {
            diagnostics.push(Diagnostic::error(
                "E0106",
                span.start..at + arrow_end,
                "a production needs a predecessor module before the arrow",
            ));
            return None;
        }
        n => {
            diagnostics.push(Diagnostic::error(
                "E0107",
                pred_span,
                format!("the predecessor must be a single module; found {n}"),
            ));
            return None;
        }
    };

    let rhs = &content[arrow_end..];
    let rhs_at = at + arrow_end;
    let trimmed = rhs.trim();
    let successor = if trimmed.is_empty() || trimmed == "ε" || trimmed == "*" {
        Vec::new()
    } else {
        if trimmed.starts_with('(') {
            let i = rhs.find('(').unwrap_or(0);
            diagnostics.push(Diagnostic::error(
                "E0194",
                rhs_at + i..rhs_at + i + 1,
                "weighted (stochastic) productions are part of the language but not implemented yet",
            ));
            return None;
        }
        let modules = scanner.scan(rhs, rhs_at, diagnostics);
        check_brackets(&modules, diagnostics);
        modules
    };
    Some(ProductionSyntax {
        label,
        predecessor,
        successor,
        span,
    })
}

/// Reports unbalanced `[` `]` in one module string (axiom or successor).
fn check_brackets(modules: &[ModuleSyntax], diagnostics: &mut Vec<Diagnostic>) {
    let mut open: Vec<&Span> = Vec::new();
    for m in modules {
        match m.name.as_str() {
            "[" => open.push(&m.span),
            "]" if open.pop().is_none() => {
                diagnostics.push(Diagnostic::error(
                    "E0108",
                    m.span.clone(),
                    "']' has no matching '['",
                ));
            }
            _ => {}
        }
    }
    for span in open {
        diagnostics.push(Diagnostic::error(
            "E0109",
            span.clone(),
            "'[' is never closed by a ']'",
        ));
    }
}

/// Splits a module string into module names (LANGUAGE.md section 1).
struct ModuleScanner<'a> {
    /// `#module` names, longest first.
    declared: &'a [String],
}

impl ModuleScanner<'_> {
    fn scan(
        &self,
        text: &str,
        base: usize,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> Vec<ModuleSyntax> {
        let mut modules = Vec::new();
        let mut i = 0;
        while i < text.len() {
            let rest = &text[i..];
            let Some(c) = rest.chars().next() else { break };
            if c.is_whitespace() {
                i += c.len_utf8();
                continue;
            }
            if c == '(' {
                let close = rest.find(')').map_or(text.len(), |j| i + j + 1);
                diagnostics.push(Diagnostic::error(
                    "E0193",
                    base + i..base + close,
                    "parameters ('(…)') are part of the language but not implemented yet",
                ));
                i = close;
                continue;
            }
            if c == ')' {
                diagnostics.push(Diagnostic::error(
                    "E0110",
                    base + i..base + i + 1,
                    "')' has no matching '('",
                ));
                i += 1;
                continue;
            }
            let len = self.name_length(rest);
            modules.push(ModuleSyntax {
                name: rest[..len].to_string(),
                span: base + i..base + i + len,
            });
            i += len;
        }
        modules
    }

    /// Byte length of the module name at the start of `rest` (which is not empty).
    fn name_length(&self, rest: &str) -> usize {
        if let Some(d) = self.declared.iter().find(|d| rest.starts_with(d.as_str())) {
            return d.len();
        }
        let bytes = rest.as_bytes();
        match bytes[0] {
            b'@' => {
                if let Some(known) = AT_NAMES.iter().find(|n| rest.starts_with(*n)) {
                    return known.len();
                }
                1 + rest[1..]
                    .find(|c: char| !c.is_ascii_alphabetic())
                    .unwrap_or(rest.len() - 1)
            }
            b'?' if bytes.len() > 1 && bytes[1].is_ascii_alphabetic() => 2,
            // A subscript is one letter (`F_a`) or a run of digits (`A_12`).
            c if c.is_ascii_alphabetic()
                && bytes.len() > 2
                && bytes[1] == b'_'
                && bytes[2].is_ascii_alphabetic() =>
            {
                3
            }
            c if c.is_ascii_alphabetic()
                && bytes.len() > 2
                && bytes[1] == b'_'
                && bytes[2].is_ascii_digit() =>
            {
                2 + rest[2..]
                    .find(|c: char| !c.is_ascii_digit())
                    .unwrap_or(rest.len() - 2)
            }
            _ => rest.chars().next().map_or(1, char::len_utf8),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(src: &str) -> Vec<String> {
        let (file, diags) = parse(&format!("axiom: {src}"));
        assert!(diags.is_empty(), "{diags:?}");
        file.axiom
            .map(|(m, _)| m.into_iter().map(|m| m.name).collect())
            .unwrap_or_default()
    }

    #[test]
    fn module_names_follow_the_lexical_rules() {
        assert_eq!(names("F [ +F ] F"), ["F", "[", "+", "F", "]", "F"]);
        assert_eq!(names("F_aF_lA_1A_12B"), ["F_a", "F_l", "A_1", "A_12", "B"]);
        assert_eq!(
            names("@GcF@Ge?PX01"),
            ["@Gc", "F", "@Ge", "?P", "X", "0", "1"]
        );
        assert_eq!(names("F_ X"), ["F", "_", "X"]);
    }

    #[test]
    fn declared_multi_letter_modules_are_one_module() {
        let (file, diags) = parse("#module Apex Leaf\naxiom: ApexFFLeaf");
        assert!(diags.is_empty());
        let names: Vec<_> = file.axiom.unwrap().0.into_iter().map(|m| m.name).collect();
        assert_eq!(names, ["Apex", "F", "F", "Leaf"]);
    }

    #[test]
    fn productions_accept_labels_every_arrow_and_empty_successors() {
        let (file, diags) = parse("p1: X -> F[+X]\nF --> FF\nA → B\n- -> +\nB -> ε\nC ->\nD -> *");
        assert!(diags.is_empty(), "{diags:?}");
        let p: Vec<_> = file
            .productions
            .iter()
            .map(|p| {
                (
                    p.label.clone(),
                    p.predecessor.name.clone(),
                    p.successor.len(),
                )
            })
            .collect();
        assert_eq!(
            p,
            [
                (Some("p1".into()), "X".into(), 5),
                (None, "F".into(), 2),
                (None, "A".into(), 1),
                (None, "-".into(), 1),
                (None, "B".into(), 0),
                (None, "C".into(), 0),
                (None, "D".into(), 0),
            ]
        );
    }

    #[test]
    fn a_bad_line_does_not_stop_the_parser() {
        let (file, diags) = parse("axiom: X\nX F\nX -> F[\nF -> FF\n");
        assert_eq!(file.productions.len(), 2);
        assert_eq!(
            diags.iter().map(|d| d.code).collect::<Vec<_>>(),
            ["E0105", "E0109"]
        );
    }
}
