//! The wasm boundary: the only file with `#[wasm_bindgen]`. A thin layer over [`crate::pipeline`];
//! the TypeScript facade in `web/src/core/` mirrors it with idiomatic types. Bulk data leaves as
//! flat typed arrays (layout: [`crate::mesh::MeshBuffers`]), each copied once out of wasm memory
//! into a fresh JavaScript array (`js_sys::Float32Array::from`); small structured data as JSON.
#![deny(clippy::unwrap_used)]

use crate::export::{self, Format};
use crate::mesh::MeshOptions;
use crate::pipeline::{self, BuildOptions};
use wasm_bindgen::prelude::*;

/// The core's version (the crate version).
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// The language's vocabulary as JSON (`crate::vocabulary::vocabulary_json`): modules, directives,
/// keywords, functions and values, each with typed parameters.
#[wasm_bindgen]
pub fn vocabulary() -> String {
    crate::vocabulary::vocabulary_json()
}

/// Runs the whole pipeline: parse -> resolve -> derive -> interpret -> mesh.
/// `iterations`: `None` takes the grammar's `#iterations`; `seed`: `None` takes `#seed` (a whole
/// number from 0 to 2^53; other values are ignored); `sides` (3 to 64, default 6) and
/// `smooth_all` (default false) are the mesh's view options. `now`, when given, is a clock
/// (JavaScript's `() => performance.now()`) read between the stages: their times come back in
/// `timings()`. The core itself reads no clock.
#[wasm_bindgen]
pub fn build(
    source: &str,
    iterations: Option<u32>,
    seed: Option<f64>,
    sides: Option<u32>,
    smooth_all: Option<bool>,
    now: Option<js_sys::Function>,
) -> Build {
    let options = build_options(iterations, seed, sides, smooth_all);
    build_reading(source, &options, now)
}

/// Runs the pipeline with `options`, reading `now` (a JavaScript clock) between the stages.
fn build_reading(source: &str, options: &BuildOptions, now: Option<js_sys::Function>) -> Build {
    let inner = match now {
        Some(now) => {
            let mut clock = || {
                now.call0(&JsValue::NULL)
                    .ok()
                    .and_then(|t| t.as_f64())
                    .unwrap_or(0.0)
            };
            pipeline::build_with_clock(source, options, &mut clock)
        }
        None => pipeline::build(source, options),
    };
    let diagnostics =
        serde_json::to_string(&inner.located_diagnostics(source)).unwrap_or_else(|_| "[]".into());
    Build { inner, diagnostics }
}

/// [`build`] up to the turtle, with every segment as a line instead of tubes (the mesh stage's
/// line fallback, which costs next to nothing): the live preview shows this sketch of a big plant
/// at once, then calls `remesh` with the same `sides` and `smooth_all` for the tubes, which are
/// then exactly [`build`]'s.
#[wasm_bindgen(js_name = buildSketch)]
pub fn build_sketch(
    source: &str,
    iterations: Option<u32>,
    seed: Option<f64>,
    now: Option<js_sys::Function>,
) -> Build {
    let mut options = build_options(iterations, seed, None, None);
    options.mesh.max_vertices = 0;
    build_reading(source, &options, now)
}

/// The options of a build from the boundary's arguments; a seed that is not a whole number from 0
/// to 2^53 is ignored (the grammar's `#seed` is used); `sides` and `smooth_all` are the view
/// options of the mesh ([`MeshOptions::view`]).
fn build_options(
    iterations: Option<u32>,
    seed: Option<f64>,
    sides: Option<u32>,
    smooth_all: Option<bool>,
) -> BuildOptions {
    let seed = seed.filter(|s| {
        s.is_finite() && *s >= 0.0 && s.fract() == 0.0 && *s <= 9.007_199_254_740_992e15
    });
    BuildOptions {
        iterations,
        seed: seed.map(|s| s as u64),
        mesh: MeshOptions::view(sides, smooth_all),
    }
}

/// Builds `source` (as [`build`] does, with the same options) and writes the model as a file to
/// download: `format` is `wrl`, `glb`, `pov`, `obj`, `iv` or `svg`; `name` is the file name without
/// extension. OBJ comes as a zip of `NAME.obj` and `NAME.mtl`. The bytes are exactly what
/// `meristem export FILE -o NAME.EXT` writes for the same grammar, iterations, seed, `--sides` and
/// `--smooth-all`. Throws when the format is unknown or the grammar has errors (callers export a
/// plant that built).
#[wasm_bindgen(js_name = exportModel)]
pub fn export_model(
    source: &str,
    format: &str,
    name: &str,
    iterations: Option<u32>,
    seed: Option<f64>,
    sides: Option<u32>,
    smooth_all: Option<bool>,
) -> Result<ExportedModel, JsError> {
    let options = build_options(iterations, seed, sides, smooth_all);
    export_reporting(source, None, format, name, &options, &mut |_| {})
}

/// The stages an export reports, in order, to [`export_model_reporting`]'s `progress`.
pub const EXPORT_STAGES: [&str; 6] = [
    "parsing",
    "deriving",
    "interpreting",
    "meshing",
    "applying edits",
    "writing",
];

/// [`export_model`] and [`export_model_with_edits`] in one, telling `progress` each stage as it
/// starts: `progress(stage, index, count)` with a stage of [`EXPORT_STAGES`] (`applying edits` only
/// when `edits` is not empty). For the studio's export worker, whose page shows the stage while the
/// core works. `edits`: an edits document, or empty for none. The bytes are those of the other two.
#[allow(clippy::too_many_arguments)]
#[wasm_bindgen(js_name = exportModelReporting)]
pub fn export_model_reporting(
    source: &str,
    edits: &str,
    format: &str,
    name: &str,
    iterations: Option<u32>,
    seed: Option<f64>,
    sides: Option<u32>,
    smooth_all: Option<bool>,
    progress: &js_sys::Function,
) -> Result<ExportedModel, JsError> {
    let options = build_options(iterations, seed, sides, smooth_all);
    let edits = (!edits.is_empty()).then_some(edits);
    export_reporting(source, edits, format, name, &options, &mut |stage| {
        let index = EXPORT_STAGES.iter().position(|s| *s == stage).unwrap_or(0);
        // A progress callback that throws changes nothing: the export goes on.
        let _ = progress.call3(
            &JsValue::NULL,
            &JsValue::from_str(stage),
            &JsValue::from_f64(index as f64),
            &JsValue::from_f64(EXPORT_STAGES.len() as f64),
        );
    })
}

/// Builds, applies `edits` and writes, calling `report` with each stage of [`EXPORT_STAGES`] as it
/// starts. The pipeline reads its clock once before the first stage and after each one; this clock
/// is a counter that reports the stage about to start.
fn export_reporting(
    source: &str,
    edits: Option<&str>,
    format: &str,
    name: &str,
    options: &BuildOptions,
    report: &mut dyn FnMut(&str),
) -> Result<ExportedModel, JsError> {
    let format = Format::from_extension(format).ok_or_else(|| {
        JsError::new(&format!(
            "unknown format '{format}'; the formats are {}",
            Format::names()
        ))
    })?;
    let edits = edits
        .map(crate::branches::parse_edits)
        .transpose()
        .map_err(|e| JsError::new(&e))?;
    let mut reads = 0usize;
    let mut clock = || {
        // Reads 0 to 3 start parse+resolve, derive, interpret and mesh; read 4 ends the mesh.
        if let Some(stage) = EXPORT_STAGES[..4].get(reads) {
            report(stage);
        }
        reads += 1;
        reads as f64
    };
    let mut result = pipeline::build_with_clock(source, options, &mut clock);
    if !result.ok() {
        return Err(JsError::new("the grammar has errors: nothing to export"));
    }
    if let Some(edits) = &edits {
        report(EXPORT_STAGES[4]);
        result.apply_edits(edits);
    }
    report(EXPORT_STAGES[5]);
    let file = export::download(format, &result.mesh, &result.skeleton, name)
        .ok_or_else(|| JsError::new("the export is larger than 4 GiB"))?;
    Ok(ExportedModel { file })
}

/// One file to download, from [`export_model`]. Free it with `.free()` once its bytes are copied.
#[wasm_bindgen]
pub struct ExportedModel {
    file: export::ExportedFile,
}

#[wasm_bindgen]
impl ExportedModel {
    /// File name with extension: `plant.glb`, or `plant.zip` for OBJ + MTL.
    #[wasm_bindgen(getter, js_name = fileName)]
    pub fn file_name(&self) -> String {
        self.file.name.clone()
    }

    /// Media type for the download (`model/gltf-binary`, `application/zip`, …).
    #[wasm_bindgen(getter, js_name = mimeType)]
    pub fn mime_type(&self) -> String {
        self.file.mime.to_string()
    }

    /// The file's bytes.
    pub fn bytes(&self) -> Vec<u8> {
        self.file.bytes.clone()
    }
}

/// The result of [`build`]. Free it with `.free()` once its arrays are copied out.
#[wasm_bindgen]
pub struct Build {
    inner: pipeline::Build,
    diagnostics: String,
}

#[wasm_bindgen]
impl Build {
    /// True when there is no error diagnostic (the geometry is present).
    #[wasm_bindgen(getter)]
    pub fn ok(&self) -> bool {
        self.inner.ok()
    }

    /// JSON array of `{severity, code, message, from, to, line, column}`; `from`/`to` are UTF-8
    /// byte offsets, `line`/`column` 1-based, columns in Unicode scalar values.
    pub fn diagnostics(&self) -> String {
        self.diagnostics.clone()
    }

    /// JSON `{modules, segments, vertices, triangles, iterations, bounds}`.
    pub fn stats(&self) -> String {
        self.inner.stats.to_json()
    }

    /// JSON `{parseResolve, derive, interpret, mesh}` in the clock's unit (milliseconds), or
    /// `null` when [`build`] was called without a clock.
    pub fn timings(&self) -> String {
        self.inner
            .timings
            .map_or_else(|| "null".into(), |t| t.to_json())
    }

    /// True when everything drawn lies in the plane z = 0 (`Skeleton::is_flat`).
    #[wasm_bindgen(getter)]
    pub fn flat(&self) -> bool {
        self.inner.skeleton.is_flat()
    }

    /// The grammar's own `#iterations` (0 when it has none or could not be resolved), whatever
    /// iterations this build ran.
    #[wasm_bindgen(getter, js_name = grammarIterations)]
    pub fn grammar_iterations(&self) -> u32 {
        self.inner
            .model
            .as_ref()
            .map_or(0, |m| m.settings.iterations)
    }

    pub fn positions(&self) -> js_sys::Float32Array {
        js_sys::Float32Array::from(&self.inner.mesh.positions[..])
    }

    pub fn normals(&self) -> js_sys::Float32Array {
        js_sys::Float32Array::from(&self.inner.mesh.normals[..])
    }

    pub fn colors(&self) -> js_sys::Float32Array {
        js_sys::Float32Array::from(&self.inner.mesh.colors[..])
    }

    pub fn indices(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.mesh.indices[..])
    }

    /// Texture coordinates, 2 floats per vertex (layout: `MeshBuffers::uvs`).
    pub fn uvs(&self) -> js_sys::Float32Array {
        js_sys::Float32Array::from(&self.inner.mesh.uvs[..])
    }

    /// Material kinds: (first triangle, kind) pairs, 0 bark, 1 leaf, 2 plain (layout:
    /// `MeshBuffers::material_ranges`).
    #[wasm_bindgen(js_name = materialRanges)]
    pub fn material_ranges(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.mesh.material_ranges[..])
    }

    /// Provenance: (first triangle, module) pairs, sorted (layout: `MeshBuffers::ranges`); the
    /// module is an index into the derived string.
    pub fn ranges(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.mesh.ranges[..])
    }

    /// For each module of the derived string, the index of the production that made it in the
    /// last step, or 4294967295 (u32::MAX) when it was copied.
    pub fn origins(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.origin[..])
    }

    /// Meshes the kept skeleton again with `sides` sides per tube (3 to 64) and, when
    /// `smooth_all`, every axis as a smooth generalized cylinder: view options that need no new
    /// derivation. The arrays and stats change; the derived string does not.
    pub fn remesh(&mut self, sides: u32, smooth_all: bool) {
        self.inner
            .remesh(&MeshOptions::view(Some(sides), Some(smooth_all)));
    }

    /// Line ends (x, y, z each) when the model was too large to mesh; empty otherwise.
    pub fn lines(&self) -> js_sys::Float32Array {
        js_sys::Float32Array::from(&self.inner.mesh.lines[..])
    }

    /// A colour (r, g, b) per line end.
    #[wasm_bindgen(js_name = lineColors)]
    pub fn line_colors(&self) -> js_sys::Float32Array {
        js_sys::Float32Array::from(&self.inner.mesh.line_colors[..])
    }

    /// The productions of the productions section, as JSON `[{index, from, to, label, context}]`:
    /// `from`/`to` are the UTF-8 byte range of the production in the source, `context` whether it
    /// has a left or right context. The index is what `origins()` and `explain` use.
    pub fn productions(&self) -> String {
        #[derive(serde::Serialize)]
        struct Row<'a> {
            index: usize,
            from: usize,
            to: usize,
            label: Option<&'a str>,
            context: bool,
        }
        let rows: Vec<Row> = self.inner.model.as_ref().map_or_else(Vec::new, |m| {
            m.productions
                .productions
                .iter()
                .enumerate()
                .map(|(index, p)| Row {
                    index,
                    from: p.span.start,
                    to: p.span.end,
                    label: p.label.as_deref(),
                    context: p.has_context(),
                })
                .collect()
        });
        serde_json::to_string(&rows).unwrap_or_else(|_| "[]".into())
    }

    /// Explains production `production` on the last step (see `pipeline::Build::explain`);
    /// `undefined` before the first step, for an unknown index, or on a runtime error.
    pub fn explain(&self, production: u32) -> Option<Explanation> {
        match self.inner.explain(production)? {
            Ok(inner) => Some(Explanation { inner }),
            Err(_) => None,
        }
    }

    /// Explains how module `module` of the derived string was made (the production that wrote it,
    /// the contexts of that rewriting); `undefined` when it was copied or before the first step.
    #[wasm_bindgen(js_name = explainModule)]
    pub fn explain_module(&self, module: usize) -> Option<Explanation> {
        match self.inner.explain_module(module)? {
            Ok(inner) => Some(Explanation { inner }),
            Err(_) => None,
        }
    }

    /// Frees the geometry (mesh and skeleton) once its arrays are copied out, keeping what
    /// `explain` and `moduleTexts` need: an inspected build then costs only its strings.
    #[wasm_bindgen(js_name = releaseGeometry)]
    pub fn release_geometry(&mut self) {
        self.inner.mesh = Default::default();
        self.inner.skeleton = Default::default();
        self.inner.editor = None;
    }

    /// A fingerprint of the derived string (16 hex digits): equal for equal derivations.
    #[wasm_bindgen(js_name = derivedHash)]
    pub fn derived_hash(&self) -> String {
        match &self.inner.model {
            Some(model) => format!("{:016x}", self.inner.string.fingerprint(&model.alphabet)),
            None => String::new(),
        }
    }

    /// Modules in the derived string.
    #[wasm_bindgen(getter, js_name = moduleCount)]
    pub fn module_count(&self) -> usize {
        self.inner.string.len()
    }

    /// The text of modules `start .. start + count` of the derived string, as a JSON array of
    /// strings (one per module), for the virtualised string panel.
    #[wasm_bindgen(js_name = moduleTexts)]
    pub fn module_texts(&self, start: usize, count: usize) -> String {
        let Some(model) = &self.inner.model else {
            return "[]".into();
        };
        let s = &self.inner.string;
        let end = start.saturating_add(count).min(s.len());
        let texts: Vec<String> = (start.min(end)..end)
            .map(|i| s.module_text(&model.alphabet, i))
            .collect();
        serde_json::to_string(&texts).unwrap_or_else(|_| "[]".into())
    }

    /// For each module of the derived string, the index of the module of the previous step's
    /// string it was rewritten or copied from (empty after 0 steps).
    pub fn parents(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.parent[..])
    }

    /// The derived string, cut after `max_chars` characters with `…` appended when longer.
    pub fn derived(&self, max_chars: usize) -> String {
        match &self.inner.model {
            Some(model) => self
                .inner
                .string
                .to_text_truncated(&model.alphabet, max_chars),
            None => String::new(),
        }
    }
}

/// Why and where one production fired in the last step. Module indices name the derived string.
#[wasm_bindgen]
pub struct Explanation {
    inner: pipeline::Explained,
}

#[wasm_bindgen]
impl Explanation {
    /// The production explained (an index into `productions()`).
    #[wasm_bindgen(getter)]
    pub fn production(&self) -> u32 {
        self.inner.explanation.production
    }

    /// Modules the production rewrote.
    #[wasm_bindgen(getter)]
    pub fn fired(&self) -> u32 {
        self.inner.explanation.rewritten.len() as u32
    }

    /// Modules whose predecessor and contexts matched it.
    #[wasm_bindgen(getter, js_name = contextMatched)]
    pub fn context_matched(&self) -> u32 {
        self.inner.explanation.context_matched
    }

    /// Of those, the modules whose condition was false.
    #[wasm_bindgen(getter, js_name = conditionFailed)]
    pub fn condition_failed(&self) -> u32 {
        self.inner.explanation.condition_failed
    }

    /// Modules of the derived string the production wrote.
    pub fn produced(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.produced[..])
    }

    /// Modules of the derived string descending from the modules that served as left context.
    #[wasm_bindgen(js_name = leftContext)]
    pub fn left_context(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.left[..])
    }

    /// Modules of the derived string descending from the modules that served as right context.
    #[wasm_bindgen(js_name = rightContext)]
    pub fn right_context(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.right[..])
    }
}

/// A parsed and resolved grammar that can be derived many times (benchmarks, and later the
/// step-through view), without the turtle and mesh stages.
#[wasm_bindgen]
pub struct Grammar {
    model: crate::model::Model,
}

#[wasm_bindgen]
impl Grammar {
    /// Parses and resolves `source`; `undefined` when it has errors (use [`build`] to see them).
    pub fn compile(source: &str) -> Option<Grammar> {
        let (file, mut diagnostics) = crate::syntax::parse(source);
        let (model, more) = crate::model::resolve(&file);
        diagnostics.extend(more);
        if crate::diagnostics::has_errors(&diagnostics) {
            return None;
        }
        model.map(|model| Grammar { model })
    }

    /// Derives `iterations` steps and returns the number of modules, or −1 when derivation fails
    /// (a limit or a runtime error).
    #[wasm_bindgen(js_name = deriveLength)]
    pub fn derive_length(&self, iterations: u32, seed: Option<f64>) -> f64 {
        let options = crate::derive::DeriveOptions {
            steps: iterations,
            seed: seed.map(|s| s as u64),
        };
        match crate::derive::derive(&self.model, &options) {
            Ok(d) => d.string.len() as f64,
            Err(_) => -1.0,
        }
    }
}

// ---- Importing other dialects (crate::import) ----------------------------------------------

/// Translates `text`, written in another L-system dialect, into Meristem's language.
/// `dialect_or_file_name` is a dialect name (`green`, `lparser`, `cpfg`, `lpy`) or the file's
/// name, whose extension or content then tells the dialect. Returns JSON
/// `{text, notes: [{line, message}], dialect}`: `line` is 1-based in `text` (0 for the whole
/// file); when the dialect cannot be told, `text` is empty, `dialect` null and one note says why.
#[wasm_bindgen]
pub fn import_grammar(text: &str, dialect_or_file_name: &str) -> String {
    use crate::import::{self, Dialect, Import, ImportNote};
    #[derive(serde::Serialize)]
    struct Imported {
        #[serde(flatten)]
        import: Import,
        dialect: Option<Dialect>,
    }
    let dialect = Dialect::from_name(dialect_or_file_name)
        .or_else(|| import::detect(text, dialect_or_file_name));
    let result = match dialect {
        Some(d) => Imported {
            import: import::import(text, d),
            dialect: Some(d),
        },
        None => Imported {
            import: Import {
                text: String::new(),
                notes: vec![ImportNote {
                    line: 0,
                    message: format!(
                        "cannot tell which dialect '{dialect_or_file_name}' is written in (green, lparser, cpfg or lpy)"
                    ),
                }],
            },
            dialect: None,
        },
    };
    serde_json::to_string(&result).unwrap_or_else(|_| "{}".into())
}

// ---- Editing branches by their Bézier handles (issue 8): `crate::branches`. ----------------
// The first of these calls on a build starts its branch editor (the mesh is meshed once more to
// record its layout); from then on `positions()` … and `stats()` are those of the edited plant.

#[wasm_bindgen]
impl Build {
    /// Branches in the plant (see `crate::branches` for what a branch is).
    #[wasm_bindgen(js_name = branchCount)]
    pub fn branch_count(&mut self) -> u32 {
        self.inner.branch_tree().len() as u32
    }

    /// The path of each branch, as JSON: `[[0], [0, 0], [0, 1], …]` (branch `i` is entry `i`).
    #[wasm_bindgen(js_name = branchPaths)]
    pub fn branch_paths(&mut self) -> String {
        let paths: Vec<&Vec<u32>> = self
            .inner
            .branch_tree()
            .branches
            .iter()
            .map(|b| &b.path)
            .collect();
        serde_json::to_string(&paths).unwrap_or_else(|_| "[]".into())
    }

    /// The parent of each branch; 4294967295 (u32::MAX) for a root.
    #[wasm_bindgen(js_name = branchParents)]
    pub fn branch_parents(&mut self) -> js_sys::Uint32Array {
        let parents: Vec<u32> = self
            .inner
            .branch_tree()
            .branches
            .iter()
            .map(|b| b.parent.unwrap_or(crate::branches::NO_BRANCH))
            .collect();
        js_sys::Uint32Array::from(&parents[..])
    }

    /// The Bézier control points of every branch where they are now: 12 floats per branch
    /// (P0, P1, P2, P3, each x, y, z). P0 is where the branch attaches; P1 to P3 can be dragged.
    #[wasm_bindgen(js_name = branchControlPoints)]
    pub fn branch_control_points(&mut self) -> js_sys::Float32Array {
        let editor = self.inner.editor();
        let mut out = Vec::with_capacity(12 * editor.tree().len());
        for b in 0..editor.tree().len() as u32 {
            for p in editor.control_points(b) {
                out.extend([p.x as f32, p.y as f32, p.z as f32]);
            }
        }
        js_sys::Float32Array::from(&out[..])
    }

    /// The joints of branch `branch` where they are now (3 floats each); empty for no branch.
    #[wasm_bindgen(js_name = branchJoints)]
    pub fn branch_joints(&mut self, branch: u32) -> js_sys::Float32Array {
        let joints = self.inner.branch_joints(branch);
        let flat: Vec<f32> = joints
            .iter()
            .flat_map(|j| [j.x as f32, j.y as f32, j.z as f32])
            .collect();
        js_sys::Float32Array::from(&flat[..])
    }

    /// The parameter of each joint of branch `branch` on its curve (0 to 1, by length).
    #[wasm_bindgen(js_name = branchParameters)]
    pub fn branch_parameters(&mut self, branch: u32) -> js_sys::Float32Array {
        let params: Vec<f32> = self
            .inner
            .branch_tree()
            .branches
            .get(branch as usize)
            .map_or_else(Vec::new, |b| {
                b.fit.params.iter().map(|&t| t as f32).collect()
            });
        js_sys::Float32Array::from(&params[..])
    }

    /// The branch that drew each triangle: (first triangle, branch) pairs sorted like `ranges()`;
    /// branch 4294967295 for what grew from no segment. What picking a branch reads.
    #[wasm_bindgen(js_name = branchRanges)]
    pub fn branch_ranges(&mut self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.branch_ranges()[..])
    }

    /// Replaces every edit by those of `edits` (the edits document, `docs/LANGUAGE.md`) and
    /// rebuilds the plant's geometry whole. Returns the report as JSON: `{"applied": [paths],
    /// "notApplied": [{"path", "reason"}]}`. Throws when the document is malformed.
    #[wasm_bindgen(js_name = applyEdits)]
    pub fn apply_edits(&mut self, edits: &str) -> Result<String, JsError> {
        let edits = crate::branches::parse_edits(edits).map_err(|e| JsError::new(&e))?;
        Ok(self.inner.apply_edits(&edits).to_json())
    }

    /// The edits in force as an edits document (JSON).
    pub fn edits(&self) -> String {
        crate::branches::write_edits(&self.inner.edits())
    }

    /// Drags handle `handle` (1, 2 or 3) of branch `branch` to (x, y, z): the branch's edit
    /// changes and only what moved is re-meshed. Returns true when the whole mesh was rebuilt
    /// (read every array again, `changeReason()` says why); otherwise read only the changed
    /// vertices (`changedRanges`, `changedPositions`, `changedNormals`). Throws on a bad branch,
    /// handle or position.
    pub fn drag(
        &mut self,
        branch: u32,
        handle: u32,
        x: f64,
        y: f64,
        z: f64,
    ) -> Result<bool, JsError> {
        self.inner
            .drag(branch, handle as usize, glam::DVec3::new(x, y, z))
            .map(|change| change.full)
            .map_err(|e| JsError::new(&e))
    }

    /// The vertices the last edit changed: (first vertex, count) pairs, sorted and disjoint.
    #[wasm_bindgen(js_name = changedRanges)]
    pub fn changed_ranges(&self) -> js_sys::Uint32Array {
        let flat: Vec<u32> = self
            .last_change()
            .ranges
            .iter()
            .flatten()
            .copied()
            .collect();
        js_sys::Uint32Array::from(&flat[..])
    }

    /// Why the last edit rebuilt the whole mesh; `undefined` when it did not.
    #[wasm_bindgen(js_name = changeReason)]
    pub fn change_reason(&self) -> Option<String> {
        let change = self.last_change();
        change
            .full
            .then(|| change.reason.clone().unwrap_or_default())
    }

    /// The positions of the changed vertices, range after range (3 floats per vertex).
    #[wasm_bindgen(js_name = changedPositions)]
    pub fn changed_positions(&self) -> js_sys::Float32Array {
        self.gather(&self.inner.mesh.positions)
    }

    /// The normals of the changed vertices, range after range.
    #[wasm_bindgen(js_name = changedNormals)]
    pub fn changed_normals(&self) -> js_sys::Float32Array {
        self.gather(&self.inner.mesh.normals)
    }

    /// The texture coordinates of the changed vertices, range after range (2 floats per vertex:
    /// a re-meshed tube's v follows its new length).
    #[wasm_bindgen(js_name = changedUvs)]
    pub fn changed_uvs(&self) -> js_sys::Float32Array {
        let change = self.last_change();
        let out = js_sys::Float32Array::new_with_length(2 * change.vertices() as u32);
        let uvs = &self.inner.mesh.uvs;
        let mut at = 0;
        for r in &change.ranges {
            let from = (2 * r[0] as usize).min(uvs.len());
            let to = (2 * (r[0] as usize + r[1] as usize)).min(uvs.len());
            out.set(&js_sys::Float32Array::from(&uvs[from..to]), at);
            at += (to - from) as u32;
        }
        out
    }

    /// The positions of vertices `first .. first + count` (clamped to the mesh).
    #[wasm_bindgen(js_name = positionsRange)]
    pub fn positions_range(&self, first: u32, count: u32) -> js_sys::Float32Array {
        js_sys::Float32Array::from(window(&self.inner.mesh.positions, first, count))
    }

    /// The normals of vertices `first .. first + count` (clamped to the mesh).
    #[wasm_bindgen(js_name = normalsRange)]
    pub fn normals_range(&self, first: u32, count: u32) -> js_sys::Float32Array {
        js_sys::Float32Array::from(window(&self.inner.mesh.normals, first, count))
    }
}

impl Build {
    fn last_change(&self) -> crate::branches::MeshChange {
        self.inner
            .editor
            .as_ref()
            .map(|e| e.last_change().clone())
            .unwrap_or_default()
    }

    fn gather(&self, array: &[f32]) -> js_sys::Float32Array {
        let change = self.last_change();
        let out = js_sys::Float32Array::new_with_length(3 * change.vertices() as u32);
        let mut at = 0;
        for r in &change.ranges {
            let part = window(array, r[0], r[1]);
            out.set(&js_sys::Float32Array::from(part), at);
            at += part.len() as u32;
        }
        out
    }
}

/// Vertices `first .. first + count` of a 3-floats-per-vertex array, clamped.
fn window(array: &[f32], first: u32, count: u32) -> &[f32] {
    let from = (3 * first as usize).min(array.len());
    let to = from.saturating_add(3 * count as usize).min(array.len());
    &array[from..to]
}

/// As [`export_model`], with the branch edits of `edits` (an edits document) applied: the bytes
/// of `meristem export FILE -o NAME.EXT --edits EDITS.json`. Edits that do not apply are left
/// out (as the command line does, which warns). Throws on a malformed document too.
#[allow(clippy::too_many_arguments)]
#[wasm_bindgen(js_name = exportModelWithEdits)]
pub fn export_model_with_edits(
    source: &str,
    edits: &str,
    format: &str,
    name: &str,
    iterations: Option<u32>,
    seed: Option<f64>,
    sides: Option<u32>,
    smooth_all: Option<bool>,
) -> Result<ExportedModel, JsError> {
    let options = build_options(iterations, seed, sides, smooth_all);
    export_reporting(source, Some(edits), format, name, &options, &mut |_| {})
}
