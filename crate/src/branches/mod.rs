//! Branches of a skeleton and their Bézier skeletons, and the edits a user makes by dragging a
//! branch's handles (issue 8, after Rynkiewicz & Napieralski). Between the turtle and the mesh:
//! `Skeleton` → [`BranchTree`] (plain data) → with [`BranchEdit`]s → an edited `Skeleton`.
//!
//! **A branch** is a run of segments along one axis between branching points. An axis is a
//! chain of segments each continuing the one before (`Segment::previous`). A *branching point*
//! is the end joint of a segment from which another segment grows (`Segment::anchor`) other
//! than its continuation — a lateral `[…]`, or a segment after `f` — or where the axis ends. The
//! axis is cut at every branching point, so a branch's children always grow from its **end**
//! joint, and the continuation of the axis after a branching point is a child too (the last
//! one: it comes last in the string).
//!
//! - **parent**: the branch holding the segment its first segment grows from; none for a
//!   **root** (a segment drawn before any other on its path, or after `@M`).
//! - **children**: in the order their first segments appear in the string.
//! - **path**: the index of its root among the roots, then the child index at each level:
//!   `[0]` is the first root, `[0, 2]` its third child, `[0, 2, 1]` that one's second child.
//!   The same string always gives the same paths; after a re-derivation a path names the
//!   branch in the same place as long as the branches before it in the string still exist.
//! - **items**: polygons, leaves and spheres belong to the branch of the segment they grow from
//!   (their `anchor`), at that segment's end joint, and follow that joint when it moves.
//!
//! Each branch has a cubic Bézier curve fitted to its joints ([`fit`]); its control points
//! are what the user drags.

pub mod deform;
pub mod editor;
pub mod edits;
pub mod fit;

pub use deform::Rigid;
pub use editor::{BranchEditor, DragError, MeshChange};
pub use edits::{
    check_edit, parse_edits, write_edits, BranchEdit, EditReport, NotApplied, EDITS_VERSION,
    MAX_EDITS, MAX_OFFSET, MAX_PATH,
};

use crate::turtle::{Segment, Skeleton};
use glam::DVec3;

/// No branch (a root's parent, an item drawn before any segment).
pub const NO_BRANCH: u32 = u32::MAX;

/// Something drawn at a joint that is not a segment.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Item {
    Polygon(u32),
    Surface(u32),
    Sphere(u32),
}

/// One branch of the tree (see the module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct Branch {
    /// Its place among its parent's children (or among the roots): the last number of its path
    /// ([`BranchTree::path`]). Paths are not kept: a comb of n segments, each a fork, has
    /// branches n deep, and their paths n²/2 numbers (7 GB at 60,000 segments).
    pub rank: u32,
    /// How many branches its path passes through: its parent's depth and one.
    pub depth: u32,
    pub parent: Option<u32>,
    pub children: Vec<u32>,
    /// Its segments in order along the axis (indices into `Skeleton::segments`).
    pub segments: Vec<u32>,
    /// Polygons, leaves and spheres growing from its joints: (item, k) with the item at the end
    /// joint of `segments[k]`.
    pub items: Vec<(Item, u32)>,
    /// The Bézier curve fitted to the unedited branch's joints.
    pub fit: fit::Fit,
    /// The sum of its segments' lengths (the unit of edit offsets).
    pub length: f64,
}

/// The branches of a skeleton, parents before children.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BranchTree {
    pub branches: Vec<Branch>,
    /// The root branches, in the order they appear.
    pub roots: Vec<u32>,
    /// For each segment, its branch.
    pub segment_branch: Vec<u32>,
    /// For each segment, its index in its branch's `segments`.
    pub segment_position: Vec<u32>,
}

/// How the segments of a skeleton continue each other: where [`BranchTree::new`] cuts the axes
/// into branches.
struct Axes {
    /// The continuation of each segment (the first segment continuing it).
    continuation: Vec<Option<u32>>,
    /// Whether each segment continues another.
    continues: Vec<bool>,
    /// Whether anything other than its continuation grows from each segment's end.
    forks: Vec<bool>,
}

impl Axes {
    /// How `segments` continue each other.
    fn of(segments: &[Segment]) -> Axes {
        let n = segments.len();
        let mut axes = Axes {
            continuation: vec![None; n],
            continues: vec![false; n],
            forks: vec![false; n],
        };
        for (i, s) in segments.iter().enumerate() {
            match (s.previous, s.anchor) {
                (Some(p), _) if axes.continuation[p as usize].is_none() && (p as usize) < i => {
                    axes.continuation[p as usize] = Some(i as u32);
                    axes.continues[i] = true;
                }
                (_, Some(a)) if (a as usize) < i => axes.forks[a as usize] = true,
                _ => {}
            }
        }
        axes
    }

    /// Whether a branch ends at segment `s`'s end joint: a branching point, or the axis ends.
    fn ends_branch(&self, s: usize) -> bool {
        self.forks[s] || self.continuation[s].is_none()
    }

    /// Whether a branch starts with segment `s`: it continues nothing, or the segment it
    /// continues ends a branch.
    fn starts_branch(&self, segments: &[Segment], s: usize) -> bool {
        !self.continues[s]
            || segments[s]
                .previous
                .is_some_and(|p| self.ends_branch(p as usize))
    }

    /// The segments of the branch that starts with segment `start`.
    fn branch_from(&self, start: usize) -> Vec<u32> {
        let mut run = vec![start as u32];
        let mut at = start;
        while !self.ends_branch(at) {
            let Some(next) = self.continuation[at] else {
                break;
            };
            run.push(next);
            at = next as usize;
        }
        run
    }
}

impl BranchTree {
    /// The branches of `skeleton`.
    pub fn new(skeleton: &Skeleton) -> BranchTree {
        let segments = &skeleton.segments;
        let n = segments.len();
        let axes = Axes::of(segments);
        let mut tree = BranchTree {
            segment_branch: vec![NO_BRANCH; n],
            segment_position: vec![0; n],
            ..BranchTree::default()
        };
        for start in 0..n {
            if axes.starts_branch(segments, start) {
                tree.add_branch(segments, axes.branch_from(start));
            }
        }
        tree.attach_items(skeleton);
        tree
    }

    /// Adds the branch of the segments `run`, a child of the branch its first segment grows
    /// from (whose branch is already in the tree) or a root.
    fn add_branch(&mut self, segments: &[Segment], run: Vec<u32>) {
        let id = self.branches.len() as u32;
        let start = run[0] as usize;
        for (k, &s) in run.iter().enumerate() {
            self.segment_branch[s as usize] = id;
            self.segment_position[s as usize] = k as u32;
        }
        let grows_from = segments[start]
            .anchor
            .filter(|&a| (a as usize) < start)
            .map(|a| self.segment_branch[a as usize])
            .filter(|&b| b != NO_BRANCH);
        let (rank, depth) = match grows_from {
            Some(parent) => {
                let p = &mut self.branches[parent as usize];
                p.children.push(id);
                (p.children.len() as u32 - 1, p.depth + 1)
            }
            None => {
                self.roots.push(id);
                (self.roots.len() as u32 - 1, 1)
            }
        };
        let mut joints = vec![segments[start].start];
        joints.extend(run.iter().map(|&s| segments[s as usize].end));
        let length = run
            .iter()
            .map(|&s| {
                let s = &segments[s as usize];
                (s.end - s.start).length()
            })
            .sum();
        self.branches.push(Branch {
            rank,
            depth,
            parent: grows_from,
            children: Vec::new(),
            segments: run,
            items: Vec::new(),
            fit: fit::fit(&joints),
            length,
        });
    }

    /// Gives each polygon, leaf and sphere to the branch of the segment it grows from.
    fn attach_items(&mut self, skeleton: &Skeleton) {
        let n = skeleton.segments.len();
        let anchored = skeleton
            .polygons
            .iter()
            .enumerate()
            .map(|(i, p)| (Item::Polygon(i as u32), p.anchor))
            .chain(
                skeleton
                    .surfaces
                    .iter()
                    .enumerate()
                    .map(|(i, s)| (Item::Surface(i as u32), s.anchor)),
            )
            .chain(
                skeleton
                    .spheres
                    .iter()
                    .enumerate()
                    .map(|(i, s)| (Item::Sphere(i as u32), s.anchor)),
            );
        for (item, anchor) in anchored {
            if let Some(a) = anchor.filter(|&a| (a as usize) < n) {
                let b = self.segment_branch[a as usize];
                if b != NO_BRANCH {
                    let k = self.segment_position[a as usize];
                    self.branches[b as usize].items.push((item, k));
                }
            }
        }
    }

    pub fn len(&self) -> usize {
        self.branches.len()
    }

    pub fn is_empty(&self) -> bool {
        self.branches.is_empty()
    }

    /// The path of `branch`: its root's place among the roots, then at each branch down to it
    /// its place among its parent's children (what an edits document names it by).
    pub fn path(&self, branch: u32) -> Vec<u32> {
        let mut path = Vec::new();
        let mut at = self.branches.get(branch as usize);
        while let Some(b) = at {
            path.push(b.rank);
            at = b.parent.and_then(|p| self.branches.get(p as usize));
        }
        path.reverse();
        path
    }

    /// The branch at `path`, or why there is none (the deepest part of the path that exists).
    pub fn find(&self, path: &[u32]) -> Result<u32, String> {
        let Some((&root, rest)) = path.split_first() else {
            return Err("the path is empty".into());
        };
        let mut at = *self.roots.get(root as usize).ok_or_else(|| {
            format!(
                "the plant has {} root branch{}",
                self.roots.len(),
                if self.roots.len() == 1 { "" } else { "es" }
            )
        })?;
        for (depth, &child) in rest.iter().enumerate() {
            let children = &self.branches[at as usize].children;
            at = *children.get(child as usize).ok_or_else(|| {
                let n = children.len();
                format!(
                    "branch {:?} has {n} child branch{}",
                    &path[..depth + 1],
                    if n == 1 { "" } else { "es" }
                )
            })?;
        }
        Ok(at)
    }

    /// `branch` and all its descendants, parents before children.
    pub fn subtree(&self, branch: u32) -> Vec<u32> {
        let mut out = vec![branch];
        let mut k = 0;
        while k < out.len() {
            out.extend(&self.branches[out[k] as usize].children);
            k += 1;
        }
        out.sort_unstable();
        out
    }

    /// The joints of `branch` in `skeleton`: its first segment's start, then each segment's end.
    pub fn joints(&self, skeleton: &Skeleton, branch: u32) -> Vec<DVec3> {
        let b = &self.branches[branch as usize];
        let mut joints = Vec::with_capacity(b.segments.len() + 1);
        if let Some(&first) = b.segments.first() {
            joints.push(skeleton.segments[first as usize].start);
        }
        joints.extend(
            b.segments
                .iter()
                .map(|&s| skeleton.segments[s as usize].end),
        );
        joints
    }
}

#[cfg(test)]
mod tests;
