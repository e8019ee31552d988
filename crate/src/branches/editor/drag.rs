//! Dragging a handle: the session fixed when a drag of a branch begins (which chains are rebuilt,
//! which are moved rigidly, which items are meshed anew, and what stays where it was), and the
//! partial re-mesh of each frame, which gives up (for a full re-mesh) when the mesh's topology
//! would change.

use super::{BranchEditor, MeshChange};
use crate::branches::deform::{self, Rigid};
use crate::branches::Item;
use crate::mesh::parts::{self, NO_CHAIN};
use crate::mesh::{self, MeshBuffers};
use crate::turtle::Skeleton;
use glam::DVec3;

/// Bounds of vertices: [[min x, y, z], [max x, y, z]].
type Bounds = [[f32; 3]; 2];

/// What one drag rebuilds and moves, fixed while the same branch is dragged.
#[derive(Clone, Debug)]
pub(super) struct DragSession {
    pub(super) branch: u32,
    /// Chains holding the branch's segments: rebuilt every frame.
    rebuilt: Vec<u32>,
    /// Chains below the branch: moved rigidly every frame.
    moved: Vec<u32>,
    /// Polygons, leaves and spheres of the branch and below: meshed anew every frame.
    items: Vec<Item>,
    /// The moved chains' positions, normals and growth origins (when the mesh grows in time)
    /// when the drag began, chain after chain.
    base_positions: Vec<f32>,
    base_normals: Vec<f32>,
    base_origins: Vec<f32>,
    /// The motion of the branch's end joint when the drag began.
    base_end: Rigid,
    ranges: Vec<[u32; 2]>,
    /// The segments of the branch and below (their ends move), and the sorted joint keys of
    /// all other segments' ends (fixed while the drag lasts): where tubes may start hidden.
    moving_segments: Vec<u32>,
    fixed_joints: Vec<[u64; 3]>,
    /// The bounds of the vertices outside `ranges` (fixed while the drag lasts).
    fixed_bounds: Option<Bounds>,
}

impl BranchEditor {
    /// The session of a drag of `branch` that begins now (`None` for the lines fallback).
    pub(super) fn start_session(
        &self,
        branch: u32,
        skeleton: &Skeleton,
        mesh: &MeshBuffers,
    ) -> Option<DragSession> {
        if self.parts.lines {
            return None;
        }
        let tree = &self.tree;
        let subtree = tree.subtree(branch);
        let (rebuilt, moved) = self.dragged_chains(branch, &subtree);
        let items: Vec<Item> = subtree
            .iter()
            .flat_map(|&d| {
                tree.branches[d as usize]
                    .items
                    .iter()
                    .map(|&(item, _)| item)
            })
            .collect();
        let mut base_positions = Vec::new();
        let mut base_normals = Vec::new();
        let mut base_origins = Vec::new();
        for &c in &moved {
            let p = &self.parts.chains[c as usize].part;
            let (from, to) = (
                3 * p.first_vertex as usize,
                3 * (p.first_vertex + p.vertices) as usize,
            );
            base_positions.extend_from_slice(&mesh.positions[from..to]);
            base_normals.extend_from_slice(&mesh.normals[from..to]);
            if let Some(origins) = mesh.growth_origins.get(from..to) {
                base_origins.extend_from_slice(origins);
            }
        }
        let parts = rebuilt
            .iter()
            .chain(&moved)
            .map(|&c| self.parts.chains[c as usize].part)
            .chain(items.iter().map(|&item| self.item_part(item)));
        let ranges = merge(parts.map(|p| [p.first_vertex, p.vertices]).collect());
        let moving_segments: Vec<u32> = subtree
            .iter()
            .flat_map(|&d| tree.branches[d as usize].segments.iter().copied())
            .collect();
        Some(DragSession {
            branch,
            rebuilt,
            moved,
            items,
            base_positions,
            base_normals,
            base_origins,
            base_end: self.end_motion(branch),
            fixed_joints: self.fixed_joints(&moving_segments, skeleton),
            fixed_bounds: bounds_outside(&mesh.positions, &ranges),
            ranges,
            moving_segments,
        })
    }

    /// The chains a drag of `branch` (whose `subtree` it is) rebuilds, those holding its
    /// segments, and those it moves rigidly, the others below it; each sorted.
    fn dragged_chains(&self, branch: u32, subtree: &[u32]) -> (Vec<u32>, Vec<u32>) {
        let tree = &self.tree;
        let chain_of = |s: &u32| self.parts.segment_chain[*s as usize];
        let mut rebuilt: Vec<u32> = tree.branches[branch as usize]
            .segments
            .iter()
            .map(chain_of)
            .filter(|&c| c != NO_CHAIN)
            .collect();
        rebuilt.sort_unstable();
        rebuilt.dedup();
        let mut moved: Vec<u32> = subtree[1..]
            .iter()
            .flat_map(|&d| tree.branches[d as usize].segments.iter().map(chain_of))
            .filter(|&c| c != NO_CHAIN && rebuilt.binary_search(&c).is_err())
            .collect();
        moved.sort_unstable();
        moved.dedup();
        (rebuilt, moved)
    }

    /// The motion of `branch`'s end joint, edited or inherited.
    fn end_motion(&self, branch: u32) -> Rigid {
        let inherited = self.inherited[branch as usize];
        let Some(local) = &self.edits[branch as usize] else {
            return inherited;
        };
        let mut joints = Vec::new();
        deform::edited_motions(
            &self.original,
            &self.tree,
            branch,
            local,
            &inherited,
            &mut joints,
        );
        joints.last().copied().unwrap_or_default()
    }

    /// The sorted joint keys of the ends of every segment but `moving_segments`, where they are
    /// in `skeleton`.
    fn fixed_joints(&self, moving_segments: &[u32], skeleton: &Skeleton) -> Vec<[u64; 3]> {
        let mut moving = vec![false; self.original.segments.len()];
        moving_segments
            .iter()
            .for_each(|&s| moving[s as usize] = true);
        let mut fixed_joints: Vec<[u64; 3]> = (0..self.original.segments.len())
            .filter(|&s| !moving[s])
            .map(|s| mesh::joint_key(skeleton.segments[s].end))
            .collect();
        fixed_joints.sort_unstable();
        fixed_joints
    }

    /// Where `item` lies in the current mesh.
    pub(super) fn item_part(&self, item: Item) -> parts::Part {
        match item {
            Item::Polygon(i) => self.parts.polygons[i as usize],
            Item::Surface(i) => self.parts.surfaces[i as usize],
            Item::Sphere(i) => self.parts.spheres[i as usize],
        }
    }

    /// Re-meshes what a drag of `branch` changed; `Err(reason)` when the whole mesh must be
    /// rebuilt (nothing is promised about `mesh` then).
    pub(super) fn remesh_dragged(
        &mut self,
        branch: u32,
        joints: &[Rigid],
        skeleton: &Skeleton,
        mesh: &mut MeshBuffers,
    ) -> Result<(), String> {
        let Some(session) = &self.session else {
            return Err("the mesh is the lines fallback".into());
        };
        self.check_joints(branch, skeleton)?;
        self.check_start_caps(session, skeleton)?;
        self.check_end_domes(skeleton)?;
        self.rebuild_chains(session, skeleton, mesh)?;
        let end = joints
            .last()
            .copied()
            .unwrap_or(self.inherited[branch as usize]);
        self.move_chains(session, &session.base_end.inverse().then(&end), mesh);
        self.remesh_items(&session.items, skeleton, mesh)?;
        let mut bounds = session.fixed_bounds;
        for &r in &session.ranges {
            bounds = union(bounds, bounds_of(&mesh.positions, r));
        }
        self.change = MeshChange {
            full: false,
            reason: None,
            ranges: session.ranges.clone(),
            bounds: bounds.map_or([[0.0; 3]; 2], |b| b.map(|p| p.map(f64::from))),
        };
        Ok(())
    }

    /// Fails when a joint that may have turned sharper or straighter (along `branch`, where it
    /// leaves its parent's axis, and where its axis continues) now splits or joins its tube.
    fn check_joints(&self, branch: u32, skeleton: &Skeleton) -> Result<(), String> {
        let b = &self.tree.branches[branch as usize];
        let last = *b.segments.last().unwrap_or(&0);
        let continuation = b
            .children
            .iter()
            .map(|&c| self.tree.branches[c as usize].segments[0])
            .find(|&s| skeleton.segments[s as usize].previous == Some(last));
        for &s in b.segments.iter().chain(continuation.as_ref()) {
            if let Some(p) = skeleton.segments[s as usize].previous {
                let (cp, cs) = (
                    self.parts.segment_chain[p as usize],
                    self.parts.segment_chain[s as usize],
                );
                let was = cp != NO_CHAIN && cp == cs;
                if was != parts::joins(skeleton, p, s, self.unit) {
                    return Err(format!(
                        "a joint of the branch turned {} enough to {} its tube",
                        if was { "sharp" } else { "straight" },
                        if was { "split" } else { "join" }
                    ));
                }
            }
        }
        Ok(())
    }

    /// Fails when a tube that started hidden at another segment's end no longer does, or the
    /// other way round (its start cap would appear or vanish).
    fn check_start_caps(&self, session: &DragSession, skeleton: &Skeleton) -> Result<(), String> {
        let mut moving_joints: Vec<[u64; 3]> = session
            .moving_segments
            .iter()
            .map(|&s| mesh::joint_key(skeleton.segments[s as usize].end))
            .collect();
        moving_joints.sort_unstable();
        for c in &self.parts.chains {
            let start = mesh::joint_key(skeleton.segments[c.segments[0] as usize].start);
            let hidden = session.fixed_joints.binary_search(&start).is_ok()
                || moving_joints.binary_search(&start).is_ok();
            if hidden == c.start_cap {
                return Err("a tube's start cap appeared or vanished".into());
            }
        }
        Ok(())
    }

    /// Fails when a tube's end gained or lost the branch that starts there (its rounded end would
    /// become a flat cap, or the other way round).
    fn check_end_domes(&self, skeleton: &Skeleton) -> Result<(), String> {
        let chains = self.parts.chains.iter();
        let ends = parts::chain_ends(skeleton, chains.clone().map(|c| &c.segments[..]));
        for (c, (_, end_dome)) in chains.zip(ends) {
            if end_dome != c.end_dome {
                return Err("a tube's rounded end appeared or vanished".into());
            }
        }
        Ok(())
    }

    /// Rebuilds the tubes of the chains holding the dragged branch's segments in place; fails
    /// when one no longer has the same layout.
    fn rebuild_chains(
        &self,
        session: &DragSession,
        skeleton: &Skeleton,
        mesh: &mut MeshBuffers,
    ) -> Result<(), String> {
        for &c in &session.rebuilt {
            let chain = &self.parts.chains[c as usize];
            let (alone, ranges) = parts::chain_mesh(
                skeleton,
                self.alone(),
                &chain.segments,
                chain.start_cap,
                chain.end_dome,
            );
            if ranges != chain.ranges || !parts::write_part(mesh, &chain.part, &alone, false) {
                return Err("a rebuilt tube has another number of rings".into());
            }
        }
        Ok(())
    }

    /// Moves the chains below the dragged branch by `delta` from where they were when the drag
    /// began (their vertices, normals and growth origins).
    fn move_chains(&self, session: &DragSession, delta: &Rigid, mesh: &mut MeshBuffers) {
        let point = |b: &[f32]| {
            let p = delta.point(DVec3::new(b[0] as f64, b[1] as f64, b[2] as f64));
            [p.x as f32, p.y as f32, p.z as f32]
        };
        let vector = |b: &[f32]| {
            let q = delta.vector(DVec3::new(b[0] as f64, b[1] as f64, b[2] as f64));
            [q.x as f32, q.y as f32, q.z as f32]
        };
        let mut at = 0;
        for &c in &session.moved {
            let p = &self.parts.chains[c as usize].part;
            let n = 3 * p.vertices as usize;
            let v = 3 * p.first_vertex as usize;
            moved(
                &mut mesh.positions[v..v + n],
                &session.base_positions[at..at + n],
                point,
            );
            moved(
                &mut mesh.normals[v..v + n],
                &session.base_normals[at..at + n],
                vector,
            );
            if let (Some(to), Some(from)) = (
                mesh.growth_origins.get_mut(v..v + n),
                session.base_origins.get(at..at + n),
            ) {
                moved(to, from, point);
            }
            at += n;
        }
    }

    /// Meshes `items` (the polygons, leaves and spheres of the dragged branch and below) anew in
    /// place; fails when one has another number of triangles.
    fn remesh_items(
        &self,
        items: &[Item],
        skeleton: &Skeleton,
        mesh: &mut MeshBuffers,
    ) -> Result<(), String> {
        for &item in items {
            let part = self.item_part(item);
            let alone = match item {
                Item::Polygon(i) => parts::polygon_mesh(skeleton, self.alone(), i as usize),
                Item::Surface(i) => parts::surface_mesh(skeleton, self.alone(), i as usize),
                Item::Sphere(i) => parts::sphere_mesh(skeleton, self.alone(), i as usize),
            };
            if !parts::write_part(mesh, &part, &alone, true) {
                return Err(
                    "a polygon or leaf is triangulated into another number of triangles".into(),
                );
            }
        }
        Ok(())
    }
}

/// Writes `motion` of each triple of `base` into `to` (as long).
fn moved(to: &mut [f32], base: &[f32], motion: impl Fn(&[f32]) -> [f32; 3]) {
    for (t, b) in to.chunks_exact_mut(3).zip(base.chunks_exact(3)) {
        t.copy_from_slice(&motion(b));
    }
}

/// The bounds of the vertices outside `ranges` (sorted, disjoint); `None` for no vertex.
fn bounds_outside(positions: &[f32], ranges: &[[u32; 2]]) -> Option<Bounds> {
    let vertices = (positions.len() / 3) as u32;
    let mut bounds = None;
    let mut from = 0;
    for r in ranges.iter().copied().chain([[vertices, 0]]) {
        bounds = union(bounds, bounds_of(positions, [from, r[0] - from]));
        from = r[0] + r[1];
    }
    bounds
}

/// The bounds of vertices `range[0] .. range[0] + range[1]`; `None` for no vertex.
fn bounds_of(positions: &[f32], range: [u32; 2]) -> Option<Bounds> {
    let (from, to) = (3 * range[0] as usize, 3 * (range[0] + range[1]) as usize);
    let points = positions.get(from..to)?.chunks_exact(3);
    let mut out: Option<Bounds> = None;
    for p in points {
        let b = out.get_or_insert([[p[0], p[1], p[2]]; 2]);
        for k in 0..3 {
            b[0][k] = b[0][k].min(p[k]);
            b[1][k] = b[1][k].max(p[k]);
        }
    }
    out
}

/// The bounds around both `a` and `b`.
fn union(a: Option<Bounds>, b: Option<Bounds>) -> Option<Bounds> {
    match (a, b) {
        (Some(a), Some(b)) => Some([
            [0, 1, 2].map(|k| a[0][k].min(b[0][k])),
            [0, 1, 2].map(|k| a[1][k].max(b[1][k])),
        ]),
        (a, None) => a,
        (None, b) => b,
    }
}

/// Sorts (first, count) ranges and merges those that touch or overlap.
fn merge(mut ranges: Vec<[u32; 2]>) -> Vec<[u32; 2]> {
    ranges.retain(|r| r[1] > 0);
    ranges.sort_unstable();
    let mut out: Vec<[u32; 2]> = Vec::with_capacity(ranges.len());
    for r in ranges {
        match out.last_mut() {
            Some(last) if r[0] <= last[0] + last[1] => {
                last[1] = last[1].max(r[0] + r[1] - last[0]);
            }
            _ => out.push(r),
        }
    }
    out
}
