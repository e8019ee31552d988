//! Resolve: syntax tree -> [`Model`]. Checks directive arguments, interns module names and builds
//! the production lookup table.

use super::{Alphabet, LString, Model, Production, Settings};
use crate::diagnostics::Diagnostic;
use crate::syntax::{Directive, SourceFile};

/// Directives of LANGUAGE.md section 2 that this version reads but does not implement yet; using
/// one is an error that says so, rather than being silently ignored.
const NOT_YET: &[&str] = &[
    "define",
    "seed",
    "ignore",
    "consider",
    "random",
    "width_step",
    "tropism",
];

/// Resolves a parsed file. Returns `None` for the model when there is nothing to derive (no
/// axiom); otherwise a model plus every diagnostic, even when some are errors.
pub fn resolve(file: &SourceFile) -> (Option<Model>, Vec<Diagnostic>) {
    let mut diagnostics = Vec::new();
    let mut alphabet = Alphabet::default();
    let mut settings = Settings::default();
    let mut seen: Vec<&Directive> = Vec::new();

    for d in &file.directives {
        if let Some(previous) = seen
            .iter()
            .find(|p| p.name == d.name && d.name != "module" && d.name != "draw")
        {
            diagnostics.push(Diagnostic::warning(
                "E0201",
                d.name_span.clone(),
                format!(
                    "#{} is set twice; this one replaces the value at byte {}",
                    d.name, previous.name_span.start
                ),
            ));
        }
        seen.push(d);
        match d.name.as_str() {
            "angle" => {
                if let Some(v) = number(d, &mut diagnostics) {
                    settings.angle = v;
                }
            }
            "step" => {
                if let Some(v) = number(d, &mut diagnostics) {
                    settings.step = v;
                }
            }
            "width" => {
                if let Some(v) = number(d, &mut diagnostics) {
                    settings.width = v;
                }
            }
            "iterations" => {
                if let Some(v) = whole(d, u32::MAX as u64, &mut diagnostics) {
                    settings.iterations = v as u32;
                    settings.iterations_span = Some(d.name_span.start..d.args_span.end);
                }
            }
            "max_modules" => {
                if let Some(v) = whole(d, u32::MAX as u64, &mut diagnostics) {
                    settings.max_modules = v.max(1) as usize;
                }
            }
            "max_steps" => {
                if let Some(v) = whole(d, u32::MAX as u64, &mut diagnostics) {
                    settings.max_steps = v as u32;
                }
            }
            "module" => {} // read by the parser
            "draw" => {
                for name in d.args.split_whitespace() {
                    let id = alphabet.intern(name);
                    settings.draw.push(id);
                }
            }
            name if NOT_YET.contains(&name) => diagnostics.push(Diagnostic::error(
                "E0290",
                d.name_span.clone(),
                format!("#{name} is part of the language but not implemented yet"),
            )),
            name => diagnostics.push(Diagnostic::error(
                "E0200",
                d.name_span.clone(),
                format!("unknown directive '#{name}'"),
            )),
        }
    }
    let Some((axiom_syntax, axiom_span)) = &file.axiom else {
        diagnostics.push(Diagnostic::error(
            "E0300",
            0..0,
            "the grammar has no axiom: add a line 'axiom: …'",
        ));
        return (None, diagnostics);
    };
    let axiom = LString {
        ids: axiom_syntax
            .iter()
            .map(|m| alphabet.intern(&m.name))
            .collect(),
    };

    let mut productions = Vec::with_capacity(file.productions.len());
    let mut rule_of: Vec<Option<u32>> = Vec::new();
    for p in &file.productions {
        let predecessor = alphabet.intern(&p.predecessor.name);
        let successor = p
            .successor
            .iter()
            .map(|m| alphabet.intern(&m.name))
            .collect();
        if rule_of.len() < alphabet.len() {
            rule_of.resize(alphabet.len(), None);
        }
        if let Some(first) = rule_of[predecessor.index()] {
            let first_line = &file.productions[first as usize].span;
            diagnostics.push(Diagnostic::warning(
                "E0301",
                p.span.clone(),
                format!(
                    "this production never applies: the production at byte {} already rewrites '{}'",
                    first_line.start, p.predecessor.name
                ),
            ));
        } else {
            rule_of[predecessor.index()] = Some(productions.len() as u32);
        }
        productions.push(Production {
            label: p.label.clone(),
            predecessor,
            successor,
            span: p.span.clone(),
        });
    }
    rule_of.resize(alphabet.len(), None);

    let model = Model {
        alphabet,
        axiom,
        axiom_span: axiom_span.clone(),
        productions,
        rule_of,
        settings,
    };
    (Some(model), diagnostics)
}

fn number(d: &Directive, diagnostics: &mut Vec<Diagnostic>) -> Option<f64> {
    match d.args.parse::<f64>() {
        Ok(v) if v.is_finite() => Some(v),
        _ => {
            diagnostics.push(Diagnostic::error(
                "E0203",
                if d.args.is_empty() {
                    d.name_span.clone()
                } else {
                    d.args_span.clone()
                },
                format!("#{} needs a number, found '{}'", d.name, d.args),
            ));
            None
        }
    }
}

fn whole(d: &Directive, max: u64, diagnostics: &mut Vec<Diagnostic>) -> Option<u64> {
    match d.args.parse::<u64>() {
        Ok(v) if v <= max => Some(v),
        _ => {
            diagnostics.push(Diagnostic::error(
                "E0204",
                if d.args.is_empty() {
                    d.name_span.clone()
                } else {
                    d.args_span.clone()
                },
                format!(
                    "#{} needs a whole number from 0 to {max}, found '{}'",
                    d.name, d.args
                ),
            ));
            None
        }
    }
}
