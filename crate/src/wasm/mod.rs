//! The wasm boundary: the only file with `#[wasm_bindgen]`. A thin layer over [`crate::pipeline`]
//! whose classes have the names and roles of the TypeScript facade in `web/src/core/`:
//! [`PlantBuild`] (a built plant: diagnostics, stats, mesh arrays), [`PlantInspector`] (questions
//! about its derivation), [`PlantEditor`] (branch edits), [`ExportedModel`] (a file to download).
//! Calls take an options object, never a long list of positional arguments. Getters have no side
//! effects; what changes an object says so in its name (`remesh`, `drag`, `applyEdits`, `into…`).
//!
//! Bulk data leaves as flat typed arrays (layout: [`crate::mesh::MeshBuffers`]), each copied once
//! out of wasm memory into a fresh JavaScript array; small structured data as JSON. A panic in the
//! core is reported with its message to the callback given to [`on_panic`] and to the console
//! before the call traps, so the studio can say what failed and start a fresh core.
#![deny(clippy::unwrap_used)]

#[cfg(feature = "studio-extras")]
use crate::branches::{parse_edits, write_edits, DragError, NO_BRANCH};
#[cfg(feature = "io")]
use crate::export::{self, Format};
use crate::mesh::{self, MeshOptions};
use crate::pipeline::{self, BuildOptions, Hooks, Progress, Stage};
#[cfg(feature = "io")]
use serde::Deserialize;
use std::cell::RefCell;
use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const OPTIONS: &str = r#"
/** Options of `build`: every field is optional (the grammar's own settings, 6 sides, no smoothing). */
export interface BuildOptions {
  /** Overrides `#iterations`. */
  iterations?: number;
  /** Overrides `#seed`: a whole number from 0 to 2^53 (other values are ignored). */
  seed?: number;
  /** Sides of each branch tube, 3 to 64. */
  sides?: number;
  /** Every axis as a smooth generalized cylinder. */
  smoothAll?: boolean;
  /** Segments as lines instead of tubes (a sketch, cheap to make; `remesh` gives the tubes). */
  sketch?: boolean;
}
/** The mesh's view options, for `PlantBuild.remesh` and `PlantEditor.remesh`. */
export interface ViewOptions {
  sides?: number;
  smoothAll?: boolean;
  /** False: no tubes, only leaves, polygons and spheres (the Lines mode draws the segments as lines). */
  tubes?: boolean;
}
/** Options of `exportModel`: the build's, and what to write. */
export interface ExportOptions extends BuildOptions {
  /** `wrl`, `glb`, `pov`, `obj`, `iv` or `svg`. */
  format: string;
  /** File name without extension; default `plant`. A zip of several files is `NAME-FORMAT.zip`. */
  name?: string;
  /** An edits document (JSON text) to apply first. */
  edits?: string;
  /** An SVG's picture settings (refused for the other formats). */
  svg?: SvgLook;
}
/** An SVG's picture settings: the CLI's `--background`, `--line-width`, `--size` and `--dpi`. */
export interface SvgLook {
  /** `white`, `none` (transparent, the default) or a hex colour: `#` and six hex digits. */
  background?: string;
  /** Every line this wide in the picture's pixels, 0.5 to 60 (the Lines mode). */
  lineWidth?: number;
  /** The picture's width and height in pixels, 16 to 8192 (both or neither). */
  width?: number;
  height?: number;
  /** Dots per inch, 10 to 2400: the width and height are then written in millimetres. */
  dpi?: number;
}
"#;

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(typescript_type = "BuildOptions")]
    pub type BuildOptionsObject;
    #[wasm_bindgen(typescript_type = "ViewOptions")]
    pub type ViewOptionsObject;
    #[wasm_bindgen(typescript_type = "ExportOptions")]
    pub type ExportOptionsObject;
    #[wasm_bindgen(js_namespace = console, js_name = error)]
    fn console_error(message: &str);
}

/// [`BuildOptionsObject`] as read (serde's `Deserialize` only for the `exportModel` options that
/// flatten it in).
#[derive(Default)]
#[cfg_attr(feature = "io", derive(Deserialize))]
#[cfg_attr(feature = "io", serde(rename_all = "camelCase"))]
struct BuildOptionsFields {
    iterations: Option<u32>,
    seed: Option<f64>,
    sides: Option<u32>,
    smooth_all: Option<bool>,
    sketch: Option<bool>,
}

/// [`ExportOptionsObject`] as read.
#[cfg(feature = "io")]
#[derive(Deserialize)]
#[serde(rename_all = "camelCase")]
struct ExportOptionsFields {
    #[serde(flatten)]
    build: BuildOptionsFields,
    format: String,
    name: Option<String>,
    edits: Option<String>,
    svg: Option<SvgLookFields>,
}

/// An `SvgLook` as read.
#[cfg(feature = "io")]
#[derive(Deserialize)]
#[serde(rename_all = "camelCase")]
struct SvgLookFields {
    background: Option<String>,
    line_width: Option<f64>,
    width: Option<u32>,
    height: Option<u32>,
    dpi: Option<f64>,
}

#[cfg(feature = "io")]
impl SvgLookFields {
    /// The look, checked.
    fn look(&self) -> Result<export::svg::Look, String> {
        let size = match (self.width, self.height) {
            (Some(w), Some(h)) => Some((w, h)),
            (None, None) => None,
            _ => return Err("an SVG's size needs both its width and its height".into()),
        };
        export::svg::Look::read(self.background.as_deref(), self.line_width, size, self.dpi)
    }
}

impl BuildOptionsFields {
    /// The pipeline's options; a seed that is not a whole number from 0 to 2^53 is ignored.
    fn options(&self) -> BuildOptions {
        let seed = self.seed.filter(|s| {
            s.is_finite() && *s >= 0.0 && s.fract() == 0.0 && *s <= 9.007_199_254_740_992e15
        });
        let mut mesh = MeshOptions::view(self.sides, self.smooth_all);
        if self.sketch == Some(true) {
            mesh.max_vertices = 0;
        }
        BuildOptions {
            iterations: self.iterations,
            seed: seed.map(|s| s as u64),
            mesh,
            sketch: self.sketch == Some(true),
        }
    }
}

/// [`ViewOptionsObject`] as read.
#[derive(Default)]
struct ViewOptionsFields {
    sides: Option<u32>,
    smooth_all: Option<bool>,
    tubes: Option<bool>,
}

impl ViewOptionsFields {
    /// The mesh options of a remesh.
    fn mesh(&self) -> MeshOptions {
        MeshOptions {
            tubes: self.tubes.unwrap_or(true),
            ..MeshOptions::view(self.sides, self.smooth_all)
        }
    }
}

impl BuildOptionsFields {
    /// Reads a `BuildOptions` object (`undefined` and `null` are no options).
    fn read(value: &JsValue) -> Result<Self, JsError> {
        let Some(object) = OptionsObject::of(value) else {
            return Ok(Self::default());
        };
        Ok(Self {
            iterations: object.whole("iterations")?,
            seed: object.number("seed")?,
            sides: object.whole("sides")?,
            smooth_all: object.flag("smoothAll")?,
            sketch: object.flag("sketch")?,
        })
    }
}

impl ViewOptionsFields {
    /// Reads a `ViewOptions` object (`undefined` and `null` are no options).
    fn read(value: &JsValue) -> Result<Self, JsError> {
        let Some(object) = OptionsObject::of(value) else {
            return Ok(Self::default());
        };
        Ok(Self {
            sides: object.whole("sides")?,
            smooth_all: object.flag("smoothAll")?,
            tubes: object.flag("tubes")?,
        })
    }
}

/// An options object of the first plant's calls (`build`, `remesh`), read field by field with
/// `Reflect.get` rather than serde (issue 22, the first load: serde's deserializer and its error
/// messages were KBs of the first plant's wasm). A field that is `undefined` or `null` is not
/// given; other fields are ignored.
struct OptionsObject<'a>(&'a JsValue);

impl<'a> OptionsObject<'a> {
    /// `None` for `undefined` and `null`: no options.
    fn of(value: &'a JsValue) -> Option<Self> {
        (!value.is_undefined() && !value.is_null()).then_some(Self(value))
    }

    fn field(&self, name: &str) -> Result<Option<JsValue>, JsError> {
        let value = js_sys::Reflect::get(self.0, &JsValue::from_str(name))
            .map_err(|_| JsError::new("bad options: not an object"))?;
        Ok((!value.is_undefined() && !value.is_null()).then_some(value))
    }

    fn number(&self, name: &str) -> Result<Option<f64>, JsError> {
        self.field(name)?
            .map(|v| {
                v.as_f64()
                    .ok_or_else(|| JsError::new(&format!("bad options: {name} must be a number")))
            })
            .transpose()
    }

    fn whole(&self, name: &str) -> Result<Option<u32>, JsError> {
        self.number(name)?
            .map(|x| {
                if x.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&x) {
                    Ok(x as u32)
                } else {
                    Err(JsError::new(&format!(
                        "bad options: {name} must be a whole number from 0 to {}",
                        u32::MAX
                    )))
                }
            })
            .transpose()
    }

    fn flag(&self, name: &str) -> Result<Option<bool>, JsError> {
        self.field(name)?
            .map(|v| {
                v.as_bool().ok_or_else(|| {
                    JsError::new(&format!("bad options: {name} must be true or false"))
                })
            })
            .transpose()
    }
}

thread_local! {
    /// Told the message of a panic (see [`on_panic`]).
    static PANIC_LISTENER: RefCell<Option<js_sys::Function>> = const { RefCell::new(None) };
}

/// Installs the panic hook when the module starts: a panic's message goes to the console and to
/// the [`on_panic`] listener before the call traps.
#[wasm_bindgen(start)]
fn start() {
    std::panic::set_hook(Box::new(|info| {
        let message = format!("the core crashed (a bug): {info}");
        console_error(&message);
        PANIC_LISTENER.with(|listener| {
            if let Ok(listener) = listener.try_borrow() {
                if let Some(f) = listener.as_ref() {
                    let _ = f.call1(&JsValue::NULL, &JsValue::from_str(&message));
                }
            }
        });
    }));
}

/// Calls `listener(message)` when the core panics, just before the call that panicked throws
/// (a `WebAssembly.RuntimeError`). The instance should not be used after that.
#[wasm_bindgen(js_name = onPanic)]
pub fn on_panic(listener: js_sys::Function) {
    PANIC_LISTENER.with(|l| *l.borrow_mut() = Some(listener));
}

/// Panics with `message`: how the tests reach the panic path (the hook, [`on_panic`], the studio's
/// `CoreCrashed`) now that no known input does.
#[wasm_bindgen(js_name = panicForTests)]
pub fn panic_for_tests(message: &str) {
    panic!("{message}");
}

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

/// Runs the whole pipeline on `source`. `clock`, when given, is read between the stages
/// (JavaScript's `() => performance.now()`): their times come back in `timings()`.
/// `progress(stage, step, steps)`, when given, is told each stage as it starts (`parsing`,
/// `deriving`, `interpreting`, `meshing`; step and steps 0) and, while deriving, each step done
/// (`deriving`, k, n, from 0 of n). A progress callback that throws changes nothing.
#[wasm_bindgen]
pub fn build(
    source: &str,
    options: &BuildOptionsObject,
    clock: Option<js_sys::Function>,
    progress: Option<js_sys::Function>,
) -> Result<PlantBuild, JsError> {
    let options = BuildOptionsFields::read(options)?.options();
    Ok(build_reading(
        source,
        &options,
        clock.as_ref(),
        progress.as_ref(),
    ))
}

#[cfg(feature = "studio-extras")]
/// `build(source, { iterations, sketch: true })`: the entry point of the shared benchmark
/// harness's turtle workload (`../shared/bench/js/meristem-peer.mjs`).
#[wasm_bindgen(js_name = buildSketch)]
pub fn build_sketch(source: &str, iterations: Option<u32>) -> PlantBuild {
    let options = BuildOptionsFields {
        iterations,
        sketch: Some(true),
        ..BuildOptionsFields::default()
    };
    build_reading(source, &options.options(), None, None)
}

/// The time `clock` (JavaScript's `() => performance.now()`) tells; 0 without one or when it
/// throws.
fn read_clock(clock: Option<&js_sys::Function>) -> f64 {
    clock
        .and_then(|c| c.call0(&JsValue::NULL).ok())
        .and_then(|t| t.as_f64())
        .unwrap_or(0.0)
}

fn build_reading(
    source: &str,
    options: &BuildOptions,
    clock: Option<&js_sys::Function>,
    progress: Option<&js_sys::Function>,
) -> PlantBuild {
    let mut now = || read_clock(clock);
    let mut tell = |p: Progress| {
        let (stage, step, steps) = match p {
            Progress::Started(stage) => (stage, 0, 0),
            Progress::Derived { step, steps } => (Stage::Derive, step, steps),
        };
        if let Some(f) = progress {
            let _ = f.call3(
                &JsValue::NULL,
                &JsValue::from_str(stage.label()),
                &JsValue::from_f64(step.into()),
                &JsValue::from_f64(steps.into()),
            );
        }
    };
    let mut hooks = Hooks {
        clock: clock.map(|_| &mut now as &mut dyn FnMut() -> f64),
        progress: progress.map(|_| &mut tell as &mut dyn FnMut(Progress)),
    };
    let build = pipeline::build_with(source, options, &mut hooks);
    let diagnostics =
        serde_json::to_string(&build.located_diagnostics(source)).unwrap_or_else(|_| "[]".into());
    PlantBuild { build, diagnostics }
}

/// Builds and writes the model as one file to download (a zip when the format has several: OBJ
/// and its MTL, POV-Ray's scene and its textures). The bytes are those of `meristem export` for
/// the same grammar and options. `progress(stage, index, count)` is told each stage as it starts
/// (`parsing`, `deriving`, `interpreting`, `meshing`, `applying edits`, `writing`). Throws when
/// the format is unknown, the edits are malformed or the grammar has errors.
#[cfg(feature = "io")]
#[wasm_bindgen(js_name = exportModel)]
pub fn export_model(
    source: &str,
    options: &ExportOptionsObject,
    progress: Option<js_sys::Function>,
) -> Result<ExportedModel, JsError> {
    let fields: ExportOptionsFields = serde_wasm_bindgen::from_value(JsValue::from(options))
        .map_err(|e| JsError::new(&format!("bad options: {e}")))?;
    let format = Format::from_extension(&fields.format).ok_or_else(|| {
        JsError::new(&format!(
            "unknown format '{}'; the formats are {}",
            fields.format,
            Format::names()
        ))
    })?;
    let edits = fields
        .edits
        .as_deref()
        .map(parse_edits)
        .transpose()
        .map_err(|e| JsError::new(&e))?;
    let look = match &fields.svg {
        Some(_) if format != Format::Svg => {
            return Err(JsError::new("picture settings are for an SVG only"))
        }
        Some(svg) => svg.look().map_err(|e| JsError::new(&e))?,
        None => export::svg::Look::default(),
    };
    let stem = fields.name.unwrap_or_else(|| "plant".into());
    let options = pipeline::ExportOptions {
        build: fields.build.options(),
        format,
        stem: stem.clone(),
        edits,
        look,
    };
    let mut tell = |p: Progress| {
        // Stage starts only: an export's progress is its stages.
        let Progress::Started(stage) = p else { return };
        if let Some(f) = &progress {
            let index = Stage::ALL.iter().position(|s| *s == stage).unwrap_or(0);
            // A progress callback that throws changes nothing: the export goes on.
            let _ = f.call3(
                &JsValue::NULL,
                &JsValue::from_str(stage.label()),
                &JsValue::from_f64(index as f64),
                &JsValue::from_f64(Stage::ALL.len() as f64),
            );
        }
    };
    let mut hooks = Hooks {
        clock: None,
        progress: Some(&mut tell),
    };
    let exported = pipeline::export(source, &options, &mut hooks)
        .map_err(|_| JsError::new("the grammar has errors: nothing to export"))?;
    // Several files go in one zip named after the format too: `fern-pov.zip`, `fern-obj.zip`.
    let file = export::bundle(exported.files, &format!("{stem}-{}", format.extension()))
        .ok_or_else(|| JsError::new("the export is larger than 4 GiB"))?;
    Ok(ExportedModel { file })
}

/// One file to download. Free it with `.free()` once its bytes are copied.
#[cfg(feature = "io")]
#[wasm_bindgen]
pub struct ExportedModel {
    file: export::ExportedFile,
}

#[cfg(feature = "io")]
#[wasm_bindgen]
impl ExportedModel {
    /// File name with extension: `plant.glb`, or `plant.zip` for several files.
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

/// `copy(values)` when a typed array of `out` values fits `values` exactly, else an error.
#[cfg(feature = "studio-extras")]
fn copy_into<T>(values: &[T], out: u32, copy: impl FnOnce(&[T])) -> Result<(), JsError> {
    if values.len() != out as usize {
        return Err(JsError::new(&format!(
            "the array has {} values, the typed array to copy them into {out}",
            values.len()
        )));
    }
    copy(values);
    Ok(())
}

/// The typed-array getters of a plant's mesh, for [`PlantBuild`] and [`PlantEditor`] alike.
macro_rules! mesh_getters {
    ($class:ident, $plant:ident => $get:expr) => {
        #[wasm_bindgen]
        impl $class {
            /// JSON `{modules, segments, vertices, triangles, lines, iterations, bounds}`.
            pub fn stats(&self) -> String {
                let $plant = self;
                $get.stats.to_json()
            }

            /// 3 floats per vertex.
            pub fn positions(&self) -> js_sys::Float32Array {
                let $plant = self;
                js_sys::Float32Array::from(&$get.mesh.positions[..])
            }

            /// 3 floats per vertex, unit length.
            pub fn normals(&self) -> js_sys::Float32Array {
                let $plant = self;
                js_sys::Float32Array::from(&$get.mesh.normals[..])
            }

            /// Linear RGB, 3 floats per vertex.
            pub fn colors(&self) -> js_sys::Float32Array {
                let $plant = self;
                js_sys::Float32Array::from(&$get.mesh.colors[..])
            }

            /// `normals` packed for the GPU: 16-bit normalized (`mesh::pack_normals`).
            #[wasm_bindgen(js_name = packedNormals)]
            pub fn packed_normals(&self) -> Vec<i16> {
                let $plant = self;
                mesh::pack_normals(&$get.mesh.normals)
            }

            /// `colors` packed for the GPU: 8-bit normalized (`mesh::pack_colors`).
            #[wasm_bindgen(js_name = packedColors)]
            pub fn packed_colors(&self) -> Vec<u8> {
                let $plant = self;
                mesh::pack_colors(&$get.mesh.colors)
            }

            /// 3 vertex indices per triangle.
            pub fn indices(&self) -> js_sys::Uint32Array {
                let $plant = self;
                js_sys::Uint32Array::from(&$get.mesh.indices[..])
            }

            /// Texture coordinates, 2 floats per vertex.
            pub fn uvs(&self) -> js_sys::Float32Array {
                let $plant = self;
                js_sys::Float32Array::from(&$get.mesh.uvs[..])
            }

            /// `positions` copied into `out` (a `Float32Array` of that length): the studio's build
            /// worker copies a big mesh into buffers it made ahead (`web/src/core/spare-buffers.ts`)
            /// rather than into new ones. Throws when the lengths differ, as the other `…Into`
            /// getters do.
            #[cfg(feature = "studio-extras")]
            #[wasm_bindgen(js_name = positionsInto)]
            pub fn positions_into(&self, out: &js_sys::Float32Array) -> Result<(), JsError> {
                let $plant = self;
                copy_into(&$get.mesh.positions, out.length(), |values| {
                    out.copy_from(values)
                })
            }

            /// `indices` copied into `out`, as [`Self::positions_into`].
            #[cfg(feature = "studio-extras")]
            #[wasm_bindgen(js_name = indicesInto)]
            pub fn indices_into(&self, out: &js_sys::Uint32Array) -> Result<(), JsError> {
                let $plant = self;
                copy_into(&$get.mesh.indices, out.length(), |values| {
                    out.copy_from(values)
                })
            }

            /// `uvs` copied into `out`, as [`Self::positions_into`].
            #[cfg(feature = "studio-extras")]
            #[wasm_bindgen(js_name = uvsInto)]
            pub fn uvs_into(&self, out: &js_sys::Float32Array) -> Result<(), JsError> {
                let $plant = self;
                copy_into(&$get.mesh.uvs, out.length(), |values| out.copy_from(values))
            }

            /// `packedNormals` written into `out`, as [`Self::positions_into`].
            #[cfg(feature = "studio-extras")]
            #[wasm_bindgen(js_name = packedNormalsInto)]
            pub fn packed_normals_into(&self, out: &js_sys::Int16Array) -> Result<(), JsError> {
                let $plant = self;
                copy_into(
                    &mesh::pack_normals(&$get.mesh.normals),
                    out.length(),
                    |values| out.copy_from(values),
                )
            }

            /// `packedColors` written into `out`, as [`Self::positions_into`].
            #[cfg(feature = "studio-extras")]
            #[wasm_bindgen(js_name = packedColorsInto)]
            pub fn packed_colors_into(&self, out: &js_sys::Uint8Array) -> Result<(), JsError> {
                let $plant = self;
                copy_into(
                    &mesh::pack_colors(&$get.mesh.colors),
                    out.length(),
                    |values| out.copy_from(values),
                )
            }

            /// Material kinds: (first triangle, kind) pairs, 0 bark, 1 leaf, 2 plain.
            #[wasm_bindgen(js_name = materialRanges)]
            pub fn material_ranges(&self) -> js_sys::Uint32Array {
                let $plant = self;
                js_sys::Uint32Array::from(&$get.mesh.material_ranges[..])
            }

            /// Provenance: (first triangle, module of the derived string) pairs, sorted.
            pub fn ranges(&self) -> js_sys::Uint32Array {
                let $plant = self;
                js_sys::Uint32Array::from(&$get.mesh.ranges[..])
            }

            /// Line ends (x, y, z each) when the plant is drawn as lines; empty otherwise.
            pub fn lines(&self) -> js_sys::Float32Array {
                let $plant = self;
                js_sys::Float32Array::from(&$get.mesh.lines[..])
            }

            /// A colour (r, g, b) per line end.
            #[wasm_bindgen(js_name = lineColors)]
            pub fn line_colors(&self) -> js_sys::Float32Array {
                let $plant = self;
                js_sys::Float32Array::from(&$get.mesh.line_colors[..])
            }

            /// `lines` copied into `out`, as [`Self::positions_into`]: the build worker's sketch of
            /// a big plant, the first thing on screen after an edit.
            #[cfg(feature = "studio-extras")]
            #[wasm_bindgen(js_name = linesInto)]
            pub fn lines_into(&self, out: &js_sys::Float32Array) -> Result<(), JsError> {
                let $plant = self;
                copy_into(&$get.mesh.lines, out.length(), |values| {
                    out.copy_from(values)
                })
            }

            /// `lineColors` copied into `out`, as [`Self::positions_into`].
            #[cfg(feature = "studio-extras")]
            #[wasm_bindgen(js_name = lineColorsInto)]
            pub fn line_colors_into(&self, out: &js_sys::Float32Array) -> Result<(), JsError> {
                let $plant = self;
                copy_into(&$get.mesh.line_colors, out.length(), |values| {
                    out.copy_from(values)
                })
            }

            /// Every segment as a line, whatever the mesh (the studio's Lines mode): two ends
            /// (x, y, z each) per segment.
            #[wasm_bindgen(js_name = segmentEnds)]
            pub fn segment_ends(&self) -> js_sys::Float32Array {
                let $plant = self;
                js_sys::Float32Array::from(&$get.segment_ends()[..])
            }

            /// A colour (r, g, b) per end of `segmentEnds`.
            #[wasm_bindgen(js_name = segmentColors)]
            pub fn segment_colors(&self) -> js_sys::Float32Array {
                let $plant = self;
                js_sys::Float32Array::from(&$get.segment_colors()[..])
            }

            /// `segmentEnds` copied into `out`, as [`Self::positions_into`].
            #[cfg(feature = "studio-extras")]
            #[wasm_bindgen(js_name = segmentEndsInto)]
            pub fn segment_ends_into(&self, out: &js_sys::Float32Array) -> Result<(), JsError> {
                let $plant = self;
                copy_into(&$get.segment_ends(), out.length(), |values| {
                    out.copy_from(values)
                })
            }

            /// `segmentColors` copied into `out`, as [`Self::positions_into`].
            #[cfg(feature = "studio-extras")]
            #[wasm_bindgen(js_name = segmentColorsInto)]
            pub fn segment_colors_into(&self, out: &js_sys::Float32Array) -> Result<(), JsError> {
                let $plant = self;
                copy_into(&$get.segment_colors(), out.length(), |values| {
                    out.copy_from(values)
                })
            }

            /// The module of the derived string that drew each segment of `segmentEnds`.
            #[wasm_bindgen(js_name = segmentModules)]
            pub fn segment_modules(&self) -> js_sys::Uint32Array {
                let $plant = self;
                js_sys::Uint32Array::from(&$get.segment_modules()[..])
            }

            /// True when everything drawn lies in the plane z = 0.
            #[wasm_bindgen(getter)]
            pub fn flat(&self) -> bool {
                let $plant = self;
                $get.is_flat()
            }
        }
    };
}

/// A built plant: what one run of the pipeline produced. Free it with `.free()`, or turn it into
/// an inspector or an editor, once its arrays are copied out.
#[wasm_bindgen]
pub struct PlantBuild {
    build: pipeline::Build,
    diagnostics: String,
}

mesh_getters!(PlantBuild, this => this.build.plant);

#[wasm_bindgen]
impl PlantBuild {
    /// True when there is no error diagnostic (the geometry is present).
    #[wasm_bindgen(getter)]
    pub fn ok(&self) -> bool {
        self.build.ok()
    }

    /// JSON array of `{severity, code, message, from, to, line, column}`; `from`/`to` are UTF-8
    /// byte offsets, `line`/`column` 1-based, columns in Unicode scalar values.
    pub fn diagnostics(&self) -> String {
        self.diagnostics.clone()
    }

    /// JSON `{parseResolve, derive, interpret, mesh}` in the clock's unit, or `null` without one.
    pub fn timings(&self) -> String {
        self.build
            .timings
            .map_or_else(|| "null".into(), |t| t.to_json())
    }

    /// The grammar's own `#iterations` (0 when it has none or could not be resolved).
    #[wasm_bindgen(getter, js_name = grammarIterations)]
    pub fn grammar_iterations(&self) -> u32 {
        self.build
            .model
            .as_ref()
            .map_or(0, |m| m.settings.iterations)
    }

    /// The seed the derivation used: the `seed` option, or the grammar's `#seed` (0 when the
    /// grammar could not be resolved).
    #[wasm_bindgen(getter)]
    pub fn seed(&self) -> f64 {
        let grammar = self.build.model.as_ref().map_or(0, |m| m.settings.seed);
        self.build.seed.unwrap_or(grammar) as f64
    }

    /// Modules in the derived string.
    #[wasm_bindgen(getter, js_name = moduleCount)]
    pub fn module_count(&self) -> usize {
        self.build.derivation.string.len()
    }

    /// The derived string, cut after `max_chars` characters with `…` appended when longer.
    pub fn derived(&self, max_chars: usize) -> String {
        self.build
            .inspector()
            .map(|i| i.derived_text(max_chars))
            .unwrap_or_default()
    }

    /// For each module of the derived string, the index of the production that made it in the
    /// last step, or 4294967295 (u32::MAX) when it was copied.
    pub fn origins(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(self.build.derivation.origin())
    }

    /// The productions of the productions section, as JSON `[{index, from, to, label, context,
    /// condition}]`: `from`/`to` are the UTF-8 byte range of the production in the source,
    /// `context` whether it has a left or right context, `condition` the byte range of its
    /// condition or null. The index is what `origins()` and `explain` use.
    pub fn productions(&self) -> String {
        #[derive(serde::Serialize)]
        struct Row<'a> {
            index: usize,
            from: usize,
            to: usize,
            label: Option<&'a str>,
            context: bool,
            condition: Option<[usize; 2]>,
        }
        let rows: Vec<Row> = self.build.model.as_ref().map_or_else(Vec::new, |m| {
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
                    condition: p.condition.as_ref().map(|c| [c.span.start, c.span.end]),
                })
                .collect()
        });
        serde_json::to_string(&rows).unwrap_or_else(|_| "[]".into())
    }

    /// Meshes the plant again with other view options (no new derivation); the arrays and stats
    /// change. `clock`, as `build`'s: when both were given, `timings()` adds the time this took
    /// (a sketch's skeleton to `interpret`, the mesh to `mesh`).
    pub fn remesh(
        &mut self,
        options: &ViewOptionsObject,
        clock: Option<js_sys::Function>,
    ) -> Result<(), JsError> {
        let view = ViewOptionsFields::read(options)?;
        let mut now = || read_clock(clock.as_ref());
        let mut hooks = Hooks {
            clock: clock.as_ref().map(|_| &mut now as &mut dyn FnMut() -> f64),
            progress: None,
        };
        self.build.remesh_with(&view.mesh(), &mut hooks);
        Ok(())
    }

    /// Keeps only what questions about the derivation need (the geometry is dropped).
    #[wasm_bindgen(js_name = intoInspector)]
    pub fn into_inspector(mut self) -> PlantInspector {
        self.build.plant = Default::default();
        PlantInspector { build: self.build }
    }

    /// Starts editing the plant's branches (the plant is meshed once more to record its layout).
    #[cfg(feature = "studio-extras")]
    #[wasm_bindgen(js_name = intoEditor)]
    pub fn into_editor(mut self) -> PlantEditor {
        self.build.ensure_skeleton();
        PlantEditor {
            editor: pipeline::PlantEditor::new(self.build.plant),
        }
    }
}

/// Questions about a build's derivation, kept alive without its geometry.
#[wasm_bindgen]
pub struct PlantInspector {
    build: pipeline::Build,
}

#[wasm_bindgen]
impl PlantInspector {
    #[cfg(feature = "studio-extras")]
    /// Explains production `production` on the last step; `undefined` before the first step, for
    /// an unknown index, or on a runtime error.
    pub fn explain(&self, production: u32) -> Option<Explanation> {
        let explained = self.build.inspector()?.explain(production)?.ok()?;
        Some(Explanation { inner: explained })
    }

    #[cfg(feature = "studio-extras")]
    /// Explains how module `module` of the derived string was made (the production that wrote it,
    /// the contexts of that rewriting); `undefined` when it was copied or before the first step.
    #[wasm_bindgen(js_name = explainModule)]
    pub fn explain_module(&self, module: usize) -> Option<Explanation> {
        let explained = self.build.inspector()?.explain_module(module)?.ok()?;
        Some(Explanation { inner: explained })
    }

    /// The text of modules `start .. start + count` of the derived string, as a JSON array of
    /// strings (one per module).
    #[wasm_bindgen(js_name = moduleTexts)]
    pub fn module_texts(&self, start: usize, count: usize) -> String {
        let texts = self
            .build
            .inspector()
            .map(|i| i.module_texts(start, count))
            .unwrap_or_default();
        serde_json::to_string(&texts).unwrap_or_else(|_| "[]".into())
    }

    #[cfg(feature = "studio-extras")]
    /// Why production `production` did or did not rewrite the module that module `module` of the
    /// derived string comes from, as JSON (`MatchReport`: `{production, module, moduleText,
    /// predecessor, left, right, condition, rewrittenBy}`, contexts as `{matched, modules,
    /// expected, found, foundText}`; module indices name the string the last step read);
    /// `undefined` before the first step.
    #[wasm_bindgen(js_name = matchReport)]
    pub fn match_report(&self, production: u32, module: usize) -> Option<String> {
        let report = self
            .build
            .inspector()?
            .match_report(production, module)?
            .ok()?;
        serde_json::to_string(&report).ok()
    }

    #[cfg(feature = "studio-extras")]
    /// The whole derivation, step 0 to the last, as JSON `[{texts, parent, origin}]` (each step's
    /// modules as written, and for each the module of the step before it comes from and the
    /// production that wrote it), when all the steps' strings hold `max_modules` modules or fewer
    /// together; `undefined` when they do not.
    pub fn sequence(&self, max_modules: usize) -> Option<String> {
        #[derive(serde::Serialize)]
        struct Step<'a> {
            texts: Vec<String>,
            parent: &'a [u32],
            origin: &'a [u32],
        }
        let inspector = self.build.inspector()?;
        let traced = inspector.sequence(max_modules)?.ok()?;
        let steps: Vec<Step> = traced
            .iter()
            .map(|s| Step {
                texts: inspector.texts_of(&s.string),
                parent: &s.parent,
                origin: &s.origin,
            })
            .collect();
        serde_json::to_string(&steps).ok()
    }

    /// The text of modules `start .. start + count` of the string the last step read (JSON array).
    #[wasm_bindgen(js_name = previousTexts)]
    pub fn previous_texts(&self, start: usize, count: usize) -> String {
        let texts = self
            .build
            .inspector()
            .map(|i| i.previous_texts(start, count))
            .unwrap_or_default();
        serde_json::to_string(&texts).unwrap_or_else(|_| "[]".into())
    }

    /// Modules in the string the last step read (0 after 0 steps).
    #[wasm_bindgen(getter, js_name = previousCount)]
    pub fn previous_count(&self) -> usize {
        self.build.derivation.previous.len()
    }

    /// For each module of the derived string, the module of the string the last step read it
    /// comes from (empty after 0 steps).
    pub fn parents(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(self.build.derivation.parent())
    }

    /// A fingerprint of the derived string (16 hex digits): equal for equal derivations.
    #[wasm_bindgen(js_name = derivedHash)]
    pub fn derived_hash(&self) -> String {
        self.build
            .inspector()
            .map(|i| i.derived_hash())
            .unwrap_or_default()
    }
}

#[cfg(feature = "studio-extras")]
/// Why and where one production fired in the last step. Module indices name the derived string.
#[wasm_bindgen]
pub struct Explanation {
    inner: pipeline::Explained,
}

#[cfg(feature = "studio-extras")]
#[wasm_bindgen]
impl Explanation {
    /// The production explained (an index into `productions()`).
    #[wasm_bindgen(getter)]
    pub fn production(&self) -> u32 {
        self.inner.explanation.production
    }

    /// Modules the production rewrote in the last step (in the whole string, also when the
    /// explanation is of one module).
    #[wasm_bindgen(getter)]
    pub fn fired(&self) -> u32 {
        self.inner.explanation.fired
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

/// A plant whose branches are being edited (see `crate::branches`).
#[cfg(feature = "studio-extras")]
#[wasm_bindgen]
pub struct PlantEditor {
    editor: pipeline::PlantEditor,
}

#[cfg(feature = "studio-extras")]
mesh_getters!(PlantEditor, this => this.editor.plant());

#[cfg(feature = "studio-extras")]
#[wasm_bindgen]
impl PlantEditor {
    /// The path of each branch, as JSON: `[[0], [0, 0], [0, 1], …]` (branch `i` is entry `i`).
    #[wasm_bindgen(js_name = branchPaths)]
    pub fn branch_paths(&self) -> String {
        let paths: Vec<&Vec<u32>> = self
            .editor
            .tree()
            .branches
            .iter()
            .map(|b| &b.path)
            .collect();
        serde_json::to_string(&paths).unwrap_or_else(|_| "[]".into())
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
        let out: Vec<f32> = (0..n)
            .flat_map(|b| self.editor.control_points(b))
            .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
            .collect();
        js_sys::Float32Array::from(&out[..])
    }

    /// The joints of branch `branch` where they are now (3 floats each); empty for no branch.
    #[wasm_bindgen(js_name = branchJoints)]
    pub fn branch_joints(&self, branch: u32) -> js_sys::Float32Array {
        let flat: Vec<f32> = self
            .editor
            .joints(branch)
            .iter()
            .flat_map(|j| [j.x as f32, j.y as f32, j.z as f32])
            .collect();
        js_sys::Float32Array::from(&flat[..])
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
    /// vertices (`changedRanges`, `changedPositions`, `changedNormals`, `changedUvs`). Throws on a
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

    /// Meshes the edited plant again with other view options.
    pub fn remesh(&mut self, options: &ViewOptionsObject) -> Result<(), JsError> {
        let view = ViewOptionsFields::read(options)?;
        self.editor.remesh(&view.mesh());
        Ok(())
    }
}

#[cfg(feature = "studio-extras")]
impl PlantEditor {
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

#[cfg(feature = "studio-extras")]
/// A parsed and resolved grammar derived many times, without the turtle and mesh stages: the
/// benchmarks' entry point (`npm run bench`, `../shared/bench/js/meristem-peer.mjs`).
#[wasm_bindgen]
pub struct Grammar {
    model: crate::model::Model,
}

#[cfg(feature = "studio-extras")]
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

/// Imports files opened together, a vlab object (its `.l`, view file, functions and colours, as a
/// folder, several files or a `.zip`) or an L-Py model: `names[k]` is the k-th file's name (a path
/// inside the folder), its bytes are the next `lengths[k]` bytes of `bytes`. Returns the JSON of
/// [`import_grammar`] (`dialect` is null when nothing could be imported).
#[cfg(feature = "io")]
#[wasm_bindgen(js_name = importObject)]
pub fn import_object(names: Vec<String>, bytes: &[u8], lengths: &[u32]) -> String {
    use crate::import::{self, Dialect, Import, ObjectFile};
    #[derive(serde::Serialize)]
    struct Imported {
        #[serde(flatten)]
        import: Import,
        dialect: Option<Dialect>,
    }
    let mut files = Vec::new();
    let mut at = 0usize;
    for (name, &len) in names.into_iter().zip(lengths) {
        let end = at.saturating_add(len as usize).min(bytes.len());
        files.push(ObjectFile {
            name,
            bytes: bytes[at.min(end)..end].to_vec(),
        });
        at = end;
    }
    let (import, dialect) = import::import_files(&files);
    serde_json::to_string(&Imported { import, dialect }).unwrap_or_else(|_| "{}".into())
}

/// Translates `text`, written in another L-system dialect, into Meristem's language.
/// `dialect_or_file_name` is a dialect name (`green`, `lparser`, `cpfg`, `lpy`) or the file's
/// name, whose extension or content then tells the dialect. Returns JSON
/// `{text, notes: [{line, message}], dialect}`: `line` is 1-based in `text` (0 for the whole
/// file); when the dialect cannot be told, `text` is empty, `dialect` null and one note says why.
#[cfg(feature = "io")]
#[wasm_bindgen(js_name = importGrammar)]
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
