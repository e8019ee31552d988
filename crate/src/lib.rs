//! Meristem's core: an L-system engine with a 3D turtle, free of IO and of the browser.
//!
//! The pipeline is one module per stage with plain data between them (see ARCHITECTURE.md):
//! [`syntax`] (text -> syntax tree) -> [`model`] (resolve: validated model) -> [`derive`]
//! (rewriting) -> [`turtle`] (interpretation: skeleton) -> [`mesh`] (triangles) -> [`export`].
//! [`pipeline::build`] runs them all. [`growth`] adds the particle attributes (lifetime, speed,
//! shape, attractors) to derive and turtle. `wasm` (a folder, one file per class or concept of
//! the boundary) is the only module that knows wasm-bindgen; `number` alone besides it calls
//! JavaScript (its `parseFloat`, under wasm32: see its doc).

pub mod branches;
pub mod derive;
pub mod diagnostics;
#[cfg(feature = "environment")]
pub mod environment;
pub mod export;
pub mod growth;
pub mod import;
pub mod maths;
pub mod mesh;
pub mod model;
pub mod number;
pub mod pipeline;
pub mod sort;
pub mod syntax;
pub mod turtle;
pub mod vocabulary;
pub mod wasm; // public for the wasm32 boundary tests (tests/wasm_boundary.rs)

pub use pipeline::{build, Build, BuildOptions};
