//! The module classes' pass: the productions section of a grammar without parameters or control
//! modules, unplanned, each module rewritten as its class says ([`super::module_classes`]): by
//! table, by one draw, by comparing its neighbours, or by the general path.

use super::context;
use super::module_classes::{self, ModuleClass, ModuleClasses, ModuleKind};
use super::rewriter::{Pass, Rewriter};
use super::successors::{self, PAD};
use super::{check_size, MAX_STRING_BYTES, NOT_REWRITTEN};
use crate::diagnostics::Diagnostic;
use crate::model::{LString, ModuleId};
use rand::RngExt;

impl<R: rand::Rng> Rewriter<'_, R> {
    /// [`Rewriter::rewrite_range`] over the whole string, each module as its class says: the
    /// productions section of a grammar without parameters or control modules, unplanned.
    /// `scratch`: the right neighbours and a stack.
    #[inline(never)]
    pub(super) fn rewrite_by_class(
        &mut self,
        c: &ModuleClasses,
        pass: &Pass<'_>,
        dst: &mut LString,
        (right, stack): (&mut Vec<u32>, &mut Vec<u32>),
    ) -> Result<bool, Diagnostic> {
        let tracking = self.tracker.is_some();
        let nested = c.neighbours
            && !c.flat
            && module_classes::right_neighbours(&c.classes, pass.src, right, stack);
        if c.sized && !tracking && !nested {
            if let Some(changed) = self.rewrite_sized(c, pass, dst) {
                return Ok(changed);
            }
        }
        let right = if nested { &right[..] } else { &[][..] };
        self.rewrite_each(c, pass, dst, right, stack)
    }

    /// [`Rewriter::rewrite_by_class`] module by module: `right` holds each module's right
    /// neighbour when the string is nested (empty when the neighbours are the modules next to
    /// each other). A function of its own, and one copy of a successor for every kind but the
    /// general one ([`Rewriter::successor_of`]): V8 spills this loop's values less so. With the
    /// loop inside `rewrite_by_class` beside the sized passes' set-up, Hogeweg-Hesper (1.31a, n =
    /// 30) derived about 20% slower, and with a copy in each arm 5% (measured 2026-11-29,
    /// docs/notes/performance-history.md).
    #[inline(never)]
    fn rewrite_each(
        &mut self,
        c: &ModuleClasses,
        pass: &Pass<'_>,
        dst: &mut LString,
        right: &[u32],
        stack: &mut Vec<u32>,
    ) -> Result<bool, Diagnostic> {
        let Pass { src, num_it, .. } = *pass;
        let model = self.model;
        // Past either limit, check_size says which (a string without parameters: 4 bytes a module).
        let max = (model.settings.max_modules).min(MAX_STRING_BYTES / size_of::<ModuleId>());
        let tracking = self.tracker.is_some();
        let nested = !right.is_empty();
        stack.clear();
        let mut last = context::NONE;
        let mut changed = false;
        for (i, &id) in src.ids.iter().enumerate() {
            let class = &c.classes[id.index()];
            let production = if class.kind == ModuleKind::General {
                self.rewrite_module(pass, i, dst)?.unwrap_or(NOT_REWRITTEN)
            } else {
                let right = next_to(src, right, i, nested);
                let (start, len, production) = self.successor_of(c, class, last, right);
                c.put(&mut dst.ids, start, len);
                production
            };
            if production != NOT_REWRITTEN {
                changed = true;
                if dst.len() > max {
                    check_size(model, num_it, dst.len(), dst.bytes())?;
                }
            }
            if tracking {
                self.note(dst.len(), i, production);
            }
            if nested {
                last = module_classes::step_left(class.role, id, last, stack);
            } else {
                last = id.0;
            }
        }
        Ok(changed)
    }

    /// [`Rewriter::rewrite_by_class`] when every class writes a known number of modules, the
    /// string's neighbours are the modules next to each other (no brackets or ignored modules
    /// between them, or no class compares neighbours) and nothing is tracked: the next length is
    /// known first, so the output is allocated once and every module is one copy of a successor.
    /// When no class compares neighbours (every class is Fixed or Choice), the length comes from
    /// the id counts ([`super::fixed_pass::Counts`], carried from the last pass when it wrote
    /// `src`). `None` when the next string passes a limit (the caller's loop says where) or the
    /// successors have no copy width.
    fn rewrite_sized(
        &mut self,
        c: &ModuleClasses,
        pass: &Pass<'_>,
        dst: &mut LString,
    ) -> Option<bool> {
        let Pass { src, num_it, .. } = *pass;
        if !c.neighbours {
            let carried = self.counts.carried;
            let len = c.fixed_len(&src.ids, &mut self.counts, carried);
            self.sized_room(num_it, dst, len, len.saturating_mul(size_of::<ModuleId>()))?;
            let picks = &mut self.counts.picks;
            picks.clear();
            picks.resize(c.alternatives.len(), 0);
            let changed = c.write_fixed(&src.ids, &mut dst.ids, &mut *self.rng, &mut self.counts);
            debug_assert_eq!(dst.len(), len);
            c.carry(&mut self.counts);
            self.counts.len = Some(len);
            return Some(changed);
        }
        let write: fn(&mut Self, &ModuleClasses, &[ModuleId], &mut LString) -> bool = match c.width
        {
            4 => Self::write_flat::<4>,
            8 => Self::write_flat::<8>,
            PAD => Self::write_flat::<{ PAD }>,
            _ => return None,
        };
        let len: usize = if c.unit {
            src.len()
        } else {
            src.ids.iter().map(|id| c.outs[id.index()] as usize).sum()
        };
        self.sized_room(num_it, dst, len, len * size_of::<ModuleId>())?;
        let changed = write(self, c, &src.ids, dst);
        debug_assert_eq!(dst.len(), len);
        Some(changed)
    }

    /// Room in `dst` for the `len` ids (`bytes` bytes) a sized pass writes, and the [`PAD`] ids
    /// its copies write past them; `None` when they pass a limit: the caller's loop says where.
    fn sized_room(&self, num_it: u32, dst: &mut LString, len: usize, bytes: usize) -> Option<()> {
        check_size(self.model, num_it, len, bytes).ok()?;
        if dst.ids.capacity() < len + PAD {
            // A new buffer: growing the old one would copy what it held.
            dst.ids = Vec::with_capacity(len + PAD);
        }
        Some(())
    }

    /// Writes the flat string `ids` into `dst`, each successor copied as `W` ids
    /// ([`ModuleClasses::width`]), in room made for it; returns whether a production applied.
    #[inline(never)]
    fn write_flat<const W: usize>(
        &mut self,
        c: &ModuleClasses,
        ids: &[ModuleId],
        dst: &mut LString,
    ) -> bool {
        let n = ids.len();
        let mut changed = false;
        // A flat string whose modules compare neighbours: a module that is cold (no production
        // rewrites it unless a neighbour is a context) between cold neighbours is copied as it
        // is, in bulk; the others one by one.
        let hot = |k: usize| c.hot[ids[k].index()];
        let mut i = 0;
        while i < n {
            let h = c.next_hot(ids, i);
            let a = if i > 0 && hot(i - 1) { i + 1 } else { i };
            let b = if h < n {
                h.saturating_sub(1).max(a)
            } else {
                n.max(a)
            };
            let stop = (h + 2).min(n).max(b);
            for k in i..a {
                changed |= self.write_flat_one::<W>(c, ids, k, dst);
            }
            dst.ids.extend_from_slice(&ids[a..b]);
            for k in b..stop {
                changed |= self.write_flat_one::<W>(c, ids, k, dst);
            }
            i = stop;
        }
        changed
    }

    /// Writes module `i` of `ids` as its class says, its neighbours being the modules next to
    /// it; returns whether a production applied.
    #[inline(always)]
    fn write_flat_one<const W: usize>(
        &mut self,
        c: &ModuleClasses,
        ids: &[ModuleId],
        i: usize,
        dst: &mut LString,
    ) -> bool {
        let class = &c.classes[ids[i].index()];
        let left = if i > 0 { ids[i - 1].0 } else { context::NONE };
        let right = ids.get(i + 1).map_or(context::NONE, |r| r.0);
        let (start, n, production) = self.successor_of(c, class, left, right);
        successors::put_wide::<W>(&mut dst.ids, &c.successors, start as usize, n as usize);
        production != NOT_REWRITTEN
    }

    /// What a module of `class` writes, its neighbours being `left` and `right`: the successor in
    /// [`ModuleClasses::successors`] (start, length) and the production applied. A general class
    /// (which writes an unknown number of modules) is copied here: its callers rewrite it first.
    #[inline(always)]
    fn successor_of(
        &mut self,
        c: &ModuleClasses,
        class: &ModuleClass,
        left: u32,
        right: u32,
    ) -> (u32, u32, u32) {
        match class.kind {
            ModuleKind::Fixed => (class.start, class.len, class.production),
            ModuleKind::Choice => {
                let a = c.choose(class, self.rng.random::<f64>());
                (a.start, a.len, a.production)
            }
            ModuleKind::Neighbours => match c.neighbours_match(class, left, right) {
                Some(a) => (a.start, a.len, a.production),
                None => (class.own, 1, NOT_REWRITTEN),
            },
            ModuleKind::General => (class.own, 1, NOT_REWRITTEN),
        }
    }
}

/// The right neighbour of module `i`: from `right` when the string is `nested`, else the next
/// module.
#[inline(always)]
fn next_to(src: &LString, right: &[u32], i: usize, nested: bool) -> u32 {
    if nested {
        right[i]
    } else {
        src.ids.get(i + 1).map_or(context::NONE, |id| id.0)
    }
}
