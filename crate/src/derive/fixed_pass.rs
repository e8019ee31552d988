//! The Fixed/Choice pass of the module classes ([`super::module_classes`]): every module of the
//! string a table copy or one draw among constant weights, the draws made a block at a time, and
//! the id counts carried from step to step so that the next length is known before the step.

use super::module_classes::{ModuleClasses, ModuleKind, REWRITES, SPECIAL};
use super::successors::{Room, PAD};
use crate::model::ModuleId;
use rand::RngExt;

/// How many times each module id occurs in the string a Fixed/Choice pass wrote, carried to the
/// next step as the D0L path does, so that the next length is known without reading the string.
#[derive(Default)]
pub(super) struct Counts {
    pub ids: Vec<u64>,
    /// The length of the string counted; `None` when the counts are not those of the string the
    /// last pass wrote.
    pub len: Option<usize>,
    /// Set by each pass: true when `ids` are the counts of the string it reads.
    pub carried: bool,
    next: Vec<u64>,
    /// For each alternative of a Choice class, how many times the pass drew it.
    pub picks: Vec<u64>,
    /// Scratch: a block of draws.
    us: Vec<f64>,
}

/// The draws of a Fixed/Choice pass, made a block at a time: exactly as many in all as the pass
/// has Choice modules (`left` still to make), so the generator ends where the general path leaves
/// it.
struct Draws<'r, R: rand::Rng> {
    rng: &'r mut R,
    left: u64,
    us: Vec<f64>,
    at: usize,
}

impl<R: rand::Rng> Draws<'_, R> {
    /// The next block of at most 4096 draws.
    #[inline(never)]
    fn refill(&mut self) {
        let n = self.left.min(4096);
        self.left -= n;
        self.us.clear();
        let rng = &mut *self.rng;
        self.us.extend((0..n).map(|_| rng.random::<f64>()));
        self.at = 0;
    }
}

impl ModuleClasses {
    /// Writes the successor of every module of `ids`, each copied as [`ModuleClasses::width`] ids,
    /// when every class is Fixed or Choice; returns whether a production applied. A small
    /// function of its own, called from each width's sized pass (so `wasm-opt` does not inline
    /// it into one of them: V8 then allocates registers for this loop alone): one 8-byte entry a
    /// module, the class looked at only for a draw ([`ModuleClasses::pick`]), the same draws in the
    /// same order as the general path.
    #[inline(never)]
    pub fn write_fixed<R: rand::Rng>(
        &self,
        ids: &[ModuleId],
        out: &mut Vec<ModuleId>,
        rng: &mut R,
        counts: &mut Counts,
    ) -> bool {
        // How many draws the pass makes: its Choice modules. They are made in blocks, ahead of
        // the modules that use them and in the same order, so the copy loop calls nothing but
        // the choice between alternatives.
        let draws = self
            .classes
            .iter()
            .zip(&counts.ids)
            .filter(|(class, _)| class.kind == ModuleKind::Choice)
            .map(|(_, &count)| count)
            .sum();
        // The buffer is the last pass's, kept for its room: emptied, so that the first Choice
        // module draws a new block instead of reading the last pass's draws again.
        let mut us = std::mem::take(&mut counts.us);
        us.clear();
        let mut draw = Draws {
            rng,
            left: draws,
            us,
            at: 0,
        };
        let picks = &mut counts.picks;
        let changed = match self.width {
            4 => self.write_fixed_as::<4, R>(ids, out, &mut draw, picks),
            8 => self.write_fixed_as::<8, R>(ids, out, &mut draw, picks),
            _ => self.write_fixed_as::<PAD, R>(ids, out, &mut draw, picks),
        };
        counts.us = draw.us;
        changed
    }

    #[inline(always)]
    fn write_fixed_as<const W: usize, R: rand::Rng>(
        &self,
        ids: &[ModuleId],
        out: &mut Vec<ModuleId>,
        draw: &mut Draws<'_, R>,
        picks: &mut [u64],
    ) -> bool {
        Room::fill(out, |room| {
            self.write_fixed_into::<W, R>(ids, room, draw, picks)
        })
    }

    #[inline(always)]
    fn write_fixed_into<const W: usize, R: rand::Rng>(
        &self,
        ids: &[ModuleId],
        out: &mut Room<'_>,
        draw: &mut Draws<'_, R>,
        picks: &mut [u64],
    ) -> bool {
        let mut rewrites = 0;
        for &id in ids {
            let (mut start, mut len) = self.entry[id.index()];
            if len & SPECIAL != 0 {
                if draw.at == draw.us.len() {
                    draw.refill();
                }
                let u = draw.us[draw.at];
                draw.at += 1;
                (start, len) = self.pick(id, u, picks);
            }
            rewrites |= len;
            out.put::<W>(
                &self.successors,
                start as usize,
                (len & !(SPECIAL | REWRITES)) as usize,
            );
        }
        rewrites & REWRITES != 0
    }

    /// The successor the draw `u` picks for a Choice module `id` (start, length with
    /// [`REWRITES`]), out of the copy loop; counts the pick in `picks` (by alternative).
    #[inline(never)]
    fn pick(&self, id: ModuleId, u: f64, picks: &mut [u64]) -> (u32, u32) {
        let class = &self.classes[id.index()];
        let k = self.choose_index(class, u);
        picks[class.start as usize + k] += 1;
        let a = &self.alternatives[class.start as usize + k];
        (a.start, a.len | REWRITES)
    }

    /// The length of the string a Fixed/Choice pass writes from `ids`, from how many times each
    /// id occurs in it: `counts.ids` when they are those of `ids` (`carried`: the last pass wrote
    /// `ids` and nothing changed it since), else counted now.
    pub fn fixed_len(&self, ids: &[ModuleId], counts: &mut Counts, carried: bool) -> usize {
        counts.ids.resize(self.classes.len(), 0);
        if !carried {
            counts.ids.iter_mut().for_each(|c| *c = 0);
            for id in ids {
                counts.ids[id.index()] += 1;
            }
        }
        let len = counts
            .ids
            .iter()
            .zip(&self.outs)
            .fold(0u64, |len, (&count, &out)| {
                len.saturating_add(count.saturating_mul(out as u64))
            });
        usize::try_from(len).unwrap_or(usize::MAX)
    }

    /// After a Fixed/Choice pass: `counts.ids` become the counts of the string it wrote, from
    /// those of the string it read and the draws (`counts.picks`).
    pub fn carry(&self, counts: &mut Counts) {
        let Counts {
            ids, next, picks, ..
        } = counts;
        next.clear();
        next.resize(ids.len(), 0);
        let mut add = |start: u32, len: u32, count: u64| {
            for s in &self.successors[start as usize..][..len as usize] {
                next[s.index()] += count;
            }
        };
        for (class, &count) in self.classes.iter().zip(ids.iter()) {
            if count != 0 && class.kind == ModuleKind::Fixed {
                add(class.start, class.len, count);
            }
        }
        for (a, &count) in self.alternatives.iter().zip(picks.iter()) {
            if count != 0 {
                add(a.start, a.len, count);
            }
        }
        std::mem::swap(ids, next);
    }
}
