//! Applying edits to a skeleton: an edited branch's joints move with its Bézier handles and every
//! descendant follows rigidly.
//!
//! An edit moves the handles `P1 P2 P3` of a branch's fitted curve by offsets `Δ1 Δ2 Δ3`; the
//! curve moves by `D(t) = b1(t)·Δ1 + b2(t)·Δ2 + b3(t)·Δ3` (Bernstein weights) and each joint by
//! `D` at its parameter: `J_i' = J_i + D(t_i)`. A joint on the fitted curve lands on the edited
//! curve; one off it keeps its small distance from it (so an edit of zero changes nothing and a
//! handle moved by a little moves the branch by a little). `P0` never moves: the branch stays
//! attached to its parent. Each segment's heading becomes the direction between its new joints;
//! its left and up vectors turn with it by the smallest rotation (they are transported, so the
//! branch does not twist). The rigid motion taking a segment's old end frame (end joint, heading,
//! left, up) to its new one is that joint's motion: items drawn at the joint follow it, and the
//! motion of the last joint carries every child branch and all that grows from it. All this is
//! computed in the branch's unedited place and then carried by the motion the branch inherited
//! from its parent, so an edit is kept in the branch's own frame and moves with its ancestors.

use super::{fit, BranchTree, Item};
use crate::turtle::Skeleton;
use glam::{DMat3, DQuat, DVec3};

/// A rigid motion `x ↦ rotation·(x − from) + to`. Written about a pivot so that the pivot lands
/// exactly (bit for bit) on `to`: a child branch that starts at its parent's end joint still
/// starts exactly there after both have moved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rigid {
    pub rotation: DMat3,
    pub from: DVec3,
    pub to: DVec3,
    /// The identity, applied as a copy (no rounding at all).
    pub identity: bool,
}

impl Default for Rigid {
    fn default() -> Self {
        Rigid::IDENTITY
    }
}

impl Rigid {
    pub const IDENTITY: Rigid = Rigid {
        rotation: DMat3::IDENTITY,
        from: DVec3::ZERO,
        to: DVec3::ZERO,
        identity: true,
    };

    /// The motion that turns the frame (`from`, `rotation` of the old frame) into (`to`, …): the
    /// rotation is given already (new frame times old frame transposed).
    pub fn about(rotation: DMat3, from: DVec3, to: DVec3) -> Rigid {
        Rigid {
            rotation,
            from,
            to,
            identity: false,
        }
    }

    pub fn point(&self, p: DVec3) -> DVec3 {
        if self.identity {
            p
        } else {
            self.rotation * (p - self.from) + self.to
        }
    }

    pub fn vector(&self, v: DVec3) -> DVec3 {
        if self.identity {
            v
        } else {
            self.rotation * v
        }
    }

    /// `outer ∘ self`: this motion, then `outer`.
    pub fn then(&self, outer: &Rigid) -> Rigid {
        match (self.identity, outer.identity) {
            (true, _) => *outer,
            (_, true) => *self,
            _ => Rigid {
                rotation: outer.rotation * self.rotation,
                from: self.from,
                to: outer.point(self.to),
                identity: false,
            },
        }
    }

    pub fn inverse(&self) -> Rigid {
        if self.identity {
            return *self;
        }
        Rigid {
            rotation: self.rotation.transpose(),
            from: self.to,
            to: self.from,
            identity: false,
        }
    }
}

/// The offsets of an edit in world units, from its offsets in the branch's start frame in
/// branch lengths.
pub fn world_offsets(frame: [DVec3; 3], length: f64, local: &[DVec3; 3]) -> [DVec3; 3] {
    local.map(|o| (frame[0] * o.x + frame[1] * o.y + frame[2] * o.z) * length)
}

/// The unedited start frame of `branch` (heading, left, up of its first segment).
pub fn start_frame(original: &Skeleton, tree: &BranchTree, branch: u32) -> [DVec3; 3] {
    let b = &tree.branches[branch as usize];
    let s = &original.segments[b.segments[0] as usize];
    let heading = (s.end - s.start).try_normalize().unwrap_or(DVec3::Y);
    [heading, s.left, s.up]
}

/// Writes `branch`'s segments and items into `out`, from their unedited place in `original`,
/// deformed by `offsets` (local, as stored in an edit) when given, then carried by `inherited`.
/// Fills `joints` with the motion of each segment's end joint (from unedited to edited place).
pub fn place_branch(
    original: &Skeleton,
    tree: &BranchTree,
    branch: u32,
    offsets: Option<&[DVec3; 3]>,
    inherited: &Rigid,
    out: &mut Skeleton,
    joints: &mut Vec<Rigid>,
) {
    let b = &tree.branches[branch as usize];
    joints.clear();
    match offsets {
        None => {
            for &s in &b.segments {
                let (o, e) = unedited_and_edited(&original.segments, &mut out.segments, s);
                e.start = inherited.point(o.start);
                e.end = inherited.point(o.end);
                e.left = inherited.vector(o.left);
                e.up = inherited.vector(o.up);
                joints.push(*inherited);
            }
        }
        Some(local) => {
            edited_motions(original, tree, branch, local, inherited, joints);
            let mut start = inherited.point(original.segments[b.segments[0] as usize].start);
            for (&s, joint) in b.segments.iter().zip(joints.iter()) {
                let o = &original.segments[s as usize];
                let e = &mut out.segments[s as usize];
                e.start = start;
                e.end = joint.to;
                e.left = joint.vector(o.left);
                e.up = joint.vector(o.up);
                start = joint.to;
            }
        }
    }
    for &(item, k) in &b.items {
        place_item(original, item, &joints[k as usize], out);
    }
}

/// The motion of each end joint of `branch` under the edit `local`, carried by `inherited`:
/// for segment `k`, the smallest rotation from its unedited direction to its edited one, about
/// its end joint, which lands on the edited joint `J + D(t)` (the rotation also turns its left
/// and up vectors). Written into `joints`.
pub fn edited_motions(
    original: &Skeleton,
    tree: &BranchTree,
    branch: u32,
    local: &[DVec3; 3],
    inherited: &Rigid,
    joints: &mut Vec<Rigid>,
) {
    let b = &tree.branches[branch as usize];
    joints.clear();
    let frame = start_frame(original, tree, branch);
    let delta = world_offsets(frame, b.length, local);
    let unedited = tree.joints(original, branch);
    let moved: Vec<DVec3> = unedited
        .iter()
        .zip(&b.fit.params)
        .enumerate()
        .map(|(i, (&j, &t))| {
            if i == 0 {
                return j;
            }
            let w = fit::bernstein(t);
            j + delta[0] * w[1] + delta[1] * w[2] + delta[2] * w[3]
        })
        .collect();
    for k in 0..b.segments.len() {
        let old = (unedited[k + 1] - unedited[k]).try_normalize();
        let new = (moved[k + 1] - moved[k]).try_normalize();
        let turn = match (old, new) {
            (Some(a), Some(b)) => DMat3::from_quat(DQuat::from_rotation_arc(a, b)),
            _ => DMat3::IDENTITY,
        };
        joints.push(Rigid::about(turn, unedited[k + 1], moved[k + 1]).then(inherited));
    }
}

/// Element `i` of a skeleton's list as it was (`original`) and as it is being written (`out`).
fn unedited_and_edited<'a, T>(original: &'a [T], out: &'a mut [T], i: u32) -> (&'a T, &'a mut T) {
    (&original[i as usize], &mut out[i as usize])
}

/// Moves one polygon, leaf or sphere from its unedited place by `motion`.
pub fn place_item(original: &Skeleton, item: Item, motion: &Rigid, out: &mut Skeleton) {
    match item {
        Item::Polygon(i) => {
            let (o, e) = unedited_and_edited(&original.polygons, &mut out.polygons, i);
            for (p, q) in e.points.iter_mut().zip(&o.points) {
                *p = motion.point(*q);
            }
        }
        Item::Surface(i) => {
            let (o, e) = unedited_and_edited(&original.surfaces, &mut out.surfaces, i);
            e.origin = motion.point(o.origin);
            e.heading = motion.vector(o.heading);
            e.left = motion.vector(o.left);
            e.up = motion.vector(o.up);
        }
        Item::Sphere(i) => {
            out.spheres[i as usize].center = motion.point(original.spheres[i as usize].center);
        }
    }
}

/// Places `branch` and every branch below it (see [`place_branch`]), each child carried by the
/// motion of its parent's end joint, and records in `inherited` the motion each descendant now
/// inherits. `edits[b]` is branch `b`'s edit, if any. Returns the joint motions of `branch`.
pub fn place_subtree(
    original: &Skeleton,
    tree: &BranchTree,
    branch: u32,
    edits: &[Option<[DVec3; 3]>],
    inherited: &mut [Rigid],
    out: &mut Skeleton,
) -> Vec<Rigid> {
    let mut first = Vec::new();
    let mut joints = Vec::new();
    for b in tree.subtree(branch) {
        let carried = inherited[b as usize];
        place_branch(
            original,
            tree,
            b,
            edits[b as usize].as_ref(),
            &carried,
            out,
            &mut joints,
        );
        let end = joints.last().copied().unwrap_or(carried);
        for &c in &tree.branches[b as usize].children {
            inherited[c as usize] = end;
        }
        if b == branch {
            first = joints.clone();
        }
    }
    first
}

/// The control points of `branch`'s curve where they are now: the fitted ones moved by its edit,
/// carried by the motion it inherits.
pub fn control_points(
    original: &Skeleton,
    tree: &BranchTree,
    branch: u32,
    edit: Option<&[DVec3; 3]>,
    inherited: &Rigid,
) -> [DVec3; 4] {
    let b = &tree.branches[branch as usize];
    let mut control = b.fit.control;
    if let Some(local) = edit {
        let delta = world_offsets(start_frame(original, tree, branch), b.length, local);
        for k in 0..3 {
            control[k + 1] += delta[k];
        }
    }
    control.map(|p| inherited.point(p))
}
