//! What a build knows of its environment, for the studio's views (issue 47): the studio core's
//! (feature `environment`). Small data as JSON, a grid's values and the points as typed arrays
//! (layout: [`crate::pipeline::EnvironmentView`]).

use super::PlantBuild;
use wasm_bindgen::prelude::*;

#[wasm_bindgen]
impl PlantBuild {
    /// JSON of the environment after the last step ([`crate::pipeline::EnvironmentView::to_json`]:
    /// the grids without their values, the obstacles' solids, the count of attraction points, the
    /// names of a `?E`'s reply values), or `null` when the grammar declares none.
    pub fn environment(&self) -> String {
        self.environment_view()
            .map_or_else(|| "null".into(), |v| v.to_json())
    }

    /// Grid `i`'s values (`dims[0] × dims[1] × dims[2]`, x fastest); empty when there is none.
    #[wasm_bindgen(js_name = environmentField)]
    pub fn environment_field(&self, i: usize) -> js_sys::Float32Array {
        let values = self
            .environment_view()
            .map_or(&[][..], |v| v.field_values(i));
        js_sys::Float32Array::from(values)
    }

    /// The attraction points left, x, y, z each.
    #[wasm_bindgen(js_name = environmentPoints)]
    pub fn environment_points(&self) -> js_sys::Float32Array {
        let points = self
            .environment_view()
            .map(|v| v.point_coordinates())
            .unwrap_or_default();
        js_sys::Float32Array::from(&points[..])
    }
}
