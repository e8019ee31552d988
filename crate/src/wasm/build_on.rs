//! `buildOn`: a build that continues a kept build's derivation, for the build worker's steps
//! forward and Play (the studio core only: the first plant has nothing to continue).

use super::build::{build_after, PlantBuild};
use super::inspector::PlantInspector;
use super::options::BuildOptionsObject;
use wasm_bindgen::prelude::*;

/// Runs the whole pipeline on `source` as `build` does, but derives on from the derivation `from`
/// keeps when `from` built the same grammar with the same seed to fewer steps (and the grammar
/// allows it: docs/LANGUAGE.md, "Stepping"), so that only the new steps are derived; the plant is
/// the very one `build` makes. `continuedFrom` on the result tells the step it went on from.
#[wasm_bindgen(js_name = buildOn)]
pub fn build_on(
    source: &str,
    options: &BuildOptionsObject,
    from: &PlantInspector,
    clock: Option<js_sys::Function>,
    progress: Option<js_sys::Function>,
) -> Result<PlantBuild, JsValue> {
    build_after(source, options, Some(from.build()), clock, progress)
}
