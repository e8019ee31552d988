//! The typed-array getters of a plant's mesh, shared by [`super::PlantBuild`] and
//! [`super::PlantEditor`]: one row per array (layout: [`crate::mesh::MeshBuffers`]), each copied
//! once out of wasm memory into a fresh JavaScript array, and for the biggest an `…Into` twin
//! that copies it into a typed array the caller made (the studio's build worker copies a big mesh
//! into buffers it made ahead, `web/src/core/spare-buffers.ts`, rather than into new ones).

/// `copy(values)` when a typed array of `out` values fits `values` exactly, else an error.
#[cfg(feature = "studio-extras")]
pub(super) fn copy_into<T>(
    values: &[T],
    out: u32,
    copy: impl FnOnce(&[T]),
) -> Result<(), wasm_bindgen::JsError> {
    if values.len() != out as usize {
        return Err(wasm_bindgen::JsError::new(&format!(
            "the array has {} values, the typed array to copy them into {out}",
            values.len()
        )));
    }
    copy(values);
    Ok(())
}

/// The getters of `$class`, which has `fn plant(&self) -> &pipeline::Plant`. Each row: the
/// array's doc, its getter and JavaScript name, `/ its_into "itsInto"` when it has an `…Into`
/// twin (studio core only), its typed array, and its values from the plant `$p`. A
/// `#[wasm_bindgen] impl` block expands no macros inside it, so the macro writes the blocks whole.
macro_rules! mesh_arrays {
    ($class:ident, $p:ident; $(
        $(#[doc = $doc:literal])+
        $getter:ident $js:literal $(/ $into:ident $js_into:literal)?: $array:ident = $values:expr;
    )*) => {
        #[wasm_bindgen]
        impl $class {
            /// JSON `{modules, segments, vertices, triangles, lines, iterations, bounds}`.
            pub fn stats(&self) -> String {
                self.plant().stats.to_json()
            }

            /// True when everything drawn lies in the plane z = 0.
            #[wasm_bindgen(getter)]
            pub fn flat(&self) -> bool {
                self.plant().is_flat()
            }

            $(
                $(#[doc = $doc])+
                #[wasm_bindgen(js_name = $js)]
                pub fn $getter(&self) -> js_sys::$array {
                    let $p = self.plant();
                    js_sys::$array::from(&($values)[..])
                }
            )*
        }

        #[cfg(feature = "studio-extras")]
        #[wasm_bindgen]
        impl $class {
            $($(
                #[doc = concat!("`", $js, "` copied into `out`, a typed array of its length; throws when the lengths differ.")]
                #[wasm_bindgen(js_name = $js_into)]
                pub fn $into(&self, out: &js_sys::$array) -> Result<(), JsError> {
                    let $p = self.plant();
                    super::mesh_arrays::copy_into(&($values)[..], out.length(), |values| {
                        out.copy_from(values)
                    })
                }
            )?)*
        }
    };
}

/// The getters of a class holding a plant (see [`mesh_arrays!`]).
macro_rules! plant_mesh_getters {
    ($class:ident) => {
        mesh_arrays! { $class, p;
            /// 3 floats per vertex.
            positions "positions" / positions_into "positionsInto": Float32Array = p.mesh.positions;
            /// 3 floats per vertex, unit length.
            normals "normals": Float32Array = p.mesh.normals;
            /// Linear RGB, 3 floats per vertex.
            colors "colors": Float32Array = p.mesh.colors;
            /// `normals` packed for the GPU: 16-bit normalized (`mesh::pack_normals`).
            packed_normals "packedNormals" / packed_normals_into "packedNormalsInto": Int16Array =
                crate::mesh::pack_normals(&p.mesh.normals);
            /// `colors` packed for the GPU: 8-bit normalized (`mesh::pack_colors`).
            packed_colors "packedColors" / packed_colors_into "packedColorsInto": Uint8Array =
                crate::mesh::pack_colors(&p.mesh.colors);
            /// 3 vertex indices per triangle.
            indices "indices" / indices_into "indicesInto": Uint32Array = p.mesh.indices;
            /// Texture coordinates, 2 floats per vertex.
            uvs "uvs" / uvs_into "uvsInto": Float32Array = p.mesh.uvs;
            /// Material kinds: (first triangle, kind) pairs, 0 bark, 1 leaf, 2 plain.
            material_ranges "materialRanges": Uint32Array = p.mesh.material_ranges;
            /// Provenance: (first triangle, module of the derived string) pairs, sorted.
            ranges "ranges": Uint32Array = p.mesh.ranges;
            /// Line ends (x, y, z each) when the plant is drawn as lines; empty otherwise.
            lines "lines": Float32Array = p.mesh.lines;
            /// A colour (r, g, b) per line end.
            line_colors "lineColors": Float32Array = p.mesh.line_colors;
            /// Every segment as a line, whatever the mesh (the studio's Lines mode): two ends
            /// (x, y, z each) per segment.
            segment_ends "segmentEnds" / segment_ends_into "segmentEndsInto": Float32Array =
                p.segment_ends();
            /// A colour (r, g, b) per end of `segmentEnds`.
            segment_colors "segmentColors" / segment_colors_into "segmentColorsInto": Float32Array =
                p.segment_colors();
            /// The module of the derived string that drew each segment of `segmentEnds`.
            segment_modules "segmentModules": Uint32Array = p.segment_modules();
        }

        // Growth in time: the studio core only (feature `growth`, crate/Cargo.toml).
        #[cfg(feature = "growth")]
        #[wasm_bindgen]
        impl $class {
            /// With the `growth` option: the point each vertex (each line end, for lines) grows
            /// from, 3 floats each; empty otherwise.
            #[wasm_bindgen(js_name = "growthOrigins")]
            pub fn growth_origins(&self) -> js_sys::Float32Array {
                js_sys::Float32Array::from(&self.plant().mesh.growth_origins[..])
            }

            /// With the `growth` option: each vertex's growth times (t0, t1), 2 floats each, in
            /// derivation steps; empty otherwise.
            #[wasm_bindgen(js_name = "growthTimes")]
            pub fn growth_times(&self) -> js_sys::Float32Array {
                js_sys::Float32Array::from(&self.plant().mesh.growth_times[..])
            }

            /// With the `growth` option: each segment's growth times (t0, t1) in the order of
            /// `segmentEnds`, 2 floats each (the Lines mode's lines grow by them); empty otherwise.
            #[wasm_bindgen(js_name = "segmentGrowthTimes")]
            pub fn segment_growth_times(&self) -> js_sys::Float32Array {
                js_sys::Float32Array::from(&self.plant().mesh.segment_growth_times[..])
            }
        }
    };
}
