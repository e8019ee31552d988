//! Timed modules (ABOP section 6.1): `#terminal_age` and `#dt` read, and every place a timed
//! module is written checked: its first parameter is its age, and a constant initial age lies
//! from 0 up to (not including) its terminal age.

use super::directives::{words, DirectiveValues};
use super::Resolver;
use crate::diagnostics::Diagnostic;
use crate::model::{ModuleId, RuleSet, Settings, SuccessorModule};
use crate::number::Decimal;
use crate::syntax::{Directive, SourceFile, Span};
use crate::vocabulary::DirectiveKind;

/// The value of the last `#dt` when it is written as a plain number: read before anything is
/// compiled, since expressions fold `dt` to it. `#dt` itself is checked with the directives.
pub(super) fn written_dt(file: &SourceFile) -> Option<f64> {
    let d = file
        .directives
        .iter()
        .rev()
        .find(|d| d.kind == Some(DirectiveKind::Dt))?;
    crate::number::parse_f64(&d.args).filter(|v| v.is_finite() && *v > 0.0)
}

impl Resolver {
    /// `#terminal_age a 2 b 1`: pairs of a module name and a terminal age of 10^-6 or more
    /// (`E0211`).
    pub(super) fn terminal_ages(&mut self, d: &Directive, s: &mut Settings) {
        let words = words(d);
        if words.is_empty() || !words.len().is_multiple_of(2) {
            let message = format!(
                "{} needs pairs of a module name and its terminal age (a_r 2 b_r 1), found {} \
                 words",
                d.written,
                words.len()
            );
            self.directive_error("E0211", d, message);
            return;
        }
        s.terminal_age_span
            .get_or_insert(d.name_span.start..d.args_span.end);
        for pair in words.chunks(2) {
            let (name, age) = (&pair[0], &pair[1]);
            let Some(value) = self.number(age) else {
                continue;
            };
            // Below a millionth the clock cannot tell its moments apart (it takes times 10^-9
            // apart as one and keeps ages to 12 decimals): 1e-9 was never reached, silently.
            if value < 1e-6 {
                let message = format!(
                    "{} {}: a terminal age must be at least 0.000001, found {}",
                    d.written,
                    name.args,
                    Decimal(value)
                );
                self.directive_error("E0211", age, message);
                continue;
            }
            let id = self.alphabet.intern(&name.args);
            if s.terminal_ages.iter().any(|&(other, _)| other == id) {
                let message = format!("{} gives '{}' a second terminal age", d.written, name.args);
                self.directive_error("E0211", name, message);
                continue;
            }
            s.terminal_ages.push((id, value));
        }
    }

    /// `#dt`: a time above 0 (`E0211`).
    pub(super) fn dt_directive(&mut self, d: &Directive, s: &mut Settings) {
        let Some(value) = self.number(d) else {
            return;
        };
        if value > 0.0 {
            s.dt = value;
            s.dt_given = true;
        } else {
            let message = format!(
                "{} must be above 0, found {}",
                d.written,
                crate::number::Decimal(value)
            );
            self.directive_error("E0211", d, message);
        }
    }

    /// Every timed module is written with its age first (`E0212`) and a constant initial age
    /// from 0 to below its terminal age (`E0213`).
    pub(super) fn check_timed(
        &mut self,
        values: &DirectiveValues,
        axiom: &[SuccessorModule],
        sets: [&RuleSet; 3],
    ) {
        let settings = &values.settings;
        if settings.terminal_ages.is_empty() {
            return;
        }
        if values.growth.is_active() {
            self.diagnostics.push(Diagnostic::error(
                "E0214",
                settings.terminal_age_span.clone().unwrap_or(0..0),
                format!(
                    "{} does not combine with the growth attributes ({} and the others): both \
                     decide when modules grow",
                    DirectiveKind::TerminalAge.written(),
                    DirectiveKind::Lifetime.written()
                ),
            ));
        }
        let terminal = |id: ModuleId| {
            settings
                .terminal_ages
                .iter()
                .find(|(t, _)| *t == id)
                .map(|t| t.1)
        };
        self.check_written(axiom, &terminal);
        for set in sets {
            for p in &set.productions {
                self.check_written(&p.successor, &terminal);
                for m in p.left.iter().chain([&p.predecessor]) {
                    if m.arity == 0 && terminal(m.id).is_some() {
                        self.ageless(m.id, m.span.clone());
                    }
                }
            }
        }
    }

    fn check_written(
        &mut self,
        modules: &[SuccessorModule],
        terminal: &dyn Fn(ModuleId) -> Option<f64>,
    ) {
        for m in modules {
            if let Some(group) = &m.group {
                for member in group {
                    self.check_written(member, terminal);
                }
            }
            let Some(beta) = terminal(m.id) else { continue };
            let Some(age) = m.args.first() else {
                self.ageless(m.id, m.span.clone());
                continue;
            };
            if let Some(alpha) = age.constant().filter(|a| !(*a >= 0.0 && *a < beta)) {
                let name = self.alphabet.name(m.id).to_string();
                self.diagnostics.push(Diagnostic::error(
                    "E0213",
                    m.span.clone(),
                    format!(
                        "'{name}' starts at age {}: an initial age must be from 0 to below its \
                         terminal age {}",
                        Decimal(alpha),
                        Decimal(beta)
                    ),
                ));
            }
        }
    }

    /// `E0212`: a timed module written without its age.
    fn ageless(&mut self, id: ModuleId, span: Span) {
        let name = self.alphabet.name(id).to_string();
        self.diagnostics.push(Diagnostic::error(
            "E0212",
            span,
            format!(
                "'{name}' is a timed module ({}): write its age as its first parameter, \
                 {name}(0)",
                DirectiveKind::TerminalAge.written()
            ),
        ));
    }
}
