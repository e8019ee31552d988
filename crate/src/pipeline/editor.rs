//! Editing a plant's branches by their Bézier handles ([`crate::branches`]): the plant with its
//! edits applied, meshed whole or, while a handle is dragged, only where it moved.

use super::Plant;
use crate::branches::{BranchEdit, BranchEditor, BranchTree, DragError, EditReport, MeshChange};
use crate::mesh::MeshOptions;
use glam::DVec3;

/// One branch as the studio shows it (see [`crate::branches`]).
#[derive(Clone, Debug, PartialEq)]
pub struct BranchInfo {
    pub path: Vec<u32>,
    pub parent: Option<u32>,
    pub children: Vec<u32>,
    /// Its segments, in order along the axis.
    pub segments: Vec<u32>,
    /// Its Bézier control points `P0 … P3` where they are now (edits and ancestors' edits
    /// included); `P0` is where it attaches.
    pub control: [DVec3; 4],
    /// The parameter of each of its joints on the curve (by cumulative length, 0 to 1).
    pub params: Vec<f64>,
}

/// A plant being edited: its own copy of the plant (edited), and the branch editor.
#[derive(Clone, Debug)]
pub struct PlantEditor {
    editor: BranchEditor,
    plant: Plant,
}

impl PlantEditor {
    /// Starts editing `plant` (unedited). The plant is meshed once more, to record where each
    /// part of the mesh lies.
    pub fn new(mut plant: Plant) -> PlantEditor {
        let (editor, mesh) =
            BranchEditor::new(&plant.skeleton, &plant.mesh_options, plant.mesh.width_unit);
        plant.mesh = mesh;
        plant.meshed();
        PlantEditor { editor, plant }
    }

    /// The plant with its edits.
    pub fn plant(&self) -> &Plant {
        &self.plant
    }

    /// The plant with its edits, the editor done.
    pub fn into_plant(self) -> Plant {
        self.plant
    }

    /// The branch editor itself (its options, layout, last change).
    pub fn branch_editor(&self) -> &BranchEditor {
        &self.editor
    }

    /// The branch tree (of the unedited plant: edits move branches, never make or remove one).
    pub fn tree(&self) -> &BranchTree {
        self.editor.tree()
    }

    /// Every branch: path, parent, children, segments, and its control points where they are now.
    pub fn branches(&self) -> Vec<BranchInfo> {
        let tree = self.editor.tree();
        (0..tree.len() as u32)
            .map(|b| {
                let branch = &tree.branches[b as usize];
                BranchInfo {
                    path: tree.path(b),
                    parent: branch.parent,
                    children: branch.children.clone(),
                    segments: branch.segments.clone(),
                    control: self.editor.control_points(b),
                    params: branch.fit.params.clone(),
                }
            })
            .collect()
    }

    /// Where branch `branch`'s control points `P0 … P3` are now.
    pub fn control_points(&self, branch: u32) -> [DVec3; 4] {
        self.editor.control_points(branch)
    }

    /// The joints of branch `branch` where they are now (empty for no such branch).
    pub fn joints(&self, branch: u32) -> Vec<DVec3> {
        let tree = self.editor.tree();
        if (branch as usize) < tree.len() {
            tree.joints(&self.plant.skeleton, branch)
        } else {
            Vec::new()
        }
    }

    /// The branch that drew each triangle, as (first triangle, branch) pairs.
    pub fn branch_ranges(&self) -> Vec<u32> {
        self.editor.branch_ranges()
    }

    /// Replaces all edits by `edits` (an empty list undoes every edit) and rebuilds the edited
    /// skeleton and the whole mesh. Edits whose path names no branch are reported, not errors.
    pub fn apply_edits(&mut self, edits: &[BranchEdit]) -> EditReport {
        let plant = &mut self.plant;
        let report = self
            .editor
            .apply(edits, &mut plant.skeleton, &mut plant.mesh);
        plant.meshed();
        report
    }

    /// The edits in force (applied ones only), in branch order.
    pub fn edits(&self) -> Vec<BranchEdit> {
        self.editor.edits()
    }

    /// Drags handle `handle` (1, 2, 3 for P1, P2, P3) of branch `branch` to `position`: the
    /// branch's edit changes, it and its descendants move, and only the changed part of the mesh
    /// is rebuilt (see [`MeshChange`]). The stats' bounds follow. Errors name a bad branch,
    /// handle or position, or a target too far for the edits document ([`DragError`]); then
    /// nothing changed.
    pub fn drag(
        &mut self,
        branch: u32,
        handle: usize,
        position: DVec3,
    ) -> Result<MeshChange, DragError> {
        let plant = &mut self.plant;
        let change = self.editor.drag(
            branch,
            handle,
            position,
            &mut plant.skeleton,
            &mut plant.mesh,
        )?;
        let (full, bounds) = (change.full, change.bounds);
        if full {
            plant.meshed();
        } else {
            plant.stats.bounds = bounds;
        }
        Ok(self.editor.last_change().clone())
    }

    /// What the last edit changed in the mesh.
    pub fn last_change(&self) -> &MeshChange {
        self.editor.last_change()
    }

    /// Meshes the edited plant again with other view options.
    pub fn remesh(&mut self, options: &MeshOptions) {
        let plant = &mut self.plant;
        plant.mesh_options = options.clone();
        plant.mesh = self.editor.remesh(&plant.skeleton, options);
        plant.meshed();
    }
}
