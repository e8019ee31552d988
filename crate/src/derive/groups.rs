//! Green's control modules (LANGUAGE.md section 7): `@Switch`, `@Pendulum` and `@Repeat` groups,
//! which sit in the string as `header @< member @| member @>`.

use super::rewriter::Rewriter;
use super::{context, limit_error, NOT_REWRITTEN};
use crate::diagnostics::Diagnostic;
use crate::model::{LString, RuleSet};

impl<R: rand::Rng> Rewriter<'_, R> {
    /// Derives the control module group whose header is at `i` (LANGUAGE.md section 7) and returns
    /// the index just after its closing marker.
    pub(super) fn rewrite_group(
        &mut self,
        rules: &RuleSet,
        src: &LString,
        i: usize,
        dst: &mut LString,
        num_it: u32,
    ) -> Result<usize, Diagnostic> {
        let g = self.model.groups;
        // Members: the ranges between the group's own separators.
        let mut members = Vec::new();
        let mut depth = 0usize;
        let mut start = i + 2;
        let mut end = src.len();
        for k in i + 2..src.len() {
            let id = src.ids[k];
            if id == g.open {
                depth += 1;
            } else if id == g.close {
                if depth == 0 {
                    end = k;
                    break;
                }
                depth -= 1;
            } else if id == g.separator && depth == 0 {
                members.push(start..k);
                start = k + 1;
            }
        }
        members.push(start..end);
        let id = src.ids[i];
        let header = src.params_of(i).first().copied().unwrap_or(0.0);
        let n = members.len();
        let write_header = |dst: &mut LString, value: f64| dst.push(id, &[value]);
        if id == g.switch {
            let cursor = (header.max(0.0) as usize) % n;
            write_header(dst, ((cursor + 1) % n) as f64);
            dst.push(g.open, &[]);
            self.note(dst.len(), i, NOT_REWRITTEN);
            for (k, member) in members.into_iter().enumerate() {
                if k > 0 {
                    dst.push(g.separator, &[]);
                    self.note(dst.len(), i, NOT_REWRITTEN);
                }
                if k == cursor {
                    self.rewrite_range(rules, src, member, dst, num_it)?;
                } else {
                    for j in member {
                        dst.push(src.ids[j], src.params_of(j));
                        self.note(dst.len(), j, NOT_REWRITTEN);
                    }
                }
            }
        } else if id == g.pendulum {
            // As written on odd steps, reversed on even ones.
            let reversed = if num_it.is_multiple_of(2) { 1.0 } else { 0.0 };
            if reversed != header {
                members.reverse();
            }
            write_header(dst, reversed);
            dst.push(g.open, &[]);
            self.note(dst.len(), i, NOT_REWRITTEN);
            for (k, member) in members.into_iter().enumerate() {
                if k > 0 {
                    dst.push(g.separator, &[]);
                    self.note(dst.len(), i, NOT_REWRITTEN);
                }
                self.rewrite_range(rules, src, member, dst, num_it)?;
            }
        } else {
            // @Repeat(k): the enclosed string is derived k times within this step.
            let times = header.max(0.0) as u32;
            write_header(dst, header);
            dst.push(g.open, &[]);
            self.note(dst.len(), i, NOT_REWRITTEN);
            // The k inner derivations are not tracked: their modules count as the group's. The
            // growth plan names modules of the step's string, not of the group's.
            let tracker = self.tracker.take();
            let plan = self.plan.take();
            let member = members.swap_remove(0);
            let mut current = LString::default();
            current.clear(src.is_parametric());
            for j in member {
                current.push(src.ids[j], src.params_of(j));
            }
            let mut next = LString::default();
            let saved = std::mem::take(&mut self.partner);
            for _ in 0..times {
                if rules.has_contexts() {
                    context::bracket_partners(self.model, &current, &mut self.partner);
                }
                next.clear(current.is_parametric());
                let len = current.len();
                self.rewrite_range(rules, &current, 0..len, &mut next, num_it)?;
                std::mem::swap(&mut current, &mut next);
                if current.len() > self.model.settings.max_modules {
                    return Err(limit_error(self.model, num_it, current.len()));
                }
            }
            self.partner = saved;
            self.tracker = tracker;
            self.plan = plan;
            for j in 0..current.len() {
                dst.push(current.ids[j], current.params_of(j));
            }
            self.note(dst.len(), i, NOT_REWRITTEN);
        }
        dst.push(g.close, &[]);
        Ok((end + 1).min(src.len()))
    }
}
