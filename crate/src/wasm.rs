//! The wasm boundary: the only file with `#[wasm_bindgen]`. A thin layer over [`crate::pipeline`];
//! the TypeScript facade in `web/src/core/` mirrors it with idiomatic types. Bulk data leaves as
//! flat typed arrays (layout: [`crate::mesh::MeshBuffers`]), small structured data as JSON.
#![deny(clippy::unwrap_used)]

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
/// `iterations`: `None` takes the grammar's `#iterations`.
#[wasm_bindgen]
pub fn build(source: &str, iterations: Option<u32>) -> Build {
    let options = BuildOptions {
        iterations,
        ..BuildOptions::default()
    };
    let inner = pipeline::build(source, &options);
    let diagnostics =
        serde_json::to_string(&inner.located_diagnostics(source)).unwrap_or_else(|_| "[]".into());
    Build { inner, diagnostics }
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
