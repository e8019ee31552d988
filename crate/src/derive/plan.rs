//! Planned steps: when the observer plans a step (the growth attributes decide which apices stop
//! and how often each grows), each module is rewritten as many times as the plan says.

use super::rewriter::{Pass, Rewriter};
use super::{check_size, context};
use crate::diagnostics::Diagnostic;
use crate::model::{LString, RuleSet};

impl<R: rand::Rng> Rewriter<'_, R> {
    /// Rewrites module `i` of `src` as the step's plan says: not at all (a stopped or resting
    /// apex), once, or several times (`#speed` of the growth attributes).
    pub(super) fn rewrite_planned(
        &mut self,
        pass: &Pass<'_>,
        i: usize,
        dst: &mut LString,
    ) -> Result<Option<u32>, Diagnostic> {
        let src = pass.src;
        let times = self
            .plan
            .as_ref()
            .map_or(1, |plan| plan.get(i).copied().unwrap_or(1));
        match times {
            0 => {
                dst.push(src.ids[i], src.params_of(i));
                Ok(None)
            }
            1 => self.rewrite_module(pass, i, dst),
            _ => self.rewrite_repeatedly(pass, i, dst, times),
        }
    }

    /// Rewrites module `i` of `src` `times` times within this step, like `@Repeat` on that one
    /// module (the growth attributes' `#speed`). The first rewriting sees the whole string's
    /// contexts, the later ones only the module's own successor; nothing more happens when no
    /// production applies.
    fn rewrite_repeatedly(
        &mut self,
        pass: &Pass<'_>,
        i: usize,
        dst: &mut LString,
        times: u32,
    ) -> Result<Option<u32>, Diagnostic> {
        let Pass { rules, num_it, .. } = *pass;
        let mut current = LString::default();
        current.clear(self.model.parametric);
        let applied = self.rewrite_module(pass, i, &mut current)?;
        if applied.is_some() && times > 1 {
            current =
                self.derive_apart(rules, current, times - 1, num_it, (dst.len(), dst.bytes()))?;
        }
        dst.extend_from(&current);
        Ok(applied)
    }

    /// Derives `current` `times` more times on its own within step `num_it`: its contexts are its
    /// own, and the step's tracking and plan do not reach inside (what `@Repeat` and repeated
    /// rewritings do). `outside`: the modules and bytes already written, which count against the limits.
    pub(super) fn derive_apart(
        &mut self,
        rules: &RuleSet,
        mut current: LString,
        times: u32,
        num_it: u32,
        outside: (usize, usize),
    ) -> Result<LString, Diagnostic> {
        let model = self.model;
        let plan = self.plan.take();
        let tracker = self.tracker.take();
        let saved = std::mem::take(&mut self.partner);
        let mut next = LString::default();
        for _ in 0..times {
            if rules.has_contexts() {
                context::bracket_partners(model, &current, &mut self.partner);
            }
            next.clear(model.parametric);
            let len = current.len();
            self.rewrite_range(
                &Pass {
                    rules,
                    src: &current,
                    num_it,
                },
                0..len,
                &mut next,
            )?;
            std::mem::swap(&mut current, &mut next);
            check_size(
                model,
                num_it,
                outside.0 + current.len(),
                outside.1 + current.bytes(),
            )?;
        }
        self.partner = saved;
        self.tracker = tracker;
        self.plan = plan;
        Ok(current)
    }
}
