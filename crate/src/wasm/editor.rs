//! Branch editing at the boundary: [`PlantEditor`], a plant whose branches are being edited.

use super::options::{ViewOptionsFields, ViewOptionsObject};
use crate::branches::{parse_edits, write_edits, DragError, NO_BRANCH};
use crate::pipeline;
use wasm_bindgen::prelude::*;

/// A plant whose branches are being edited (see `crate::branches`).
#[wasm_bindgen]
pub struct PlantEditor {
    editor: pipeline::PlantEditor,
}

plant_mesh_getters!(PlantEditor);

#[wasm_bindgen]
impl PlantEditor {
    /// The place of each branch among its parent's children, or among the roots (the last
    /// number of its path; a path is the places from its root down to it). Not every path whole:
    /// a comb of n forks has paths n deep, n²/2 numbers together.
    #[wasm_bindgen(js_name = branchRanks)]
    pub fn branch_ranks(&self) -> js_sys::Uint32Array {
        let tree = self.editor.tree();
        let ranks: Vec<u32> = tree.branches.iter().map(|b| b.rank).collect();
        js_sys::Uint32Array::from(&ranks[..])
    }

    /// The parent of each branch; 4294967295 (u32::MAX) for a root.
    #[wasm_bindgen(js_name = branchParents)]
    pub fn branch_parents(&self) -> js_sys::Uint32Array {
        let tree = self.editor.tree();
        let parents: Vec<u32> = tree
            .branches
            .iter()
            .map(|b| b.parent.unwrap_or(NO_BRANCH))
            .collect();
        js_sys::Uint32Array::from(&parents[..])
    }

    /// The Bézier control points of every branch where they are now: 12 floats per branch
    /// (P0, P1, P2, P3, each x, y, z). P0 is where the branch attaches; P1 to P3 can be dragged.
    #[wasm_bindgen(js_name = branchControlPoints)]
    pub fn branch_control_points(&self) -> js_sys::Float32Array {
        let n = self.editor.tree().len() as u32;
        float_triples((0..n).flat_map(|b| self.editor.control_points(b)))
    }

    /// The joints of branch `branch` where they are now (3 floats each); empty for no branch.
    #[wasm_bindgen(js_name = branchJoints)]
    pub fn branch_joints(&self, branch: u32) -> js_sys::Float32Array {
        float_triples(self.editor.joints(branch))
    }

    /// The parameter of each joint of branch `branch` on its curve (0 to 1, by length).
    #[wasm_bindgen(js_name = branchParameters)]
    pub fn branch_parameters(&self, branch: u32) -> js_sys::Float32Array {
        let params: Vec<f32> = self
            .editor
            .tree()
            .branches
            .get(branch as usize)
            .map_or_else(Vec::new, |b| {
                b.fit.params.iter().map(|&t| t as f32).collect()
            });
        js_sys::Float32Array::from(&params[..])
    }

    /// The branch that drew each triangle: (first triangle, branch) pairs sorted like `ranges()`;
    /// branch 4294967295 for what grew from no segment.
    #[wasm_bindgen(js_name = branchRanges)]
    pub fn branch_ranges(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.editor.branch_ranges()[..])
    }

    /// Replaces every edit by those of `edits` (the edits document, `docs/LANGUAGE.md`) and
    /// rebuilds the plant's geometry whole. Returns the report as JSON: `{"applied": [paths],
    /// "notApplied": [{"path", "reason"}]}`. Throws when the document is malformed.
    #[wasm_bindgen(js_name = applyEdits)]
    pub fn apply_edits(&mut self, edits: &str) -> Result<String, JsError> {
        let edits = parse_edits(edits).map_err(|e| JsError::new(&e))?;
        Ok(self.editor.apply_edits(&edits).to_json())
    }

    /// The edits in force as an edits document (JSON).
    pub fn edits(&self) -> String {
        write_edits(&self.editor.edits())
    }

    /// Drags handle `handle` (1, 2 or 3) of branch `branch` to (x, y, z): the branch's edit
    /// changes and only what moved is re-meshed. Returns true when the whole mesh was rebuilt
    /// (read every array again; `changeReason()` says why); otherwise read only the changed
    /// vertices (`changedRanges`, `changedPositions`, `changedNormals`, `changedUvs`,
    /// `changedGrowthOrigins`). Throws on a
    /// bad branch, handle or position; throws an error named `DragRefused` (and changes nothing)
    /// for a target whose edit an edits document could not hold, so `edits()` always writes a
    /// document `applyEdits` accepts.
    pub fn drag(
        &mut self,
        branch: u32,
        handle: u32,
        x: f64,
        y: f64,
        z: f64,
    ) -> Result<bool, JsValue> {
        self.editor
            .drag(branch, handle as usize, glam::DVec3::new(x, y, z))
            .map(|change| change.full)
            .map_err(|e| {
                let error = js_sys::Error::new(&e.to_string());
                if let DragError::OutOfReach(_) = e {
                    error.set_name("DragRefused");
                }
                error.into()
            })
    }

    /// Why the last edit rebuilt the whole mesh; `undefined` when it did not.
    #[wasm_bindgen(js_name = changeReason)]
    pub fn change_reason(&self) -> Option<String> {
        let change = self.editor.last_change();
        change
            .full
            .then(|| change.reason.clone().unwrap_or_default())
    }

    /// The vertices the last edit changed: (first vertex, count) pairs, sorted and disjoint.
    #[wasm_bindgen(js_name = changedRanges)]
    pub fn changed_ranges(&self) -> js_sys::Uint32Array {
        let ranges = &self.editor.last_change().ranges;
        let flat: Vec<u32> = ranges.iter().flatten().copied().collect();
        js_sys::Uint32Array::from(&flat[..])
    }

    /// The positions of the changed vertices, range after range (3 floats per vertex).
    #[wasm_bindgen(js_name = changedPositions)]
    pub fn changed_positions(&self) -> js_sys::Float32Array {
        self.gather(&self.editor.plant().mesh.positions, 3)
    }

    /// The normals of the changed vertices, range after range.
    #[wasm_bindgen(js_name = changedNormals)]
    pub fn changed_normals(&self) -> js_sys::Float32Array {
        self.gather(&self.editor.plant().mesh.normals, 3)
    }

    /// The texture coordinates of the changed vertices, range after range (2 floats per vertex:
    /// a re-meshed tube's v follows its new length).
    #[wasm_bindgen(js_name = changedUvs)]
    pub fn changed_uvs(&self) -> js_sys::Float32Array {
        self.gather(&self.editor.plant().mesh.uvs, 2)
    }

    /// The growth origins of the changed vertices, range after range (3 floats per vertex);
    /// empty when the mesh carries no growth arrays. (Their growth times do not change: an edit
    /// moves where a branch grows, not when.)
    #[wasm_bindgen(js_name = changedGrowthOrigins)]
    pub fn changed_growth_origins(&self) -> js_sys::Float32Array {
        self.gather(&self.editor.plant().mesh.growth_origins, 3)
    }

    /// Meshes the edited plant again with other view options.
    pub fn remesh(&mut self, options: &ViewOptionsObject) -> Result<(), JsError> {
        let view = ViewOptionsFields::read(options)?;
        self.editor.remesh(&view.mesh());
        Ok(())
    }
}

impl PlantEditor {
    /// Edits `plant`, meshed with its skeleton (`PlantBuild.intoEditor`).
    pub(super) fn new(plant: pipeline::Plant) -> Self {
        PlantEditor {
            editor: pipeline::PlantEditor::new(plant),
        }
    }

    /// The plant whose mesh the getters copy.
    fn plant(&self) -> &pipeline::Plant {
        self.editor.plant()
    }

    /// The values of the changed vertices in `array` (`width` floats per vertex), range after
    /// range.
    fn gather(&self, array: &[f32], width: usize) -> js_sys::Float32Array {
        let change = self.editor.last_change();
        let mut out = Vec::with_capacity(width * change.vertices());
        for r in &change.ranges {
            let from = (width * r[0] as usize).min(array.len());
            let to = from.saturating_add(width * r[1] as usize).min(array.len());
            out.extend_from_slice(&array[from..to]);
        }
        js_sys::Float32Array::from(&out[..])
    }
}

/// Points as 3 floats each (x, y, z).
fn float_triples(points: impl IntoIterator<Item = glam::DVec3>) -> js_sys::Float32Array {
    let flat: Vec<f32> = points
        .into_iter()
        .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
        .collect();
    js_sys::Float32Array::from(&flat[..])
}
