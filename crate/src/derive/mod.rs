//! Stage 3, `derive`: parallel rewriting of the string, step by step.
//!
//! Every module of step k is rewritten from the string of step k (two buffers, swapped). The
//! length of the next string is computed before it is written, so the module limit stops a
//! derivation before it allocates.

use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model, ModuleId};

/// What one derivation does.
#[derive(Clone, Debug)]
pub struct DeriveOptions {
    pub steps: u32,
}

/// The productions in the flat form the rewriting loop reads: for each module id, the range of its
/// successor in one shared array, or `None` to copy the module.
struct RuleTable {
    successors: Vec<ModuleId>,
    rule_of: Vec<Option<(u32, u32)>>,
}

impl RuleTable {
    fn new(model: &Model) -> Self {
        let mut successors = Vec::new();
        let rule_of = model
            .rule_of
            .iter()
            .map(|rule| {
                rule.map(|p| {
                    let start = successors.len() as u32;
                    successors.extend_from_slice(&model.productions[p as usize].successor);
                    (start, successors.len() as u32)
                })
            })
            .collect();
        RuleTable {
            successors,
            rule_of,
        }
    }

    /// Length of the string that `ids` rewrites to.
    fn next_len(&self, ids: &[ModuleId]) -> usize {
        ids.iter()
            .map(|id| match self.rule_of[id.index()] {
                Some((start, end)) => (end - start) as usize,
                None => 1,
            })
            .sum()
    }

    fn rewrite(&self, src: &[ModuleId], dst: &mut Vec<ModuleId>) {
        for &id in src {
            match self.rule_of[id.index()] {
                Some((start, end)) => {
                    dst.extend_from_slice(&self.successors[start as usize..end as usize])
                }
                None => dst.push(id),
            }
        }
    }
}

/// Derives `options.steps` steps from the model's axiom. Hitting the module limit is an error
/// diagnostic that names the limit, the step and how to raise it.
pub fn derive(model: &Model, options: &DeriveOptions) -> Result<LString, Diagnostic> {
    let table = RuleTable::new(model);
    let max = model.settings.max_modules;
    if model.axiom.len() > max {
        return Err(limit_error(model, 0, model.axiom.len()));
    }
    let mut current = model.axiom.ids.clone();
    let mut next = Vec::new();
    for step in 1..=options.steps {
        let len = table.next_len(&current);
        if len > max {
            return Err(limit_error(model, step, len));
        }
        next.clear();
        next.reserve(len);
        table.rewrite(&current, &mut next);
        std::mem::swap(&mut current, &mut next);
    }
    Ok(LString { ids: current })
}

fn limit_error(model: &Model, step: u32, len: usize) -> Diagnostic {
    let max = model.settings.max_modules;
    let span = model
        .settings
        .iterations_span
        .clone()
        .unwrap_or_else(|| model.axiom_span.clone());
    Diagnostic::error(
        "E0400",
        span,
        format!(
            "step {step} would make a string of {len} modules, more than the limit of {max}; \
             use fewer iterations or raise the limit with '#max_modules {}'",
            len.max(max.saturating_mul(2))
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{model, syntax};

    fn derive_text(src: &str, steps: u32) -> Result<String, Diagnostic> {
        let (file, diags) = syntax::parse(src);
        assert!(diags.is_empty(), "{diags:?}");
        let (model, diags) = model::resolve(&file);
        assert!(diags.is_empty(), "{diags:?}");
        let model = model.expect("model");
        derive(&model, &DeriveOptions { steps }).map(|s| s.to_text(&model.alphabet))
    }

    #[test]
    fn rewriting_is_parallel() {
        assert_eq!(derive_text("axiom: AB\nA -> B\nB -> AB", 1).unwrap(), "BAB");
        assert_eq!(
            derive_text("axiom: AB\nA -> B\nB -> AB", 2).unwrap(),
            "ABBAB"
        );
    }

    #[test]
    fn abop_1_24a_has_5_to_the_n_segments() {
        let s = derive_text("axiom: F\nF -> F[+F]F[-F]F", 5).unwrap();
        assert_eq!(s.matches('F').count(), 5usize.pow(5));
    }

    #[test]
    fn the_module_limit_stops_cleanly_and_says_how_to_raise_it() {
        let err = derive_text("#max_modules 1000\naxiom: F\nF -> FF", 20).unwrap_err();
        assert_eq!(err.code, "E0400");
        assert!(
            err.message
                .contains("step 10 would make a string of 1024 modules"),
            "{}",
            err.message
        );
        assert!(err.message.contains("#max_modules"));
    }
}
