//! The axes of a skeleton: which segments continue each other in one tube ([`joins`]), and the
//! chains of segment indices that become tubes ([`chains`]).

use crate::turtle::Skeleton;
use glam::DVec3;

/// Consecutive segments whose directions differ by more than this start a new tube: a ring at
/// a sharper joint would pinch.
const MAX_JOINT_ANGLE_COS: f64 = -0.2;

/// A point as a hash key (exact: joints are the same computed value, not merely close; the two
/// zeros are one): where a chain starts hidden at another segment's end.
pub fn joint_key(p: DVec3) -> [u64; 3] {
    key(p)
}

pub(super) fn key(p: DVec3) -> [u64; 3] {
    let p = p + DVec3::ZERO;
    [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()]
}

/// Whether segment `i` joins segment `p` (the one it continues) in one tube: both have a width,
/// the same smoothness, the joint between them is not sharper than `MAX_JOINT_ANGLE_COS`, and the
/// joint's ring does not reach past the middle of either segment (a tube much wider than a short
/// segment at a bend: its rings would cross and the tube turn inside out). `unit` is the width unit.
pub(crate) fn joins(skeleton: &Skeleton, p: usize, i: usize, unit: f64) -> bool {
    let (before, after) = (&skeleton.segments[p], &skeleton.segments[i]);
    if !(after.width > 0.0 && before.width > 0.0 && before.smooth == after.smooth) {
        return false;
    }
    let (along_before, along_after) = (before.end - before.start, after.end - after.start);
    let cos = along_before.normalize().dot(along_after.normalize());
    // A zero-length segment has no direction (NaN): it joins nothing.
    if cos.is_nan() || cos <= MAX_JOINT_ANGLE_COS {
        return false;
    }
    // The joint ring lies across the bisector, tilted by half the bend from each segment's
    // cross-section: it reaches radius × sin(bend / 2) along each of them.
    let reach = 0.5 * after.width * unit * ((1.0 - cos.clamp(-1.0, 1.0)) * 0.5).sqrt();
    let overruns = reach >= 0.5 * along_before.length().min(along_after.length());
    !overruns
}

/// The axes of a skeleton ([`chains`]): lists of segment indices, each continuing the one before,
/// stored end to end (a plant has tens of thousands of them: one list each cost an allocation).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Chains {
    /// Every chain's segments, chain after chain.
    segments: Vec<u32>,
    /// Where each chain ends in `segments`.
    ends: Vec<u32>,
}

impl Chains {
    /// How many chains.
    pub fn len(&self) -> usize {
        self.ends.len()
    }

    /// No chain at all (no tubes).
    pub fn is_empty(&self) -> bool {
        self.ends.is_empty()
    }

    /// Each chain's segments, in order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = &[u32]> + Clone + '_ {
        (0..self.ends.len()).map(move |k| {
            let from = if k == 0 { 0 } else { self.ends[k - 1] };
            &self.segments[from as usize..self.ends[k] as usize]
        })
    }
}

/// The axes of the skeleton, each a list of segment indices continuing the one before, in the
/// order of their first segments. A chain breaks where widths are zero, at sharp joints, where
/// smoothness changes, and where the joint's ring would reach past the middle of a segment it
/// joins (see [`joins`]). `unit` is the width unit.
pub(crate) fn chains(skeleton: &Skeleton, unit: f64) -> Chains {
    const NONE: u32 = u32::MAX;
    let segments = &skeleton.segments;
    // The segment that continues each one (NONE: none), and the segments that start a chain,
    // found in one pass (the starts in order: a second pass reading every segment's width again
    // was a sixth of this function's time in 1.24d n = 10).
    let mut next = vec![NONE; segments.len()];
    let mut starts = Vec::new();
    for (i, s) in segments.iter().enumerate() {
        if s.width <= 0.0 {
            continue;
        }
        match s.previous.map(|p| p as usize) {
            Some(p) if next[p] == NONE && joins(skeleton, p, i, unit) => next[p] = i as u32,
            _ => starts.push(i as u32),
        }
    }
    let mut chains = Chains {
        segments: Vec::with_capacity(segments.len()),
        ends: Vec::with_capacity(starts.len()),
    };
    for start in starts {
        let mut at = start;
        while at != NONE {
            chains.segments.push(at);
            at = next[at as usize];
        }
        chains.ends.push(chains.segments.len() as u32);
    }
    chains
}
