//! Green's control modules (LANGUAGE.md section 7): `@Switch`, `@Pendulum` and `@Repeat` groups,
//! which sit in the string as `header @< member @| member @>`.

use super::rewriter::{Pass, Rewriter};
use super::NOT_REWRITTEN;
use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model, SuccessorModule};
use crate::syntax::{Span, MAX_GROUP_DEPTH};
use std::ops::Range;

/// How many `@Repeat` rewritings a derivation may run for each step `#max_steps` allows: the
/// derivation stops with `E0405` past `#max_steps` × this (a million by default).
pub const REPEATS_PER_STEP: u64 = 100;

/// A control module group in the string being rewritten.
struct Group {
    /// Where its header is.
    at: usize,
    /// The header's parameter: the switch's cursor, the pendulum's orientation, the repeat count.
    header: f64,
    /// The members: the ranges between the group's own separators.
    members: Vec<Range<usize>>,
    /// Where its closing marker is.
    end: usize,
}

/// The group whose header is at `i`.
fn group_at(src: &LString, i: usize, groups: &crate::model::GroupIds) -> Group {
    let mut members = Vec::new();
    let mut depth = 0usize;
    let mut start = i + 2;
    let mut end = src.len();
    for k in i + 2..src.len() {
        let id = src.ids[k];
        if id == groups.open {
            depth += 1;
        } else if id == groups.close {
            if depth == 0 {
                end = k;
                break;
            }
            depth -= 1;
        } else if id == groups.separator && depth == 0 {
            members.push(start..k);
            start = k + 1;
        }
    }
    members.push(start..end);
    Group {
        at: i,
        header: src.params_of(i).first().copied().unwrap_or(0.0),
        members,
        end,
    }
}

impl<R: rand::Rng> Rewriter<'_, R> {
    /// Derives the control module group whose header is at `i` (LANGUAGE.md section 7) and returns
    /// the index just after its closing marker.
    pub(super) fn rewrite_group(
        &mut self,
        pass: &Pass<'_>,
        i: usize,
        dst: &mut LString,
    ) -> Result<usize, Diagnostic> {
        let num_it = pass.num_it;
        if self.group_depth >= MAX_GROUP_DEPTH {
            return Err(Diagnostic::error(
                "E0404",
                group_span(self.model, |_| true),
                format!(
                    "control modules nested more than {MAX_GROUP_DEPTH} deep at step {num_it}: the \
                     productions write groups inside groups (one whose members write it again \
                     never ends)"
                ),
            ));
        }
        self.group_depth += 1;
        let end = self.rewrite_group_members(pass, i, dst);
        self.group_depth -= 1;
        end
    }

    /// [`Rewriter::rewrite_group`] one level down.
    fn rewrite_group_members(
        &mut self,
        pass: &Pass<'_>,
        i: usize,
        dst: &mut LString,
    ) -> Result<usize, Diagnostic> {
        let src = pass.src;
        let g = self.model.groups;
        let group = group_at(src, i, &g);
        let end = group.end;
        let id = src.ids[i];
        if id == g.switch {
            self.switch(pass, group, dst)?;
        } else if id == g.pendulum {
            self.pendulum(pass, group, dst)?;
        } else {
            self.repeat(pass, group, dst)?;
        }
        dst.push(g.close, &[]);
        Ok((end + 1).min(src.len()))
    }

    /// Writes the group's header with its new value and the opening marker.
    fn open_group(&mut self, src: &LString, i: usize, value: f64, dst: &mut LString) {
        dst.push(src.ids[i], &[value]);
        dst.push(self.model.groups.open, &[]);
        self.note(dst.len(), i, NOT_REWRITTEN);
    }

    /// The separator between members `k - 1` and `k`.
    fn separate(&mut self, k: usize, i: usize, dst: &mut LString) {
        if k > 0 {
            dst.push(self.model.groups.separator, &[]);
            self.note(dst.len(), i, NOT_REWRITTEN);
        }
    }

    /// `@Switch(A B C)`: only the member under the cursor is rewritten; the cursor moves on.
    fn switch(
        &mut self,
        pass: &Pass<'_>,
        group: Group,
        dst: &mut LString,
    ) -> Result<(), Diagnostic> {
        let src = pass.src;
        let (i, n) = (group.at, group.members.len());
        let cursor = (group.header.max(0.0) as usize) % n;
        self.open_group(src, i, ((cursor + 1) % n) as f64, dst);
        for (k, member) in group.members.into_iter().enumerate() {
            self.separate(k, i, dst);
            if k == cursor {
                self.rewrite_range(pass, member, dst)?;
            } else {
                for j in member {
                    dst.push(src.ids[j], src.params_of(j));
                    self.note(dst.len(), j, NOT_REWRITTEN);
                }
            }
        }
        Ok(())
    }

    /// `@Pendulum(A B C)`: every member is rewritten, in the written order on odd steps and
    /// reversed on even ones.
    fn pendulum(
        &mut self,
        pass: &Pass<'_>,
        group: Group,
        dst: &mut LString,
    ) -> Result<(), Diagnostic> {
        let Pass { src, num_it, .. } = *pass;
        let (i, mut members) = (group.at, group.members);
        let reversed = if num_it.is_multiple_of(2) { 1.0 } else { 0.0 };
        if reversed != group.header {
            members.reverse();
        }
        self.open_group(src, i, reversed, dst);
        for (k, member) in members.into_iter().enumerate() {
            self.separate(k, i, dst);
            self.rewrite_range(pass, member, dst)?;
        }
        Ok(())
    }

    /// `@Repeat(k, A B)`: the enclosed string is derived k times within this step. The k inner
    /// derivations are not tracked: their modules count as the group's.
    fn repeat(
        &mut self,
        pass: &Pass<'_>,
        group: Group,
        dst: &mut LString,
    ) -> Result<(), Diagnostic> {
        let Pass { rules, src, num_it } = *pass;
        let i = group.at;
        let times = group.header.max(0.0) as u32;
        self.repeat_passes += u64::from(times);
        let budget = u64::from(self.model.settings.max_steps) * REPEATS_PER_STEP;
        if self.repeat_passes > budget {
            let repeat = self.model.groups.repeat;
            return Err(Diagnostic::error(
                "E0405",
                group_span(self.model, |s| s.id == repeat),
                format!(
                    "@Repeat groups asked for more than {budget} rewritings by step {num_it} \
                     ({REPEATS_PER_STEP} for each of '#max_steps {}'); use smaller counts, fewer \
                     iterations, or raise #max_steps",
                    self.model.settings.max_steps
                ),
            ));
        }
        self.open_group(src, i, group.header, dst);
        let mut enclosed = LString::default();
        enclosed.clear(src.is_parametric());
        for j in group.members[0].clone() {
            enclosed.push(src.ids[j], src.params_of(j));
        }
        let derived =
            self.derive_apart(rules, enclosed, times, num_it, (dst.len(), dst.bytes()))?;
        dst.extend_from(&derived);
        self.note(dst.len(), i, NOT_REWRITTEN);
        Ok(())
    }

    /// `E0405` for a `@Repeat` count above `#max_steps`, at the count.
    pub(super) fn check_repeat_count(
        &self,
        count: f64,
        module: &SuccessorModule,
    ) -> Result<(), Diagnostic> {
        let max = self.model.settings.max_steps;
        if count <= f64::from(max) {
            return Ok(());
        }
        let span = module
            .args
            .first()
            .map_or_else(|| module.span.clone(), |k| k.span.clone());
        Err(Diagnostic::error(
            "E0405",
            span,
            format!(
                "@Repeat count {} is above the step limit {max}; use a smaller count or raise \
                 '#max_steps N'",
                crate::number::Decimal(count)
            ),
        ))
    }
}

/// Where the first control module `wanted` accepts is written (in a production, else the axiom):
/// where an error of the groups while deriving points.
fn group_span(model: &Model, wanted: impl Fn(&SuccessorModule) -> bool) -> Span {
    let is_group = |s: &&SuccessorModule| s.group.is_some() && wanted(s);
    model
        .productions
        .productions
        .iter()
        .flat_map(|p| p.successor.iter())
        .chain(model.axiom.iter())
        .find(is_group)
        .map_or_else(|| model.axiom_span.clone(), |s| s.span.clone())
}
