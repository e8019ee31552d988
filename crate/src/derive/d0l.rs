//! The D0L path: a flat table from module id to successor, for grammars whose productions have no
//! parameters, contexts, conditions or weights. The next length is known before writing, and
//! nothing is allocated per module.
//!
//! Every id has a successor in the table (a module without production: itself), so the step is
//! one copy per module with no branch. The length of the next string comes from how many times
//! each id occurs, carried from step to step (the counts of the next string are the counts of this
//! one through the successors), so the string is read once per step, not twice; when decomposition
//! or cut change the string between steps, the ids are counted again.

use super::successors::{put, width, Room, PAD};
use super::{check_size, cut, memory_error, NOT_REWRITTEN};
use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model, ModuleId};

/// The D0L path: usable when no production has parameters, contexts, conditions or weights.
pub(super) struct D0lTable {
    /// Every successor's ids, back to back (a module without production: itself), then [`PAD`]
    /// ids of padding for [`put`].
    successors: Vec<ModuleId>,
    /// For each module id, its successor in `successors`: start and length.
    slot: Vec<(u32, u32)>,
    /// The copy width of [`Room::put`] for these successors (0: some is longer than [`PAD`]).
    width: usize,
    /// For each module id, the production that rewrites it ([`NOT_REWRITTEN`] if none).
    production_of: Vec<u32>,
    /// True when nothing changes the string between steps (no decomposition, no cut), so the
    /// counts of one step's output are those of the next step's input.
    carried: bool,
    /// How many times each id occurs in the string the last step wrote, and that string's length.
    counts: Vec<u64>,
    counted_len: Option<usize>,
    /// Scratch for the next counts.
    next_counts: Vec<u64>,
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
        let ids = model.alphabet.len().max(rules.by_predecessor.len());
        let slot: Vec<(u32, u32)> = (0..ids)
            .map(|index| {
                let start = successors.len() as u32;
                match rules.by_predecessor.get(index).and_then(|c| c.first()) {
                    Some(&p) => successors
                        .extend(rules.productions[p as usize].successor.iter().map(|s| s.id)),
                    None => successors.push(ModuleId(index as u32)),
                }
                (start, successors.len() as u32 - start)
            })
            .collect();
        successors.extend(std::iter::repeat_n(ModuleId(0), PAD));
        let longest = slot.iter().map(|&(_, n)| n as usize).max().unwrap_or(0);
        let production_of = (0..ids)
            .map(|index| {
                rules
                    .by_predecessor
                    .get(index)
                    .and_then(|c| c.first().copied())
                    .unwrap_or(NOT_REWRITTEN)
            })
            .collect();
        Some(D0lTable {
            width: width(longest),
            successors,
            slot,
            production_of,
            carried: model.decomposition.is_empty() && !cut::contains_cut(model),
            counts: vec![0; ids],
            counted_len: None,
            next_counts: vec![0; ids],
        })
    }

    /// What the provenance of a step left untracked follows from, besides the string it read.
    pub(super) fn successors(&self) -> Successors {
        Successors {
            lengths: self.slot.iter().map(|&(_, n)| n).collect(),
            productions: self.production_of.clone(),
        }
    }

    /// How many times each id occurs in the string of `len` modules the last step wrote, when
    /// nothing changed it since (no decomposition, no cut) and `len` is its length.
    pub(super) fn take_counts(&mut self, len: usize) -> Option<Vec<u64>> {
        if !(self.carried && self.counted_len == Some(len)) {
            return None;
        }
        self.counted_len = None;
        Some(std::mem::take(&mut self.counts))
    }

    /// The length of the string one step makes from `src`, the counts of its ids in
    /// `next_counts`.
    fn next_len(&mut self, src: &LString) -> usize {
        if !(self.carried && self.counted_len == Some(src.len())) {
            self.counts.iter_mut().for_each(|c| *c = 0);
            for &id in &src.ids {
                self.counts[id.index()] += 1;
            }
        }
        self.next_counts.iter_mut().for_each(|c| *c = 0);
        let mut len = 0u64;
        for (index, &count) in self.counts.iter().enumerate() {
            if count == 0 {
                continue;
            }
            let (start, n) = self.slot[index];
            len = len.saturating_add(count.saturating_mul(n as u64));
            for id in &self.successors[start as usize..(start + n) as usize] {
                self.next_counts[id.index()] += count;
            }
        }
        usize::try_from(len).unwrap_or(usize::MAX)
    }

    /// Writes every module's successor as `W` ids ([`Room::put`]).
    #[inline(never)]
    fn write<const W: usize>(&self, src: &LString, dst: &mut LString) {
        Room::fill(&mut dst.ids, |room| {
            for &id in &src.ids {
                let (start, n) = self.slot[id.index()];
                room.put::<W>(&self.successors, start as usize, n as usize);
            }
        })
    }

    pub(super) fn step(
        &mut self,
        model: &Model,
        src: &LString,
        dst: &mut LString,
        step: u32,
    ) -> Result<(), Diagnostic> {
        let len = self.prepare(model, src, dst, step)?;
        match self.width {
            4 => self.write::<4>(src, dst),
            8 => self.write::<8>(src, dst),
            PAD => self.write::<PAD>(src, dst),
            _ => {
                for &id in &src.ids {
                    let (start, n) = self.slot[id.index()];
                    put(&mut dst.ids, &self.successors, start as usize, n as usize);
                }
            }
        }
        self.finish(dst, len);
        Ok(())
    }

    /// The length of the next string, checked, with `dst` emptied and room for it and the copy
    /// width's overhang.
    fn prepare(
        &mut self,
        model: &Model,
        src: &LString,
        dst: &mut LString,
        step: u32,
    ) -> Result<usize, Diagnostic> {
        let len = self.next_len(src);
        self.counted_len = None;
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
        Ok(len)
    }

    /// After a step wrote `dst`, `len` modules: its counts are the next step's.
    fn finish(&mut self, dst: &LString, len: usize) {
        debug_assert_eq!(dst.len(), len);
        std::mem::swap(&mut self.counts, &mut self.next_counts);
        self.counted_len = (dst.len() == len).then_some(len);
    }
}

/// Stores `W` (a multiple of 4) copies of `value` into `slot` (exactly `W` elements): with
/// WebAssembly SIMD, as 4 at a time (rustc writes `[value; W]` as `W` stores of one).
#[inline(always)]
fn fill<const W: usize>(slot: &mut [std::mem::MaybeUninit<u32>], value: u32) {
    assert_eq!(slot.len(), W);
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    {
        use core::arch::wasm32::{u32x4_splat, v128};
        let four = u32x4_splat(value);
        let at = slot.as_mut_ptr() as *mut v128;
        for k in 0..W / 4 {
            // SAFETY: `slot` holds `W` u32s, 16 bytes for each k < W / 4.
            unsafe { at.add(k).write_unaligned(four) }
        }
    }
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    for v in slot {
        v.write(value);
    }
}

/// For each module id, the length of its successor and the production that writes it
/// ([`NOT_REWRITTEN`] if none): with the string a D0L step read, where each module it wrote
/// comes from ([`super::Derivation::origin`] and [`super::Derivation::parent`]).
#[derive(Clone, Debug)]
pub(super) struct Successors {
    lengths: Vec<u32>,
    productions: Vec<u32>,
}

impl Successors {
    /// (origin, parent) of the `len` modules the step wrote from `read`: each module's share as
    /// [`PAD`] values stored at once into the arrays' spare room (what lies past a successor's
    /// length is overwritten by the next module), the lengths set once at the end. The room is
    /// checked per module (a slice index), so wrong lengths could not write past it.
    pub(super) fn provenance(&self, read: &LString, len: usize) -> (Vec<u32>, Vec<u32>) {
        let mut origin = Vec::with_capacity(len + PAD);
        let mut parent = Vec::with_capacity(len + PAD);
        let origin_out = origin.spare_capacity_mut();
        let parent_out = parent.spare_capacity_mut();
        let mut at = 0usize;
        for (i, &id) in read.ids.iter().enumerate() {
            let n = self.lengths[id.index()] as usize;
            let production = self.productions[id.index()];
            if n <= PAD {
                fill::<PAD>(&mut origin_out[at..at + PAD], production);
                fill::<PAD>(&mut parent_out[at..at + PAD], i as u32);
            } else {
                origin_out[at..at + n].iter_mut().for_each(|o| {
                    o.write(production);
                });
                parent_out[at..at + n].iter_mut().for_each(|p| {
                    p.write(i as u32);
                });
            }
            at += n;
        }
        debug_assert_eq!(at, len, "the successors are the step's");
        // SAFETY: the loop initialised the first `at` elements of both arrays.
        unsafe {
            origin.set_len(at);
            parent.set_len(at);
        }
        (origin, parent)
    }
}
