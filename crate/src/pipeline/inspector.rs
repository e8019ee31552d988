//! Questions about a build's derivation: why a production fired in the last step (the studio's
//! context-sensitivity view), and the derived string's text, module by module.

use crate::derive::{
    self, Derivation, DeriveOptions, LastStep, MatchReport, TracedStep, NOT_REWRITTEN,
};
use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model};

/// A build's model and derivation, read-only.
#[derive(Clone, Debug)]
pub struct Inspector<'b> {
    model: &'b Model,
    derivation: &'b Derivation,
    options: DeriveOptions,
}

/// [`derive::Explanation`] in terms of the derived string: which of its modules production `p`
/// made in the last step, and which descend from the modules that served as its contexts.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Explained {
    pub explanation: derive::Explanation,
    /// Modules of the derived string the production wrote in the last step.
    pub produced: Vec<u32>,
    /// Modules of the derived string that descend from a left / right context module of those
    /// rewritings.
    pub left: Vec<u32>,
    pub right: Vec<u32>,
}

impl<'b> Inspector<'b> {
    pub fn new(model: &'b Model, derivation: &'b Derivation, options: DeriveOptions) -> Self {
        Inspector {
            model,
            derivation,
            options,
        }
    }

    /// The whole derivation, step 0 (the axiom) to the last, when the strings of all its steps
    /// hold `max_modules` modules or fewer together; `None` when they do not (or without steps to
    /// show). It derives again, recording every step.
    pub fn sequence(&self, max_modules: usize) -> Option<Result<Vec<TracedStep>, Diagnostic>> {
        if self.derivation.string.len() > max_modules {
            return None;
        }
        let traced = match super::observer::trace(self.model, &self.options) {
            Ok(steps) => steps,
            Err(e) => return Some(Err(e)),
        };
        let total: usize = traced.iter().map(|s| s.string.len()).sum();
        (total <= max_modules).then_some(Ok(traced))
    }

    /// The lineage of module `module` of the derived string, the last step first, back to the
    /// axiom ([`super::lineage()`]).
    pub fn lineage(&self, module: usize) -> Result<Vec<super::LineageRow>, Diagnostic> {
        super::lineage(self.model, &self.options, module)
    }

    /// The text of modules `start .. start + count` of the string the last step read (clamped).
    pub fn previous_texts(&self, start: usize, count: usize) -> Vec<String> {
        texts(self.model, &self.derivation.previous, start, count)
    }

    /// The text of each module of `string` (a string of this grammar, e.g. a traced step's).
    pub fn texts_of(&self, string: &LString) -> Vec<String> {
        texts(self.model, string, 0, string.len())
    }

    /// Modules in the derived string.
    pub fn module_count(&self) -> usize {
        self.derivation.string.len()
    }

    /// The text of modules `start .. start + count` of the derived string (clamped).
    pub fn module_texts(&self, start: usize, count: usize) -> Vec<String> {
        texts(self.model, &self.derivation.string, start, count)
    }

    /// The derived string, cut after `max_chars` characters with `…` appended when longer.
    pub fn derived_text(&self, max_chars: usize) -> String {
        self.derivation
            .string
            .to_text_truncated(&self.model.alphabet, max_chars)
    }

    /// A fingerprint of the derived string (16 hex digits): equal for equal derivations.
    pub fn derived_hash(&self) -> String {
        format!(
            "{:016x}",
            self.derivation.string.fingerprint(&self.model.alphabet)
        )
    }

    /// Explains production `production` (an index into the model's productions) on the last step:
    /// `None` before any step.
    pub fn explain(&self, production: u32) -> Option<Result<Explained, Diagnostic>> {
        self.explain_where(production, None)
    }

    /// Explains how module `module` of the derived string was made: the production that wrote it
    /// and the contexts of that one rewriting (`produced` is then every module that rewriting
    /// wrote). `None` when it was copied or before any step.
    pub fn explain_module(&self, module: usize) -> Option<Result<Explained, Diagnostic>> {
        let d = self.derivation;
        let production = *d.origin().get(module)?;
        if production == NOT_REWRITTEN {
            return None;
        }
        let source = *d.parent().get(module)? as usize;
        let mut explained = self.explain_where(production, Some(source))?;
        if let Ok(e) = &mut explained {
            e.produced
                .retain(|&j| d.parent()[j as usize] as usize == source);
        }
        Some(explained)
    }

    /// The last step, as the explanations read it.
    fn last_step(&self) -> LastStep<'b> {
        let d = self.derivation;
        LastStep {
            model: self.model,
            previous: &d.previous,
            origin: d.origin(),
            parent: d.parent(),
            steps: self.options.steps,
        }
    }

    /// Why production `production` did or did not rewrite the module of the last step's string
    /// that module `module` of the derived string comes from. `None` before any step.
    pub fn match_report(
        &self,
        production: u32,
        module: usize,
    ) -> Option<Result<MatchReport, Diagnostic>> {
        let source = *self.derivation.parent().get(module)? as usize;
        Some(derive::match_report(self.last_step(), production, source))
    }

    fn explain_where(
        &self,
        production: u32,
        only: Option<usize>,
    ) -> Option<Result<Explained, Diagnostic>> {
        let d = self.derivation;
        if d.parent().is_empty() {
            return None;
        }
        let explanation = derive::explain(self.last_step(), production, only);
        Some(explanation.map(|e| self.in_derived_string(e)))
    }

    /// An explanation in terms of the derived string: the modules the production wrote, and those
    /// that descend from its context modules.
    fn in_derived_string(&self, explanation: derive::Explanation) -> Explained {
        let d = self.derivation;
        let mut is_left = vec![false; d.previous.len()];
        let mut is_right = vec![false; d.previous.len()];
        explanation
            .left
            .iter()
            .for_each(|&i| is_left[i as usize] = true);
        explanation
            .right
            .iter()
            .for_each(|&i| is_right[i as usize] = true);
        let mut explained = Explained::default();
        for (j, (&o, &p)) in d.origin().iter().zip(d.parent()).enumerate() {
            if o == explanation.production {
                explained.produced.push(j as u32);
            }
            if is_left[p as usize] {
                explained.left.push(j as u32);
            }
            if is_right[p as usize] {
                explained.right.push(j as u32);
            }
        }
        explained.explanation = explanation;
        explained
    }
}

/// The text of modules `start .. start + count` of `s` (clamped).
fn texts(model: &Model, s: &LString, start: usize, count: usize) -> Vec<String> {
    let end = start.saturating_add(count).min(s.len());
    (start.min(end)..end)
        .map(|i| s.module_text(&model.alphabet, i))
        .collect()
}
