//! The growth in time as a glTF 2.0 animation (docs/LANGUAGE.md, "Growth in time"): morph
//! targets, each the mesh at one growth time relative to the whole plant, and their weights keyed
//! in seconds with linear interpolation, so that any glTF player (three.js's `AnimationMixer`,
//! Blender) plays the plant growing without knowing Meristem's growth arrays.
//!
//! Keyframe j is growth time j / K (K targets per step) from 0 to N; target j is the mesh at
//! that time ([`crate::mesh::mesh_at`]) minus the whole plant, and at keyframe j its weight alone
//! is 1, so between two keyframes the mesh blends linearly from one to the next. The last
//! keyframe (t = N) is the whole plant itself: no target, every weight 0, which is also the
//! mesh's default pose.
//!
//! An element that has not started at a keyframe has no size, all its vertices on one point. In
//! the mesh that point is its base; here it is the plant's root while the element starts only
//! after the next keyframe, and its base at the keyframe before it starts: so between two
//! keyframes each vertex either grows as the mesh says or travels, with the rest of its element,
//! as a point from the root to its base. Unborn elements then lie at the root, and the plant's
//! bounding box grows with the plant, as a player framing the animation expects.

use crate::mesh::{grown_position, MeshBuffers};

/// How the growth is written as an animation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Animation {
    /// Seconds of animation per derivation step.
    pub seconds_per_step: f64,
    /// Morph targets per step: the keyframes between two steps, the step's own included.
    pub targets_per_step: u32,
}

impl Default for Animation {
    fn default() -> Self {
        Animation {
            seconds_per_step: 1.0,
            targets_per_step: 4,
        }
    }
}

/// Most targets per step.
pub const MAX_TARGETS_PER_STEP: u32 = 16;

/// The fewest and most seconds of animation per step: within them every keyframe's time is finite
/// and, for a plant of up to 10,000 steps (the default step limit) at up to
/// [`MAX_TARGETS_PER_STEP`], larger than the one before in `f32` (glTF's rule for an animation's
/// input).
pub const SECONDS_PER_STEP: (f64, f64) = (0.001, 3600.0);

/// Most bytes the morph targets may take (targets × points × 12).
pub const MAX_TARGET_BYTES: usize = 256 << 20;

/// The morph targets and the keyframes of a plant's growth.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Keyframes {
    /// The keyframes' times in seconds, increasing, the first 0.
    pub seconds: Vec<f32>,
    /// One target per keyframe but the last: the points' displacements (x, y, z each).
    pub targets: Vec<Vec<f32>>,
}

impl Animation {
    /// Refuses settings out of range (not clamped: a file keyed otherwise than asked would be a
    /// silent surprise, and 1e40 seconds per step wrote infinite keyframe times, an invalid glTF).
    pub fn check(&self) -> Result<(), String> {
        let (least, most) = SECONDS_PER_STEP;
        let s = self.seconds_per_step;
        if !(least..=most).contains(&s) {
            return Err(format!(
                "the growth animation's seconds per step must be from {least} to {most}, not {s}"
            ));
        }
        let k = self.targets_per_step;
        if !(1..=MAX_TARGETS_PER_STEP).contains(&k) {
            return Err(format!(
                "the growth animation's targets per step must be from 1 to {MAX_TARGETS_PER_STEP}, not {k}"
            ));
        }
        Ok(())
    }

    /// The keyframes of `mesh`'s growth over `span` steps, or why there are too many (a message
    /// that says what to change).
    pub fn keyframes(&self, mesh: &MeshBuffers, span: u32) -> Result<Keyframes, String> {
        self.check()?;
        let per = self.targets_per_step;
        let count = span as usize * per as usize;
        let points = if mesh.positions.is_empty() {
            &mesh.lines
        } else {
            &mesh.positions
        };
        let bytes = count.saturating_mul(points.len()).saturating_mul(4);
        if bytes > MAX_TARGET_BYTES {
            return Err(format!(
                "the growth animation would take {} MB of morph targets ({count} targets of {} \
                 points), above the limit of {} MB; use fewer targets per step, fewer iterations \
                 or fewer tube sides",
                bytes.div_ceil(1 << 20),
                points.len() / 3,
                MAX_TARGET_BYTES >> 20
            ));
        }
        let seconds_per_step = self.seconds_per_step;
        let time = |j: usize| (j as f64 / f64::from(per)) as f32;
        let seconds = (0..=count)
            .map(|j| (f64::from(time(j)) * seconds_per_step) as f32)
            .collect();
        let targets = (0..count)
            .map(|j| displacements(mesh, points, time(j), time(j + 1)))
            .collect();
        Ok(Keyframes { seconds, targets })
    }
}

/// The displacement of each of `points` (the mesh's vertices or line ends) from its place at
/// growth time `t`, the next keyframe at `next` (see the module's doc).
fn displacements(mesh: &MeshBuffers, points: &[f32], t: f32, next: f32) -> Vec<f32> {
    let (origins, times) = (&mesh.growth_origins, &mesh.growth_times);
    if origins.len() != points.len() || times.len() / 2 != points.len() / 3 {
        return vec![0.0; points.len()];
    }
    // The root: the base of the element that starts first.
    let first = (0..times.len() / 2)
        .min_by(|&a, &b| times[2 * a].total_cmp(&times[2 * b]))
        .unwrap_or(0);
    let root = [0, 1, 2].map(|k| origins.get(3 * first + k).copied().unwrap_or(0.0));
    let mut out = Vec::with_capacity(points.len());
    for (v, p) in points.chunks_exact(3).enumerate() {
        let p = [p[0], p[1], p[2]];
        let o = [0, 1, 2].map(|k| origins[3 * v + k]);
        let span = [times[2 * v], times[2 * v + 1]];
        let at = if span[0] >= next {
            root
        } else {
            grown_position(p, o, span, t)
        };
        out.extend((0..3).map(|k| at[k] - p[k]));
    }
    out
}

impl Keyframes {
    /// The weights at each keyframe, one after the other (keyframe j: target j alone at 1; the
    /// last: all 0).
    pub fn weights(&self) -> Vec<f32> {
        let n = self.targets.len();
        let mut weights = vec![0.0; self.seconds.len() * n];
        for j in 0..n {
            weights[j * n + j] = 1.0;
        }
        weights
    }
}
