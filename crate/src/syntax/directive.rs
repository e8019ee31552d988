//! `#name arguments` lines. What the arguments hold comes from the directive's row in the
//! vocabulary: a definition (`#define NAME expr`, `#random NAME = expr`) and module lists
//! (`#ignore A B`) are read here; other arguments stay text for the resolver, which knows their
//! kinds.

use super::ast::Directive;
use super::expr::parse_expression;
use super::scanner::ModuleScanner;
use crate::diagnostics::Diagnostic;
use crate::vocabulary::{directive_named, DirectiveKind, ParamKind, PATCH_COLOR};

/// Parses the directive whose `#` is at byte `at`; `None` when the line is too broken to keep.
pub(super) fn parse_directive(
    after_hash: &str,
    at: usize,
    scanner: &ModuleScanner,
    diagnostics: &mut Vec<Diagnostic>,
) -> Option<Directive> {
    let name_len = after_hash
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(after_hash.len());
    if name_len == 0 {
        diagnostics.push(Diagnostic::error(
            "E0103",
            at..at + 1,
            "expected a directive name after '#'",
        ));
        return None;
    }
    let name = &after_hash[..name_len];
    let rest = &after_hash[name_len..];
    let args = rest.trim();
    let args_at = at + 1 + name_len + (rest.len() - rest.trim_start().len());
    let info = directive_named(name);
    let mut directive = Directive {
        name: name.to_string(),
        kind: info.map(|i| i.kind),
        written: format!("#{name}"),
        name_span: at..at + 1 + name_len,
        args: args.to_string(),
        args_span: args_at..args_at + args.len(),
        target: None,
        expr: None,
        modules: Vec::new(),
        points: Vec::new(),
        point_spans: Vec::new(),
    };
    let first = info.and_then(|i| i.params().first()).map(|p| p.kind);
    let second = info.and_then(|i| i.params().get(1)).map(|p| p.kind);
    let kept = match first {
        Some(ParamKind::Name) if second == Some(ParamKind::Points) => {
            curve_definition(&mut directive, diagnostics)
        }
        Some(ParamKind::Name) if second == Some(ParamKind::Surface) => {
            surface_definition(&mut directive, diagnostics)
        }
        Some(ParamKind::Name) => definition(&mut directive, diagnostics),
        Some(ParamKind::Modules) => module_list(&mut directive, scanner, diagnostics),
        _ => true,
    };
    kept.then_some(directive)
}

/// The length of the name a defining directive starts with; `None` (and error E0113, saying
/// that `then` follows the name) when it has none.
fn leading_name(d: &Directive, then: &str, diagnostics: &mut Vec<Diagnostic>) -> Option<usize> {
    let args = d.args.as_str();
    let ident_len = args
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(args.len());
    if ident_len == 0 || args.starts_with(|c: char| c.is_ascii_digit()) {
        diagnostics.push(Diagnostic::error(
            "E0113",
            d.name_span.clone(),
            format!("{} needs a name, then {then}", d.written),
        ));
        return None;
    }
    Some(ident_len)
}

/// `#define NAME expr`, `#random NAME = expr` (the `=` is optional for both). False when the line
/// is not kept.
fn definition(d: &mut Directive, diagnostics: &mut Vec<Diagnostic>) -> bool {
    let Some(ident_len) = leading_name(d, "an expression", diagnostics) else {
        return false;
    };
    let args = d.args.as_str();
    let args_at = d.args_span.start;
    let target = (args[..ident_len].to_string(), args_at..args_at + ident_len);
    let mut expr_text = &args[ident_len..];
    let mut expr_at = args_at + ident_len;
    let trimmed = expr_text.trim_start();
    expr_at += expr_text.len() - trimmed.len();
    expr_text = trimmed;
    if let Some(after_eq) = expr_text.strip_prefix('=') {
        expr_at += 1;
        expr_text = after_eq;
    }
    if expr_text.trim().is_empty() {
        diagnostics.push(Diagnostic::error(
            "E0113",
            d.args_span.clone(),
            format!("{} {} needs an expression", d.written, &args[..ident_len]),
        ));
        return false;
    }
    match parse_expression(expr_text, expr_at) {
        Ok(e) => {
            d.target = Some(target);
            d.expr = Some(e);
            true
        }
        Err(e) => {
            diagnostics.push(e);
            false
        }
    }
}

/// `#surface X words`: the letter; the words stay text for the resolver. False when the line is
/// not kept. (Without the feature `surfaces` the line is kept as written: the first plant's core
/// only says that the grammar declares surfaces, and the studio's core builds it.)
#[cfg(not(feature = "surfaces"))]
fn surface_definition(_: &mut Directive, _: &mut Vec<Diagnostic>) -> bool {
    true
}

#[cfg(feature = "surfaces")]
fn surface_definition(d: &mut Directive, diagnostics: &mut Vec<Diagnostic>) -> bool {
    let Some(ident_len) = leading_name(d, "a shape or frame words", diagnostics) else {
        return false;
    };
    let at = d.args_span.start;
    d.target = Some((d.args[..ident_len].to_string(), at..at + ident_len));
    true
}

/// `#curve NAME x y x y …`, `#table NAME x y …`, `#patch X x y z, … [color c [c]]`: a name,
/// then numbers separated by spaces or commas (a patch's colours stay text for the resolver).
/// False when the line is not kept.
fn curve_definition(d: &mut Directive, diagnostics: &mut Vec<Diagnostic>) -> bool {
    let coordinates = if d.kind == Some(DirectiveKind::Patch) {
        "x y z"
    } else {
        "x y"
    };
    let Some(ident_len) = leading_name(d, &format!("points {coordinates}"), diagnostics) else {
        return false;
    };
    let args = d.args.as_str();
    let args_at = d.args_span.start;
    let rest = &args[ident_len..];
    let mut points = Vec::new();
    let mut spans = Vec::new();
    for word in rest.split(|c: char| c.is_whitespace() || c == ',') {
        if word.is_empty() {
            continue;
        }
        // `#patch X … color top [bottom]`: the resolver reads the colours from the text.
        if word == PATCH_COLOR && d.kind == Some(DirectiveKind::Patch) {
            break;
        }
        let at = args_at + (word.as_ptr() as usize - args.as_ptr() as usize);
        match crate::number::parse_f64(word) {
            Some(v) if v.is_finite() => {
                points.push(v);
                spans.push(at..at + word.len());
            }
            _ => {
                diagnostics.push(Diagnostic::error(
                    "E0137",
                    at..at + word.len(),
                    format!(
                        "'{word}' is not a number: {} takes numbers {coordinates}",
                        d.written
                    ),
                ));
                return false;
            }
        }
    }
    d.target = Some((args[..ident_len].to_string(), args_at..args_at + ident_len));
    d.points = points;
    d.point_spans = spans;
    true
}

/// `#ignore`, `#consider`, `#draw`, `#apex`, `#module`: module names. False when the line is not
/// kept.
fn module_list(
    d: &mut Directive,
    scanner: &ModuleScanner,
    diagnostics: &mut Vec<Diagnostic>,
) -> bool {
    let (args, args_at) = (d.args.as_str(), d.args_span.start);
    if args.is_empty() {
        diagnostics.push(Diagnostic::error(
            "E0133",
            d.name_span.clone(),
            format!("{} lists no modules", d.written),
        ));
        return false;
    }
    if d.kind == Some(DirectiveKind::Module) {
        for (offset, word) in args
            .split_whitespace()
            .map(|w| (w.as_ptr() as usize - args.as_ptr() as usize, w))
        {
            if !word.starts_with(|c: char| c.is_alphabetic())
                || !word.chars().all(|c| c.is_alphanumeric() || c == '_')
            {
                let at = args_at + offset;
                diagnostics.push(Diagnostic::error(
                    "E0134",
                    at..at + word.len(),
                    format!("'{word}' cannot be a module name: names are a letter followed by letters, digits or '_'"),
                ));
            }
        }
        return true;
    }
    let modules = scanner.scan(args, args_at, diagnostics);
    if let Some(m) = modules
        .iter()
        .find(|m| !m.params.is_empty() || m.group.is_some())
    {
        diagnostics.push(Diagnostic::error(
            "E0135",
            m.span.clone(),
            format!("{} lists module names, without parameters", d.written),
        ));
    }
    d.modules = modules;
    true
}
