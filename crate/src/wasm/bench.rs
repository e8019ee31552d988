//! The benchmarks' entry points (`npm run bench`, `../shared/bench/js/meristem-peer.mjs`): a
//! sketch build, and a grammar derived many times without the turtle and mesh stages.

use super::build::{build_reading, PlantBuild};
use super::options::BuildOptionsFields;
use wasm_bindgen::prelude::*;

/// `build(source, { iterations, sketch: true })`: the entry point of the shared benchmark
/// harness's turtle workload (`../shared/bench/js/meristem-peer.mjs`).
#[wasm_bindgen(js_name = buildSketch)]
pub fn build_sketch(source: &str, iterations: Option<u32>) -> PlantBuild {
    let options = BuildOptionsFields {
        iterations,
        sketch: Some(true),
        ..BuildOptionsFields::none()
    };
    build_reading(source, &options.options(), None, None, None)
}

/// A parsed and resolved grammar derived many times, without the turtle and mesh stages: the
/// benchmarks' entry point (`npm run bench`, `../shared/bench/js/meristem-peer.mjs`).
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
            ..Default::default()
        };
        match crate::derive::derive(&self.model, &options) {
            Ok(d) => d.string.len() as f64,
            Err(_) => -1.0,
        }
    }
}
