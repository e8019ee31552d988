//! The wasm boundary: the only file with `#[wasm_bindgen]`. A thin layer over [`crate::pipeline`];
//! the TypeScript facade in `web/src/core/` mirrors it with idiomatic types. Bulk data leaves as
//! flat typed arrays (layout: [`crate::mesh::MeshBuffers`]), small structured data as JSON.
#![deny(clippy::unwrap_used)]

use crate::export::{self, Format};
use crate::pipeline::{self, BuildOptions};
use wasm_bindgen::prelude::*;

/// The core's version (the crate version).
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// The turtle command table as JSON: `[{"name","params","doc","category"}]`.
#[wasm_bindgen]
pub fn commands() -> String {
    crate::turtle::commands_json()
}

/// Runs the whole pipeline: parse -> resolve -> derive -> interpret -> mesh.
/// `iterations`: `None` takes the grammar's `#iterations`; `seed`: `None` takes `#seed` (a whole
/// number from 0 to 2^53; other values are ignored).
#[wasm_bindgen]
pub fn build(source: &str, iterations: Option<u32>, seed: Option<f64>) -> Build {
    let inner = pipeline::build(source, &build_options(iterations, seed));
    let diagnostics =
        serde_json::to_string(&inner.located_diagnostics(source)).unwrap_or_else(|_| "[]".into());
    Build { inner, diagnostics }
}

/// The options of a build from the boundary's arguments; a seed that is not a whole number from 0
/// to 2^53 is ignored (the grammar's `#seed` is used).
fn build_options(iterations: Option<u32>, seed: Option<f64>) -> BuildOptions {
    let seed = seed.filter(|s| {
        s.is_finite() && *s >= 0.0 && s.fract() == 0.0 && *s <= 9.007_199_254_740_992e15
    });
    BuildOptions {
        iterations,
        seed: seed.map(|s| s as u64),
        ..BuildOptions::default()
    }
}

/// Builds `source` (as [`build`] does) and writes the model as a file to download: `format` is
/// `wrl`, `glb`, `pov`, `obj`, `iv` or `svg`; `name` is the file name without extension. OBJ comes
/// as a zip of `NAME.obj` and `NAME.mtl`. The bytes are exactly what `meristem export FILE -o
/// NAME.EXT` writes for the same grammar, iterations and seed. Throws when the format is unknown or
/// the grammar has errors (callers export a plant that built).
#[wasm_bindgen(js_name = exportModel)]
pub fn export_model(
    source: &str,
    format: &str,
    name: &str,
    iterations: Option<u32>,
    seed: Option<f64>,
) -> Result<ExportedModel, JsError> {
    let format = Format::from_extension(format).ok_or_else(|| {
        JsError::new(&format!(
            "unknown format '{format}'; the formats are {}",
            Format::names()
        ))
    })?;
    let result = pipeline::build(source, &build_options(iterations, seed));
    if !result.ok() {
        return Err(JsError::new("the grammar has errors: nothing to export"));
    }
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

    pub fn positions(&self) -> Vec<f32> {
        self.inner.mesh.positions.clone()
    }

    pub fn normals(&self) -> Vec<f32> {
        self.inner.mesh.normals.clone()
    }

    pub fn colors(&self) -> Vec<f32> {
        self.inner.mesh.colors.clone()
    }

    pub fn indices(&self) -> Vec<u32> {
        self.inner.mesh.indices.clone()
    }

    /// Provenance: (first triangle, module) pairs, sorted (layout: `MeshBuffers::ranges`); the
    /// module is an index into the derived string.
    pub fn ranges(&self) -> Vec<u32> {
        self.inner.mesh.ranges.clone()
    }

    /// For each module of the derived string, the index of the production that made it in the
    /// last step, or 4294967295 (u32::MAX) when it was copied.
    pub fn origins(&self) -> Vec<u32> {
        self.inner.origin.clone()
    }

    /// Line ends (x, y, z each) when the model was too large to mesh; empty otherwise.
    pub fn lines(&self) -> Vec<f32> {
        self.inner.mesh.lines.clone()
    }

    /// A colour (r, g, b) per line end.
    #[wasm_bindgen(js_name = lineColors)]
    pub fn line_colors(&self) -> Vec<f32> {
        self.inner.mesh.line_colors.clone()
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
