//! Production lines: `label: left < predecessor > right : condition -> (weight) successor`.

use super::ast::{ExprSyntax, ModuleSyntax, ProductionSyntax, Section, Span};
use super::brackets::PARENTHESES;
use super::expr::parse_expression;
use super::scanner::{branch_bracket, check_brackets, ModuleScanner};
use crate::diagnostics::{Diagnostic, Severity};

/// Parses a production line starting at byte `at`. A line with an error yields no production:
/// half a production would only cause more (misleading) diagnostics later.
pub(super) fn parse_production(
    content: &str,
    at: usize,
    section: Section,
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
    let (label, lhs, lhs_at) = split_label(&content[..arrow_start], at, scanner);
    let errors_before = diagnostics.len();
    let (lhs, condition) = split_condition(lhs, lhs_at, diagnostics);
    let sides = split_contexts(lhs, lhs_at, scanner, diagnostics);
    let predecessor = predecessor(&sides, span.start..at + arrow_end, scanner, diagnostics)?;
    let (weight, successor) =
        right_side(&content[arrow_end..], at + arrow_end, scanner, diagnostics)?;
    if diagnostics[errors_before..]
        .iter()
        .any(|d| d.severity == Severity::Error)
    {
        return None;
    }
    Some(ProductionSyntax {
        label,
        section,
        left: sides.left,
        predecessor,
        right: sides.right,
        condition,
        weight,
        successor,
        span,
    })
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

/// A label is an identifier of two or more characters before a ':' (`p1: X -> …`), unless it is a
/// declared module. Returns the label and the rest of the left-hand side with its offset.
fn split_label<'a>(
    lhs: &'a str,
    at: usize,
    scanner: &ModuleScanner,
) -> (Option<String>, &'a str, usize) {
    if let Some(colon) = lhs.find(':') {
        let candidate = lhs[..colon].trim();
        let is_ident = candidate.len() >= 2
            && candidate
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_')
            && candidate.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            && !scanner.is_declared(candidate);
        if is_ident {
            return (
                Some(candidate.to_string()),
                &lhs[colon + 1..],
                at + colon + 1,
            );
        }
    }
    (None, lhs, at)
}

/// The condition: after the first ':' outside parentheses. Returns what is before it.
fn split_condition<'a>(
    lhs: &'a str,
    at: usize,
    diagnostics: &mut Vec<Diagnostic>,
) -> (&'a str, Option<ExprSyntax>) {
    let Some(colon) = PARENTHESES.find_char(lhs, ':') else {
        return (lhs, None);
    };
    let text = &lhs[colon + 1..];
    let mut condition = None;
    if text.trim().is_empty() {
        diagnostics.push(Diagnostic::error(
            "E0114",
            at + colon..at + colon + 1,
            "expected a condition after ':'",
        ));
    } else {
        match parse_expression(text, at + colon + 1) {
            Ok(e) => condition = Some(e),
            Err(d) => diagnostics.push(d),
        }
    }
    (&lhs[..colon], condition)
}

/// The contexts around the strict predecessor, and where the predecessor's text is.
struct Sides<'a> {
    left: Vec<ModuleSyntax>,
    right: Vec<ModuleSyntax>,
    predecessor: &'a str,
    predecessor_at: usize,
}

/// `left < predecessor > right`; a context of `*` alone is no context.
fn split_contexts<'a>(
    lhs: &'a str,
    at: usize,
    scanner: &ModuleScanner,
    diagnostics: &mut Vec<Diagnostic>,
) -> Sides<'a> {
    let context = |text: &str, at: usize, diagnostics: &mut Vec<Diagnostic>| {
        if text.trim() == "*" {
            Vec::new()
        } else {
            scanner.scan(text, at, diagnostics)
        }
    };
    let mut sides = Sides {
        left: Vec::new(),
        right: Vec::new(),
        predecessor: lhs,
        predecessor_at: at,
    };
    if let Some(lt) = PARENTHESES.find_char(sides.predecessor, '<') {
        sides.left = context(&sides.predecessor[..lt], sides.predecessor_at, diagnostics);
        sides.predecessor_at += lt + 1;
        sides.predecessor = &sides.predecessor[lt + 1..];
    }
    if let Some(gt) = PARENTHESES.find_char(sides.predecessor, '>') {
        let right_at = sides.predecessor_at + gt + 1;
        sides.right = context(&sides.predecessor[gt + 1..], right_at, diagnostics);
        sides.predecessor = &sides.predecessor[..gt];
    }
    for m in &sides.left {
        if branch_bracket(&m.name).is_some() {
            diagnostics.push(Diagnostic::error(
                "E0115",
                m.span.clone(),
                "a left context cannot hold brackets",
            ));
        }
    }
    check_brackets(&sides.right, diagnostics);
    sides
}

/// The strict predecessor: exactly one module. `line_to_arrow` is where E0106 points.
fn predecessor(
    sides: &Sides,
    line_to_arrow: Span,
    scanner: &ModuleScanner,
    diagnostics: &mut Vec<Diagnostic>,
) -> Option<ModuleSyntax> {
    let (text, at) = (sides.predecessor, sides.predecessor_at);
    let modules = scanner.scan(text, at, diagnostics);
    match modules.len() {
        1 => modules.into_iter().next(),
        0 => {
            diagnostics.push(Diagnostic::error(
                "E0106",
                line_to_arrow,
                "a production needs a predecessor module before the arrow",
            ));
            None
        }
        n => {
            diagnostics.push(Diagnostic::error(
                "E0107",
                at..at + text.len(),
                format!("the predecessor must be a single module; found {n}"),
            ));
            None
        }
    }
}

/// After the arrow: an optional weight `(expr)`, then the successor (empty for `ε`, `*` or
/// nothing).
fn right_side(
    rhs: &str,
    at: usize,
    scanner: &ModuleScanner,
    diagnostics: &mut Vec<Diagnostic>,
) -> Option<(Option<ExprSyntax>, Vec<ModuleSyntax>)> {
    if let Some((second, end)) = find_arrow(rhs) {
        diagnostics.push(Diagnostic::error(
            "E0136",
            at + second..at + end,
            "a second arrow: a production has one predecessor and one successor",
        ));
        return None;
    }
    let mut trimmed = rhs.trim();
    let mut rhs_at = at + (rhs.len() - rhs.trim_start().len());
    let mut weight = None;
    if trimmed.starts_with('(') {
        let Some(close) = PARENTHESES.closing(trimmed, 0) else {
            diagnostics.push(Diagnostic::error(
                "E0116",
                rhs_at..rhs_at + 1,
                "'(' is never closed by a ')'",
            ));
            return None;
        };
        match parse_expression(&trimmed[1..close], rhs_at + 1) {
            Ok(e) => weight = Some(e),
            Err(d) => diagnostics.push(d),
        }
        let after = &trimmed[close + 1..];
        rhs_at += close + 1 + (after.len() - after.trim_start().len());
        trimmed = after.trim();
    }
    let successor = if trimmed.is_empty() || trimmed == "ε" || trimmed == "*" {
        Vec::new()
    } else {
        let modules = scanner.scan(trimmed, rhs_at, diagnostics);
        check_brackets(&modules, diagnostics);
        modules
    };
    Some((weight, successor))
}
