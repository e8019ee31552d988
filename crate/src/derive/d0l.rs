//! The D0L path: a flat table from module id to successor, for grammars whose productions have no
//! parameters, contexts, conditions or weights. The next length is computed before writing, and
//! nothing is allocated per module.

use super::classes::{put, PAD};
use super::{check_size, memory_error, NOT_REWRITTEN};
use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model, ModuleId};

/// The D0L path: usable when no production has parameters, contexts, conditions or weights.
pub(super) struct D0lTable {
    /// Every successor's ids, back to back, then [`PAD`] ids of padding for [`put`].
    successors: Vec<ModuleId>,
    rule_of: Vec<Option<(u32, u32)>>,
    /// For each module id, the production that rewrites it ([`NOT_REWRITTEN`] if none).
    production_of: Vec<u32>,
}

impl D0lTable {
    pub(super) fn new(model: &Model) -> Option<Self> {
        let rules = &model.productions;
        let simple = !model.parametric
            && rules
                .productions
                .iter()
                .all(|p| !p.has_context() && p.condition.is_none() && p.weight.is_none());
        if !simple {
            return None;
        }
        let mut successors = Vec::new();
        let rule_of = rules
            .by_predecessor
            .iter()
            .map(|candidates| {
                candidates.first().map(|&p| {
                    let start = successors.len() as u32;
                    successors.extend(rules.productions[p as usize].successor.iter().map(|s| s.id));
                    (start, successors.len() as u32)
                })
            })
            .collect();
        successors.extend(std::iter::repeat_n(ModuleId(0), PAD));
        let production_of = rules
            .by_predecessor
            .iter()
            .map(|c| c.first().copied().unwrap_or(NOT_REWRITTEN))
            .collect();
        Some(D0lTable {
            successors,
            rule_of,
            production_of,
        })
    }

    /// [`D0lTable::step`], returning for each written module the production that made it.
    pub(super) fn step_tracked(
        &self,
        model: &Model,
        src: &LString,
        dst: &mut LString,
        step: u32,
    ) -> Result<(Vec<u32>, Vec<u32>), Diagnostic> {
        self.step(model, src, dst, step)?;
        let mut origin = Vec::with_capacity(dst.len());
        let mut parent = Vec::with_capacity(dst.len());
        for (i, &id) in src.ids.iter().enumerate() {
            match self.rule_of[id.index()] {
                Some((start, end)) => {
                    let production = self.production_of[id.index()];
                    origin.extend(std::iter::repeat_n(production, (end - start) as usize));
                    parent.extend(std::iter::repeat_n(i as u32, (end - start) as usize));
                }
                None => {
                    origin.push(NOT_REWRITTEN);
                    parent.push(i as u32);
                }
            }
        }
        Ok((origin, parent))
    }

    pub(super) fn step(
        &self,
        model: &Model,
        src: &LString,
        dst: &mut LString,
        step: u32,
    ) -> Result<(), Diagnostic> {
        let len: usize = src
            .ids
            .iter()
            .map(|id| match self.rule_of[id.index()] {
                Some((start, end)) => (end - start) as usize,
                None => 1,
            })
            .sum();
        check_size(model, step, len, len.saturating_mul(size_of::<ModuleId>()))?;
        dst.clear(false);
        if dst.ids.capacity() < len + PAD {
            // A new buffer: growing the old one would copy what it held.
            let mut fresh = Vec::new();
            if fresh.try_reserve_exact(len + PAD).is_err() {
                return Err(memory_error(model, step, len, len * size_of::<ModuleId>()));
            }
            dst.ids = fresh;
        }
        for &id in &src.ids {
            match self.rule_of[id.index()] {
                Some((start, end)) => put(
                    &mut dst.ids,
                    &self.successors,
                    start as usize,
                    (end - start) as usize,
                ),
                None => dst.ids.push(id),
            }
        }
        Ok(())
    }
}
