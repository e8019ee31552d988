//! The state of an edited plant: the unedited skeleton, its branches, the edits, and the layout
//! of the current mesh, so that dragging one handle rebuilds only what it changes.
//!
//! **Applying a list of edits** ([`BranchEditor::apply`]) places every branch anew from the
//! unedited skeleton and meshes the whole plant: exact, and what exports and the command line
//! use. **Dragging a handle** ([`BranchEditor::drag`]) places only the dragged branch and its
//! descendants, then re-meshes only (1) the tubes of the chains holding the dragged branch's
//! segments, rebuilt, (2) the tubes of the chains below it, moved rigidly from where they were
//! when the drag began (positions and normals), and (3) the polygons, leaves and spheres of the
//! dragged branch and below, meshed anew. The result equals a full re-mesh of the edited
//! skeleton (up to `f32` rounding) unless the mesh's topology changes: a joint of the branch
//! turns sharp enough to split its tube (or straight enough to join it), a tube's start cap
//! appears or vanishes, or a part's vertex or triangle count or provenance changes. Then the
//! whole mesh is rebuilt and [`MeshChange::full`] says so, with the reason.
//!
//! Widths: an edited plant keeps the width unit of the unedited one (a drag that makes the
//! plant a little larger does not thin every branch), so the mesh is built with
//! `WidthUnit::Absolute` of that unit.

use super::deform::{self, Rigid};
use super::edits::{BranchEdit, EditReport, NotApplied};
use super::{BranchTree, Item, NO_BRANCH};
use crate::mesh::parts::{self, MeshParts, NO_CHAIN};
use crate::mesh::{self, MeshBuffers, MeshOptions, WidthUnit};
use crate::turtle::Skeleton;
use glam::DVec3;

/// Which vertices a change touched.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshChange {
    /// The whole mesh was rebuilt: its sizes, indices and ranges may have changed too.
    pub full: bool,
    /// Why it was rebuilt whole.
    pub reason: Option<String>,
    /// The vertices whose positions and normals changed: (first vertex, count), sorted and
    /// disjoint. After a full rebuild: every vertex.
    pub ranges: Vec<[u32; 2]>,
    /// The bounds of the mesh's vertices after the change (as `MeshBuffers::bounds`).
    pub bounds: [[f64; 3]; 2],
}

impl MeshChange {
    /// Vertices changed in all.
    pub fn vertices(&self) -> usize {
        self.ranges.iter().map(|r| r[1] as usize).sum()
    }
}

/// What one drag rebuilds and moves, fixed while the same branch is dragged.
#[derive(Clone, Debug)]
struct DragSession {
    branch: u32,
    /// Chains holding the branch's segments: rebuilt every frame.
    rebuilt: Vec<u32>,
    /// Chains below the branch: moved rigidly every frame.
    moved: Vec<u32>,
    /// Polygons, leaves and spheres of the branch and below: meshed anew every frame.
    items: Vec<Item>,
    /// The moved chains' positions and normals when the drag began, chain after chain.
    base_positions: Vec<f32>,
    base_normals: Vec<f32>,
    /// The motion of the branch's end joint when the drag began.
    base_end: Rigid,
    ranges: Vec<[u32; 2]>,
    /// The segments of the branch and below (their ends move), and the sorted joint keys of
    /// all other segments' ends (fixed while the drag lasts): where tubes may start hidden.
    moving_segments: Vec<u32>,
    fixed_joints: Vec<[u64; 3]>,
    /// The bounds of the vertices outside `ranges` (fixed while the drag lasts).
    fixed_bounds: Option<[[f32; 3]; 2]>,
}

/// An edited plant (see the module documentation).
#[derive(Clone, Debug)]
pub struct BranchEditor {
    original: Skeleton,
    tree: BranchTree,
    /// Each branch's edit (offsets of P1, P2, P3 as in [`BranchEdit::handles`]).
    edits: Vec<Option<[DVec3; 3]>>,
    /// The motion each branch inherits from its parent's end joint.
    inherited: Vec<Rigid>,
    options: MeshOptions,
    unit: f64,
    parts: MeshParts,
    session: Option<DragSession>,
    change: MeshChange,
}

impl BranchEditor {
    /// Starts editing `skeleton` (unedited), meshed with `options` at width unit `unit` (the
    /// unit its mesh was built with). Returns the editor and the mesh, meshed again to record
    /// its layout (equal to the mesh built with `options`).
    pub fn new(
        skeleton: &Skeleton,
        options: &MeshOptions,
        unit: f64,
    ) -> (BranchEditor, MeshBuffers) {
        let tree = BranchTree::new(skeleton);
        let n = tree.len();
        let mut editor = BranchEditor {
            original: skeleton.clone(),
            tree,
            edits: vec![None; n],
            inherited: vec![Rigid::IDENTITY; n],
            options: MeshOptions::default(),
            unit,
            parts: MeshParts::default(),
            session: None,
            change: MeshChange::default(),
        };
        let mesh = editor.remesh(skeleton, options);
        (editor, mesh)
    }

    /// The branches of the unedited skeleton.
    pub fn tree(&self) -> &BranchTree {
        &self.tree
    }

    /// The unedited skeleton.
    pub fn original(&self) -> &Skeleton {
        &self.original
    }

    /// The layout of the current mesh.
    pub fn parts(&self) -> &MeshParts {
        &self.parts
    }

    /// The mesh options edits are meshed with (the width unit fixed).
    pub fn options(&self) -> &MeshOptions {
        &self.options
    }

    /// What the last [`apply`](Self::apply), [`drag`](Self::drag) or
    /// [`remesh`](Self::remesh) changed in the mesh.
    pub fn last_change(&self) -> &MeshChange {
        &self.change
    }

    /// Branch `branch`'s edit, if it has one.
    pub fn edit(&self, branch: u32) -> Option<BranchEdit> {
        let handles = (*self.edits.get(branch as usize)?)?;
        Some(BranchEdit {
            path: self.tree.branches[branch as usize].path.clone(),
            handles,
        })
    }

    /// Every edit in force, in branch order.
    pub fn edits(&self) -> Vec<BranchEdit> {
        (0..self.tree.len() as u32)
            .filter_map(|b| self.edit(b))
            .collect()
    }

    /// Where `branch`'s control points `P0 … P3` are now.
    pub fn control_points(&self, branch: u32) -> [DVec3; 4] {
        deform::control_points(
            &self.original,
            &self.tree,
            branch,
            self.edits[branch as usize].as_ref(),
            &self.inherited[branch as usize],
        )
    }

    /// Meshes the whole of `skeleton` (edited) with `options` at the unedited width unit,
    /// recording its layout.
    pub fn remesh(&mut self, skeleton: &Skeleton, options: &MeshOptions) -> MeshBuffers {
        self.options = MeshOptions {
            width_unit: WidthUnit::Absolute(self.unit),
            ..options.clone()
        };
        let (mesh, parts) = mesh::build_mesh_with_parts(skeleton, &self.options);
        self.parts = parts;
        self.session = None;
        self.change = MeshChange {
            full: true,
            reason: Some("the whole plant was meshed".into()),
            ranges: vec![[0, mesh.vertex_count() as u32]],
            bounds: mesh.bounds(),
        };
        mesh
    }

    /// Replaces every edit by `edits` and places every branch anew into `skeleton` (which must
    /// hold this editor's plant, edited or not), then meshes it whole into `mesh`. An edit whose
    /// path names no branch is reported, never an error; of two edits of one branch the later
    /// one applies.
    pub fn apply(
        &mut self,
        edits: &[BranchEdit],
        skeleton: &mut Skeleton,
        mesh: &mut MeshBuffers,
    ) -> EditReport {
        let mut report = EditReport::default();
        let mut chosen: Vec<Option<usize>> = vec![None; self.tree.len()];
        let mut found: Vec<Option<u32>> = Vec::with_capacity(edits.len());
        for (k, edit) in edits.iter().enumerate() {
            match self.tree.find(&edit.path) {
                Ok(b) => {
                    chosen[b as usize] = Some(k);
                    found.push(Some(b));
                }
                Err(reason) => {
                    found.push(None);
                    report.not_applied.push(NotApplied {
                        path: edit.path.clone(),
                        reason: format!("no branch at this path: {reason}"),
                    });
                }
            }
        }
        for (k, edit) in edits.iter().enumerate() {
            if let Some(b) = found[k] {
                if chosen[b as usize] == Some(k) {
                    report.applied.push(edit.path.clone());
                } else {
                    report.not_applied.push(NotApplied {
                        path: edit.path.clone(),
                        reason: "a later edit of the same branch replaces it".into(),
                    });
                }
            }
        }
        self.edits = chosen.iter().map(|k| k.map(|k| edits[k].handles)).collect();
        self.place_all(skeleton);
        let options = self.options.clone();
        *mesh = self.remesh(skeleton, &options);
        self.change.reason = Some("edits applied".into());
        report
    }

    fn place_all(&mut self, skeleton: &mut Skeleton) {
        for &root in &self.tree.roots {
            self.inherited[root as usize] = Rigid::IDENTITY;
            deform::place_subtree(
                &self.original,
                &self.tree,
                root,
                &self.edits,
                &mut self.inherited,
                skeleton,
            );
        }
    }

    /// Moves handle `handle` (1, 2 or 3: P1, P2, P3) of `branch` to `position` (world
    /// coordinates), updating that branch's edit, re-placing it and its descendants in
    /// `skeleton`, and re-meshing only what changed in `mesh` (or all of it, see
    /// [`MeshChange::full`]). Errors name a bad branch, handle or position.
    pub fn drag(
        &mut self,
        branch: u32,
        handle: usize,
        position: DVec3,
        skeleton: &mut Skeleton,
        mesh: &mut MeshBuffers,
    ) -> Result<&MeshChange, String> {
        if branch as usize >= self.tree.len() {
            return Err(format!(
                "no branch {branch}: the plant has {} branches",
                self.tree.len()
            ));
        }
        if !(1..=3).contains(&handle) {
            return Err(format!(
                "handle {handle}: the handles are 1, 2 and 3 (P1, P2, P3)"
            ));
        }
        if !position.is_finite() {
            return Err("the position is not finite".into());
        }
        let b = &self.tree.branches[branch as usize];
        let inherited = self.inherited[branch as usize];
        let frame = deform::start_frame(&self.original, &self.tree, branch);
        let offset = inherited.inverse().point(position) - b.fit.control[handle];
        let local = DVec3::new(
            offset.dot(frame[0]),
            offset.dot(frame[1]),
            offset.dot(frame[2]),
        ) / b.length;
        if self.session.as_ref().is_none_or(|s| s.branch != branch) {
            self.session = self.start_session(branch, skeleton, mesh);
        }
        let mut handles = self.edits[branch as usize].unwrap_or([DVec3::ZERO; 3]);
        handles[handle - 1] = local;
        self.edits[branch as usize] = Some(handles);
        let joints = deform::place_subtree(
            &self.original,
            &self.tree,
            branch,
            &self.edits,
            &mut self.inherited,
            skeleton,
        );
        match self.remesh_dragged(branch, &joints, skeleton, mesh) {
            Ok(()) => {}
            Err(reason) => {
                let options = self.options.clone();
                *mesh = self.remesh(skeleton, &options);
                self.change.reason = Some(reason);
            }
        }
        Ok(&self.change)
    }

    /// The session of a drag of `branch` that begins now (`None` for the lines fallback).
    fn start_session(
        &self,
        branch: u32,
        skeleton: &Skeleton,
        mesh: &MeshBuffers,
    ) -> Option<DragSession> {
        if self.parts.lines {
            return None;
        }
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
        let subtree = tree.subtree(branch);
        let mut moved: Vec<u32> = subtree[1..]
            .iter()
            .flat_map(|&d| tree.branches[d as usize].segments.iter().map(chain_of))
            .filter(|&c| c != NO_CHAIN && rebuilt.binary_search(&c).is_err())
            .collect();
        moved.sort_unstable();
        moved.dedup();
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
        let mut ranges = Vec::new();
        for &c in &moved {
            let p = &self.parts.chains[c as usize].part;
            let (from, to) = (
                3 * p.first_vertex as usize,
                3 * (p.first_vertex + p.vertices) as usize,
            );
            base_positions.extend_from_slice(&mesh.positions[from..to]);
            base_normals.extend_from_slice(&mesh.normals[from..to]);
        }
        let parts = rebuilt
            .iter()
            .chain(&moved)
            .map(|&c| self.parts.chains[c as usize].part)
            .chain(items.iter().map(|&item| self.item_part(item)));
        for p in parts {
            ranges.push([p.first_vertex, p.vertices]);
        }
        let mut joints = Vec::new();
        let base_end = match &self.edits[branch as usize] {
            Some(local) => {
                deform::edited_motions(
                    &self.original,
                    tree,
                    branch,
                    local,
                    &self.inherited[branch as usize],
                    &mut joints,
                );
                joints.last().copied().unwrap_or_default()
            }
            None => self.inherited[branch as usize],
        };
        let moving_segments: Vec<u32> = subtree
            .iter()
            .flat_map(|&d| tree.branches[d as usize].segments.iter().copied())
            .collect();
        let mut moving = vec![false; self.original.segments.len()];
        moving_segments
            .iter()
            .for_each(|&s| moving[s as usize] = true);
        let mut fixed_joints: Vec<[u64; 3]> = mesh_key_ends(&self.original, &moving, skeleton);
        fixed_joints.sort_unstable();
        let ranges = merge(ranges);
        let mut fixed_bounds = None;
        let mut from = 0;
        for r in ranges
            .iter()
            .copied()
            .chain([[mesh.vertex_count() as u32, 0]])
        {
            fixed_bounds = union(
                fixed_bounds,
                bounds_of(&mesh.positions, [from, r[0] - from]),
            );
            from = r[0] + r[1];
        }
        Some(DragSession {
            branch,
            rebuilt,
            moved,
            items,
            base_positions,
            base_normals,
            base_end,
            ranges,
            moving_segments,
            fixed_joints,
            fixed_bounds,
        })
    }

    fn item_part(&self, item: Item) -> parts::Part {
        match item {
            Item::Polygon(i) => self.parts.polygons[i as usize],
            Item::Surface(i) => self.parts.surfaces[i as usize],
            Item::Sphere(i) => self.parts.spheres[i as usize],
        }
    }

    /// Re-meshes what a drag of `branch` changed; `Err(reason)` when the whole mesh must be
    /// rebuilt (nothing is promised about `mesh` then).
    fn remesh_dragged(
        &mut self,
        branch: u32,
        joints: &[Rigid],
        skeleton: &Skeleton,
        mesh: &mut MeshBuffers,
    ) -> Result<(), String> {
        let Some(session) = &self.session else {
            return Err("the mesh is the lines fallback".into());
        };
        let b = &self.tree.branches[branch as usize];
        // Joints that may have turned sharper or straighter: along the branch, where it leaves
        // its parent's axis, and where its axis continues.
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
        for &c in &session.rebuilt {
            let chain = &self.parts.chains[c as usize];
            let (alone, ranges) = parts::chain_mesh(
                skeleton,
                &self.options,
                self.unit,
                &chain.segments,
                chain.start_cap,
            );
            if ranges != chain.ranges || !parts::write_part(mesh, &chain.part, &alone, false) {
                return Err("a rebuilt tube has another number of rings".into());
            }
        }
        let end = joints
            .last()
            .copied()
            .unwrap_or(self.inherited[branch as usize]);
        let delta = session.base_end.inverse().then(&end);
        let mut at = 0;
        for &c in &session.moved {
            let p = &self.parts.chains[c as usize].part;
            let n = 3 * p.vertices as usize;
            let v = 3 * p.first_vertex as usize;
            let (base_p, base_n) = (
                &session.base_positions[at..at + n],
                &session.base_normals[at..at + n],
            );
            for (k, (bp, bn)) in base_p
                .chunks_exact(3)
                .zip(base_n.chunks_exact(3))
                .enumerate()
            {
                let p = delta.point(DVec3::new(bp[0] as f64, bp[1] as f64, bp[2] as f64));
                let q = delta.vector(DVec3::new(bn[0] as f64, bn[1] as f64, bn[2] as f64));
                let i = v + 3 * k;
                mesh.positions[i..i + 3].copy_from_slice(&[p.x as f32, p.y as f32, p.z as f32]);
                mesh.normals[i..i + 3].copy_from_slice(&[q.x as f32, q.y as f32, q.z as f32]);
            }
            at += n;
        }
        for &item in &session.items {
            let part = self.item_part(item);
            let alone = match item {
                Item::Polygon(i) => {
                    parts::polygon_mesh(skeleton, &self.options, self.unit, i as usize)
                }
                Item::Surface(i) => {
                    parts::surface_mesh(skeleton, &self.options, self.unit, i as usize)
                }
                Item::Sphere(i) => {
                    parts::sphere_mesh(skeleton, &self.options, self.unit, i as usize)
                }
            };
            if !parts::write_part(mesh, &part, &alone, true) {
                return Err(
                    "a polygon or leaf is triangulated into another number of triangles".into(),
                );
            }
        }
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

    /// The branch that drew each triangle of the current mesh, as (first triangle, branch)
    /// pairs sorted like `MeshBuffers::ranges` ([`NO_BRANCH`] for what grew from no segment):
    /// what picking a branch by its triangle reads.
    pub fn branch_ranges(&self) -> Vec<u32> {
        let mut out = Vec::new();
        let mut push = |first: u32, branch: u32| {
            if out.len() >= 2 && out[out.len() - 1] == branch {
                return;
            }
            if out.len() >= 2 && out[out.len() - 2] == first {
                let n = out.len();
                out[n - 1] = branch;
                return;
            }
            out.extend([first, branch]);
        };
        for c in &self.parts.chains {
            for pair in c.ranges.chunks_exact(2) {
                let branch = self
                    .tree
                    .segment_branch
                    .get(pair[1] as usize)
                    .copied()
                    .unwrap_or(NO_BRANCH);
                push(c.part.first_triangle + pair[0], branch);
            }
        }
        let mut owners = [
            vec![NO_BRANCH; self.parts.polygons.len()],
            vec![NO_BRANCH; self.parts.surfaces.len()],
            vec![NO_BRANCH; self.parts.spheres.len()],
        ];
        for (b, branch) in self.tree.branches.iter().enumerate() {
            for &(item, _) in &branch.items {
                let (kind, i) = match item {
                    Item::Polygon(i) => (0, i),
                    Item::Surface(i) => (1, i),
                    Item::Sphere(i) => (2, i),
                };
                if let Some(o) = owners[kind].get_mut(i as usize) {
                    *o = b as u32;
                }
            }
        }
        let lists = [
            &self.parts.polygons,
            &self.parts.surfaces,
            &self.parts.spheres,
        ];
        for (list, owner) in lists.into_iter().zip(&owners) {
            for (p, &b) in list.iter().zip(owner) {
                if p.triangles > 0 {
                    push(p.first_triangle, b);
                }
            }
        }
        out
    }
}

/// The joint keys of the ends of the segments that do not move (`moving[s]` false), where they
/// are in `skeleton`.
fn mesh_key_ends(original: &Skeleton, moving: &[bool], skeleton: &Skeleton) -> Vec<[u64; 3]> {
    (0..original.segments.len())
        .filter(|&s| !moving[s])
        .map(|s| mesh::joint_key(skeleton.segments[s].end))
        .collect()
}

/// The bounds of vertices `range[0] .. range[0] + range[1]`; `None` for no vertex.
fn bounds_of(positions: &[f32], range: [u32; 2]) -> Option<[[f32; 3]; 2]> {
    let (from, to) = (3 * range[0] as usize, 3 * (range[0] + range[1]) as usize);
    let points = positions.get(from..to)?.chunks_exact(3);
    let mut out: Option<[[f32; 3]; 2]> = None;
    for p in points {
        let b = out.get_or_insert([[p[0], p[1], p[2]]; 2]);
        for k in 0..3 {
            b[0][k] = b[0][k].min(p[k]);
            b[1][k] = b[1][k].max(p[k]);
        }
    }
    out
}

fn union(a: Option<[[f32; 3]; 2]>, b: Option<[[f32; 3]; 2]>) -> Option<[[f32; 3]; 2]> {
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
