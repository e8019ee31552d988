//! The wasm boundary: the only module with `#[wasm_bindgen]`. A thin layer over
//! [`crate::pipeline`] whose classes have the names and roles of the TypeScript facade in
//! `web/src/core/`, one file each:
//! [`PlantBuild`] (a built plant: diagnostics, stats, mesh arrays), [`PlantInspector`] (questions
//! about its derivation), [`PlantEditor`] (branch edits), [`ExportedModel`] (a file to download).
//! Calls take an options object, never a long list of positional arguments. Getters have no side
//! effects; what changes an object says so in its name (`remesh`, `drag`, `applyEdits`, `into…`).
//!
//! Bulk data leaves as flat typed arrays (layout: [`crate::mesh::MeshBuffers`]), each copied once
//! out of wasm memory into a fresh JavaScript array; small structured data as JSON. A panic in the
//! core is reported with its message to the callback given to [`on_panic`] and to the console
//! before the call traps, so the studio can say what failed and start a fresh core.
//!
//! The files: `options` (the options objects: their one reader and their TypeScript interfaces,
//! from one table), `build`, `build_on` (a build that continues a kept one's derivation), `mesh_arrays` (the typed-array getters of a build and an editor, one
//! row per array), `inspector`, `editor`, `environment` (what a build knows of its environment,
//! for the views), `export`, `import`, `surface` (one declared surface for the surface editor),
//! `bench` and `light_bench` (the benchmarks' entry points) and `panic` (the crash path).
#![deny(clippy::unwrap_used)]

#[macro_use]
mod mesh_arrays;
#[cfg(feature = "studio-extras")]
mod bench;
mod build;
#[cfg(feature = "studio-extras")]
mod build_on;
#[cfg(feature = "studio-extras")]
mod editor;
#[cfg(feature = "environment")]
mod environment;
#[cfg(feature = "io")]
mod export;
#[cfg(feature = "io")]
mod import;
mod inspector;
#[cfg(all(feature = "studio-extras", feature = "environment"))]
mod light_bench;
mod options;
mod panic;
#[cfg(all(feature = "studio-extras", feature = "surfaces"))]
mod surface;

#[cfg(feature = "studio-extras")]
pub use bench::{build_sketch, Grammar};
pub use build::{build, PlantBuild};
#[cfg(feature = "studio-extras")]
pub use build_on::build_on;
#[cfg(feature = "studio-extras")]
pub use editor::PlantEditor;
#[cfg(feature = "io")]
pub use export::{export_model, ExportedModel};
#[cfg(feature = "io")]
pub use import::{
    import_derived, import_grammar, import_object, needs_python, prefer_derived, python_main,
};
#[cfg(feature = "studio-extras")]
pub use inspector::Explanation;
pub use inspector::PlantInspector;
#[cfg(all(feature = "studio-extras", feature = "environment"))]
pub use light_bench::LightBench;
pub use options::{BuildOptionsObject, SketchFirstObject, ViewOptionsObject, BUILD_TYPESCRIPT};
#[cfg(feature = "io")]
pub use options::{ExportOptionsObject, SvgLookObject, EXPORT_TYPESCRIPT};
pub use panic::{on_panic, panic_for_tests};
#[cfg(all(feature = "studio-extras", feature = "surfaces"))]
pub use surface::surface_preview_json;
use wasm_bindgen::prelude::*;

/// The core's version (the crate version).
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// The language's vocabulary as JSON (`crate::vocabulary::vocabulary_json`): modules, directives,
/// keywords, functions and values, each with typed parameters.
#[cfg(feature = "studio-extras")]
#[wasm_bindgen]
pub fn vocabulary() -> String {
    crate::vocabulary::vocabulary_json()
}
