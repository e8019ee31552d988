//! Bracket-aware context matching (LANGUAGE.md section 3; ABOP section 1.8, cpfg's "bracketed
//! sense"). Looking left, the neighbour is the previous module on the path to the root: whole
//! branches `[…]` are skipped and a `[` is stepped out of. Looking right, branches the pattern does
//! not mention are skipped, a `]` ends the search, and `[`…`]` in the pattern are matched against
//! the string's branches (trying each sibling branch in turn). Ignored modules are skipped on both
//! sides.

use crate::model::{LString, Model, ModuleId, PatternItem, PatternModule};

/// No partner: not a bracket, or an unbalanced one.
pub const NONE: u32 = u32::MAX;

/// For each `[` the index of its `]` and back; [`NONE`] elsewhere.
pub fn bracket_partners(model: &Model, s: &LString, partner: &mut Vec<u32>) {
    partner.clear();
    partner.resize(s.len(), NONE);
    let mut stack: Vec<u32> = Vec::new();
    for (i, &id) in s.ids.iter().enumerate() {
        if id == model.open {
            stack.push(i as u32);
        } else if id == model.close {
            if let Some(open) = stack.pop() {
                partner[open as usize] = i as u32;
                partner[i] = open;
            }
        }
    }
}

/// The module before `j` on the path to the root, skipping branches and ignored modules.
pub(super) fn previous(model: &Model, s: &LString, partner: &[u32], mut j: usize) -> Option<usize> {
    while j > 0 {
        j -= 1;
        let id = s.ids[j];
        if id == model.close {
            let open = partner[j];
            if open == NONE {
                return None;
            }
            j = open as usize; // the loop then steps past the '['
        } else if id == model.open || model.ignored[id.index()] {
            continue;
        } else {
            return Some(j);
        }
    }
    None
}

fn bind(m: &PatternModule, params: &[f64], slots: &mut [f64]) -> bool {
    if params.len() != m.arity {
        return false;
    }
    let first = m.first_slot as usize;
    slots[first..first + params.len()].copy_from_slice(params);
    true
}

/// Where a match records the modules that served as context. Derivation records nothing (`()`,
/// compiled away); the studio's explanation of a production records their indices.
pub trait Recorder {
    fn record(&mut self, index: usize);
    fn mark(&self) -> usize;
    /// Forgets what was recorded since `mark` (a branch of the pattern that did not match).
    fn reset(&mut self, mark: usize);
}

impl Recorder for () {
    #[inline(always)]
    fn record(&mut self, _: usize) {}
    #[inline(always)]
    fn mark(&self) -> usize {
        0
    }
    #[inline(always)]
    fn reset(&mut self, _: usize) {}
}

impl Recorder for Vec<u32> {
    fn record(&mut self, index: usize) {
        self.push(index as u32);
    }
    fn mark(&self) -> usize {
        self.len()
    }
    fn reset(&mut self, mark: usize) {
        self.truncate(mark);
    }
}

/// Matches a left context ending just before module `i`, binding its formal parameters and telling
/// `recorder` the indices of the context modules it matched (`&mut ()` records nothing).
pub fn match_left<R: Recorder>(
    model: &Model,
    s: &LString,
    partner: &[u32],
    i: usize,
    pattern: &[PatternModule],
    slots: &mut [f64],
    recorder: &mut R,
) -> bool {
    let mark = recorder.mark();
    let mut j = i;
    for m in pattern.iter().rev() {
        let Some(k) = previous(model, s, partner, j) else {
            recorder.reset(mark);
            return false;
        };
        if s.ids[k] != m.id || !bind(m, s.params_of(k), slots) {
            recorder.reset(mark);
            return false;
        }
        recorder.record(k);
        j = k;
    }
    true
}

/// Matches a right context starting at module `pos`, binding its formal parameters and telling
/// `recorder` the indices of the context modules it matched (`&mut ()` records nothing).
pub fn match_right<R: Recorder>(
    model: &Model,
    s: &LString,
    partner: &[u32],
    pos: usize,
    pattern: &[PatternItem],
    slots: &mut [f64],
    recorder: &mut R,
) -> bool {
    let Some(item) = pattern.first() else {
        return true;
    };
    let right = RightContext {
        model,
        s,
        partner,
        rest: &pattern[1..],
    };
    match item {
        PatternItem::Module(m) => right.module(pos, m, slots, recorder),
        PatternItem::Open => right.branch(pos, slots, recorder),
        PatternItem::Close => right.branch_end(pos, slots, recorder),
    }
}

/// One step of a right-context match: the string, and the pattern after the item being matched.
struct RightContext<'a> {
    model: &'a Model,
    s: &'a LString,
    partner: &'a [u32],
    /// The pattern items after the one this step matches.
    rest: &'a [PatternItem],
}

impl RightContext<'_> {
    /// Matches the rest of the pattern from `pos`.
    #[inline]
    fn rest<R: Recorder>(&self, pos: usize, slots: &mut [f64], recorder: &mut R) -> bool {
        match_right(
            self.model,
            self.s,
            self.partner,
            pos,
            self.rest,
            slots,
            recorder,
        )
    }

    /// The index just past the branch whose `[` is at `open`, or `None` when it is unbalanced.
    #[inline]
    fn past_branch(&self, open: usize) -> Option<usize> {
        let close = self.partner[open];
        (close != NONE).then(|| close as usize + 1)
    }

    /// The first module from `pos` on that `skip` does not pass over, stepping over whole branches
    /// `[…]`: `None` when the string ends first or a `[` is unbalanced.
    #[inline(always)]
    fn next_on_branch(&self, mut pos: usize, skip: impl Fn(ModuleId) -> bool) -> Option<usize> {
        let (model, s) = (self.model, self.s);
        while pos < s.len() {
            let id = s.ids[pos];
            if id == model.open {
                pos = self.past_branch(pos)?;
            } else if skip(id) {
                pos += 1;
            } else {
                return Some(pos);
            }
        }
        None
    }

    /// Matches the pattern module `m` with the next module from `pos` on this branch, skipping
    /// branches and ignored modules, then the rest of the pattern after it.
    fn module<R: Recorder>(
        &self,
        pos: usize,
        m: &PatternModule,
        slots: &mut [f64],
        recorder: &mut R,
    ) -> bool {
        let (model, s) = (self.model, self.s);
        let Some(at) =
            self.next_on_branch(pos, |id| id != model.close && model.ignored[id.index()])
        else {
            return false;
        };
        let id = s.ids[at];
        // A `]` ends the branch before a module to match.
        if id == model.close || id != m.id || !bind(m, s.params_of(at), slots) {
            return false;
        }
        let mark = recorder.mark();
        recorder.record(at);
        if self.rest(at + 1, slots, recorder) {
            return true;
        }
        recorder.reset(mark);
        false
    }

    /// Matches a pattern `[` with one of the branches starting at `pos` (skipping ignored modules),
    /// trying each sibling branch in turn with the rest of the pattern.
    fn branch<R: Recorder>(&self, mut pos: usize, slots: &mut [f64], recorder: &mut R) -> bool {
        let (model, s) = (self.model, self.s);
        while pos < s.len() {
            let id = s.ids[pos];
            if id == model.open {
                if self.rest(pos + 1, slots, recorder) {
                    return true;
                }
                let Some(next) = self.past_branch(pos) else {
                    return false;
                };
                pos = next; // try the next sibling branch
            } else if model.ignored[id.index()] {
                pos += 1;
            } else {
                return false;
            }
        }
        false
    }

    /// Matches a pattern `]` with the end of the branch `pos` is on (skipping whatever the branch
    /// still holds), then the rest of the pattern after it.
    fn branch_end<R: Recorder>(&self, pos: usize, slots: &mut [f64], recorder: &mut R) -> bool {
        let close = self.model.close;
        match self.next_on_branch(pos, |id| id != close) {
            Some(at) => self.rest(at + 1, slots, recorder),
            None => false,
        }
    }
}
