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
//! Growth in time (with `MeshOptions::growth`): an edit moves where a branch grows, not when. The
//! mesh's growth times are the unedited plant's schedule ([`mesh::growth_schedule`] of the
//! unedited skeleton), its growth origins where the edited skeleton puts each element; a drag
//! writes both over the parts it re-meshes and moves the moved chains' origins with them, so the
//! growth arrays equal those of the whole mesh of the same edits.
//!
//! Widths: an edited plant keeps the width unit of the unedited one (a drag that makes the
//! plant a little larger does not thin every branch), so the mesh is built with
//! `WidthUnit::Absolute` of that unit.

mod drag;

use super::deform::{self, Rigid};
use super::edits::{check_edit, BranchEdit, EditReport, NotApplied, MAX_EDITS, MAX_OFFSET};
use super::{BranchTree, Item, NO_BRANCH};
use crate::mesh::parts::{Alone, MeshParts};
use crate::mesh::{self, GrowthSchedule, MeshBuffers, MeshOptions, WidthUnit};
use crate::turtle::Skeleton;
use drag::DragSession;
use glam::DVec3;

/// Why [`BranchEditor::drag`] refused, changing nothing.
#[derive(Clone, Debug, PartialEq)]
pub enum DragError {
    /// A caller's mistake: no such branch or handle, or a position that is not finite.
    Invalid(String),
    /// A target the edits document could not hold (a handle moved more than
    /// [`MAX_OFFSET`] branch lengths, a branch of no length, a path or an edit count past the
    /// document's limits): a user's drag too far, to be ignored, not a bug.
    OutOfReach(String),
}

impl std::fmt::Display for DragError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            DragError::Invalid(message) | DragError::OutOfReach(message) => f.write_str(message),
        }
    }
}

impl From<DragError> for String {
    fn from(error: DragError) -> String {
        error.to_string()
    }
}

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
    /// The unedited skeleton's growth times, once a mesh grows in time (see the module's doc).
    schedule: Option<GrowthSchedule>,
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
            schedule: None,
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

    /// How an element of the current mesh is meshed alone (its options, unit and growth times).
    pub fn alone(&self) -> Alone<'_> {
        Alone {
            options: &self.options,
            unit: self.unit,
            schedule: self.schedule.as_ref(),
        }
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
            path: self.tree.path(branch),
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
        if self.options.with_growth() && self.schedule.is_none() {
            self.schedule = Some(mesh::growth_schedule(&self.original));
        }
        let (mesh, parts) =
            mesh::build_mesh_with_schedule(skeleton, &self.options, self.schedule.as_ref());
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
    /// [`MeshChange::full`]). Errors name a bad branch, handle or position ([`DragError::Invalid`])
    /// or a target whose edit the edits document could not hold ([`DragError::OutOfReach`]); either
    /// way nothing changes, so every edit a drag makes is one [`parse_edits`](super::parse_edits)
    /// accepts.
    pub fn drag(
        &mut self,
        branch: u32,
        handle: usize,
        position: DVec3,
        skeleton: &mut Skeleton,
        mesh: &mut MeshBuffers,
    ) -> Result<&MeshChange, DragError> {
        if branch as usize >= self.tree.len() {
            return Err(DragError::Invalid(format!(
                "no branch {branch}: the plant has {} branches",
                self.tree.len()
            )));
        }
        if !(1..=3).contains(&handle) {
            return Err(DragError::Invalid(format!(
                "handle {handle}: the handles are 1, 2 and 3 (P1, P2, P3)"
            )));
        }
        if !position.is_finite() {
            return Err(DragError::Invalid("the position is not finite".into()));
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
        // Refused here, before anything changes, when the edit would be one the edits document
        // cannot hold: whatever a drag makes, `edits()` writes and `parse_edits` reads back.
        let mut handles = self.edits[branch as usize].unwrap_or([DVec3::ZERO; 3]);
        handles[handle - 1] = local;
        if !local.is_finite() {
            return Err(DragError::OutOfReach(
                "the branch has no length, so its handles cannot be placed in branch lengths"
                    .into(),
            ));
        }
        if local.abs().max_element() > MAX_OFFSET {
            return Err(DragError::OutOfReach(format!(
                "the target is {:.0} branch lengths from the handle's place; an edit moves a handle at most {MAX_OFFSET} branch lengths",
                local.abs().max_element()
            )));
        }
        if let Err(e) = check_edit(b.depth as usize, &handles) {
            return Err(DragError::OutOfReach(format!(
                "the edit could not be kept: {e}"
            )));
        }
        if self.edits[branch as usize].is_none()
            && self.edits.iter().filter(|e| e.is_some()).count() >= MAX_EDITS
        {
            return Err(DragError::OutOfReach(format!(
                "the plant already has {MAX_EDITS} edited branches, the most an edits document holds"
            )));
        }
        if self.session.as_ref().is_none_or(|s| s.branch != branch) {
            self.session = self.start_session(branch, skeleton, mesh);
        }
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
