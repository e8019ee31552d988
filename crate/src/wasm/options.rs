//! The options objects JavaScript passes to the boundary's calls (`build`, `remesh`,
//! `exportModel`), each declared once in the table of [`options_objects!`], which gives both its
//! Rust reader and its TypeScript interface (the text of the `.d.ts` is generated from the same
//! rows, never written by hand).
//!
//! One reader for every object: field by field with `Reflect.get` rather than serde (issue 22, the
//! first load: serde's deserializer and its error messages were KBs of the first plant's wasm). A
//! field that is `undefined` or `null` is not given; other fields are ignored.

#[cfg(feature = "io")]
use crate::export;
use crate::mesh::MeshOptions;
use crate::pipeline::BuildOptions;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// A value an options field can hold, read from JavaScript and checked.
pub(super) trait FieldValue: Sized {
    /// The value of field `name`, or an error that names the field and what it must be.
    fn read(value: JsValue, name: &str) -> Result<Self, JsError>;
}

/// `bad options: NAME must be WHAT`.
fn bad(name: &str, what: &str) -> JsError {
    JsError::new(&format!("bad options: {name} {what}"))
}

impl FieldValue for f64 {
    fn read(value: JsValue, name: &str) -> Result<Self, JsError> {
        value.as_f64().ok_or_else(|| bad(name, "must be a number"))
    }
}

impl FieldValue for u32 {
    fn read(value: JsValue, name: &str) -> Result<Self, JsError> {
        let x = f64::read(value, name)?;
        if x.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&x) {
            Ok(x as u32)
        } else {
            Err(bad(
                name,
                &format!("must be a whole number from 0 to {}", u32::MAX),
            ))
        }
    }
}

impl FieldValue for bool {
    fn read(value: JsValue, name: &str) -> Result<Self, JsError> {
        value
            .as_bool()
            .ok_or_else(|| bad(name, "must be true or false"))
    }
}

impl FieldValue for String {
    fn read(value: JsValue, name: &str) -> Result<Self, JsError> {
        value
            .as_string()
            .ok_or_else(|| bad(name, "must be a string"))
    }
}

impl FieldValue for js_sys::Function {
    fn read(value: JsValue, name: &str) -> Result<Self, JsError> {
        value
            .dyn_into::<js_sys::Function>()
            .map_err(|_| bad(name, "must be a function"))
    }
}

/// Whether the mesh after a sketch has the segments' tubes ([`SketchFirstFields`]).
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default)]
pub(super) enum Tubes {
    /// Every segment as a tube.
    #[default]
    Always,
    /// No tubes: only leaves, polygons and spheres (the Lines mode draws the segments as lines).
    Never,
    /// No tubes when everything drawn lies in the plane z = 0 (the `auto` render mode).
    UnlessFlat,
}

impl FieldValue for Tubes {
    fn read(value: JsValue, name: &str) -> Result<Self, JsError> {
        match (value.as_bool(), value.as_string().as_deref()) {
            (Some(true), _) => Ok(Tubes::Always),
            (Some(false), _) => Ok(Tubes::Never),
            (_, Some("unlessFlat")) => Ok(Tubes::UnlessFlat),
            _ => Err(bad(name, "must be true, false or 'unlessFlat'")),
        }
    }
}

/// An options object being read; `None` for `undefined` and `null` (no options: every field is
/// absent).
struct OptionsObject<'a>(Option<&'a JsValue>);

impl<'a> OptionsObject<'a> {
    fn of(value: &'a JsValue) -> Self {
        Self((!value.is_undefined() && !value.is_null()).then_some(value))
    }

    /// Field `name`, `None` when it is `undefined` or `null`.
    fn get<T: FieldValue>(&self, name: &str) -> Result<Option<T>, JsError> {
        self.field(name)?.map(|v| T::read(v, name)).transpose()
    }

    /// The value of field `name` (not generic, so the first load carries one copy of it).
    fn field(&self, name: &str) -> Result<Option<JsValue>, JsError> {
        let Some(object) = self.0 else {
            return Ok(None);
        };
        let value = js_sys::Reflect::get(object, &JsValue::from_str(name))
            .map_err(|_| JsError::new("bad options: not an object"))?;
        Ok((!value.is_undefined() && !value.is_null()).then_some(value))
    }

    /// Field `name`, which must be given.
    fn require<T: FieldValue>(&self, name: &str) -> Result<T, JsError> {
        self.get(name)?.ok_or_else(|| bad(name, "is missing"))
    }
}

/// The Rust type of a field kind of [`options_objects!`].
macro_rules! rust_type {
    (number) => {
        f64
    };
    (whole) => {
        u32
    };
    (flag) => {
        bool
    };
    (text) => {
        String
    };
    (tubes) => {
        Tubes
    };
    (show) => {
        js_sys::Function
    };
    (SvgLook) => {
        SvgLookFields
    };
    (SketchFirst) => {
        SketchFirstFields
    };
}

/// The TypeScript type of a field kind of [`options_objects!`].
macro_rules! ts_type {
    (number) => {
        "number"
    };
    (whole) => {
        "number"
    };
    (flag) => {
        "boolean"
    };
    (text) => {
        "string"
    };
    (tubes) => {
        "boolean | \"unlessFlat\""
    };
    (show) => {
        "(lines: Float32Array, lineColors: Float32Array, flat: boolean, segments: number) => void"
    };
    (SvgLook) => {
        "SvgLook"
    };
    (SketchFirst) => {
        "SketchFirst"
    };
}

/// A field's type in its Rust struct: `Option<T>`, or `T` when it is required.
macro_rules! field_type {
    ($t:ty) => { Option<$t> };
    ($t:ty, required) => { $t };
}

/// The `?` of an optional field in TypeScript.
macro_rules! ts_optional {
    () => {
        "?"
    };
    (required) => {
        ""
    };
}

/// Reads a field of an options object: [`OptionsObject::get`], or `require` when it is required.
macro_rules! read_field {
    ($object:ident, $js:literal) => {
        $object.get($js)?
    };
    ($object:ident, $js:literal, required) => {
        $object.require($js)?
    };
}

/// The options objects, one row per field: its doc, its name in JavaScript, its field in Rust and
/// its kind (the Rust and TypeScript types: [`rust_type!`], [`ts_type!`]), `required` when it must
/// be given. Each object becomes a Rust struct with a `read` from a `JsValue` (`undefined` and
/// `null` are no options), `FieldValue` (so it can be a field itself), an imported JavaScript type
/// for the signatures of the calls (`BuildOptionsObject` is TypeScript's `BuildOptions`), and its
/// interface in the TypeScript const named first (`BUILD_TYPESCRIPT`...). An object that `extends` another holds the other's fields in
/// `base` (Rust) and extends its interface (TypeScript).
macro_rules! options_objects {
    ($typescript:ident; $(
        $(#[doc = $doc:literal])*
        $ts:literal $(extends $base_ts:literal $base:ident)? => $import:ident, $fields:ident {
            $(
                $(#[doc = $field_doc:literal])+
                $js:literal => $field:ident: $kind:ident $(, $required:ident)?;
            )*
        }
    )*) => {
        #[wasm_bindgen]
        extern "C" {
            $(
                #[wasm_bindgen(typescript_type = $ts)]
                pub type $import;
            )*
        }

        #[wasm_bindgen(typescript_custom_section)]
        const OPTIONS_INTERFACES: &str = $typescript;

        /// Options interfaces in TypeScript (in the packages' `.d.ts`), generated from the rows
        /// of [`options_objects!`].
        pub const $typescript: &str = concat!($(
            "\n/**", $($doc,)* " */\n",
            "export interface ", $ts, $(" extends ", $base_ts,)? " {\n",
            $(
                "  /**", $($field_doc,)+ " */\n",
                "  ", $js, ts_optional!($($required)?), ": ", ts_type!($kind), ";\n",
            )*
            "}\n",
        )*);

        $(
            #[doc = concat!("`", $ts, "` as read.")]
            pub(super) struct $fields {
                $(pub base: $base,)?
                $(
                    $(#[doc = $field_doc])+
                    pub $field: field_type!(rust_type!($kind) $(, $required)?),
                )*
            }

            impl $fields {
                #[doc = concat!("Reads a `", $ts, "` object (`undefined` and `null` are no options).")]
                pub fn read(value: &JsValue) -> Result<Self, JsError> {
                    let object = OptionsObject::of(value);
                    Ok(Self {
                        $(base: $base::read(value)?,)?
                        $($field: read_field!(object, $js $(, $required)?),)*
                    })
                }
            }

            impl FieldValue for $fields {
                fn read(value: JsValue, _name: &str) -> Result<Self, JsError> {
                    $fields::read(&value)
                }
            }
        )*
    };
}

options_objects! { BUILD_TYPESCRIPT;
    /// Options of `build`: every field is optional (the grammar's own settings, 6 sides, no smoothing).
    "BuildOptions" => BuildOptionsObject, BuildOptionsFields {
        /// Overrides `#iterations`.
        "iterations" => iterations: whole;
        /// Overrides `#seed`: a whole number from 0 to 2^53 (other values are ignored).
        "seed" => seed: number;
        /// The growth time in steps, overriding `iterations`: a timed grammar (`#terminal_age`) is
        /// shown at time `time · #dt`, between steps when it is a fraction; any other grammar at
        /// its whole steps, `floor(time)`.
        "time" => time: number;
        /// Sides of each branch tube, 3 to 64.
        "sides" => sides: whole;
        /// Every axis as a smooth generalized cylinder.
        "smoothAll" => smooth_all: flag;
        /// Segments as lines instead of tubes (a sketch, cheap to make; `remesh` gives the tubes).
        "sketch" => sketch: flag;
        /// A sketch first, shown while the same call meshes the plant (the live preview of big plants).
        "sketchFirst" => sketch_first: SketchFirst;
        /// The mesh carries its growth in time: `growthOrigins` and `growthTimes` (docs/LANGUAGE.md, "Growth in time").
        "growth" => growth: flag;
    }
    /// The sketch a build shows before it meshes (`BuildOptions.sketchFirst`).
    "SketchFirst" => SketchFirstObject, SketchFirstFields {
        /// Plants of fewer segments are not shown as a sketch.
        "minSegments" => min_segments: whole, required;
        /// Told the sketch of a plant without errors: line ends (x, y, z each) and their colours, views of the core's memory valid only during the call (copy them), whether it is flat, and its segments.
        "show" => show: show, required;
        /// Whether the mesh after the sketch has the segments' tubes: true (the default), false (only leaves, polygons and spheres), or `"unlessFlat"`.
        "tubes" => tubes: tubes;
    }
    /// The mesh's view options, for `PlantBuild.remesh` and `PlantEditor.remesh`.
    "ViewOptions" => ViewOptionsObject, ViewOptionsFields {
        /// Sides of each branch tube, 3 to 64.
        "sides" => sides: whole;
        /// Every axis as a smooth generalized cylinder.
        "smoothAll" => smooth_all: flag;
        /// False: no tubes, only leaves, polygons and spheres (the Lines mode draws the segments as lines).
        "tubes" => tubes: flag;
        /// The mesh carries its growth in time: `growthOrigins` and `growthTimes`.
        "growth" => growth: flag;
    }
}

// The export's options: crate/pkg only (the `io` feature).
#[cfg(feature = "io")]
options_objects! { EXPORT_TYPESCRIPT;
    /// Options of `exportModel`: the build's, and what to write.
    "ExportOptions" extends "BuildOptions" BuildOptionsFields => ExportOptionsObject, ExportOptionsFields {
        /// `wrl`, `glb`, `pov`, `obj`, `iv` or `svg`.
        "format" => format: text, required;
        /// File name without extension; default `plant`. A zip of several files is `NAME-FORMAT.zip`. Made a safe stem first: at most 64 characters, path separators, control characters and spaces as `-`, no dot or dash at either end (`../../x` gives `x`).
        "name" => name: text;
        /// An edits document (JSON text) to apply first.
        "edits" => edits: text;
        /// An SVG's picture settings (refused for the other formats).
        "svg" => svg: SvgLook;
        /// glTF only: the plant's growth as a glTF animation (morph targets keyed in time; docs/LANGUAGE.md, "Growth in time").
        "animate" => animate: flag;
        /// With `animate`: seconds of animation per derivation step, 0.001 to 3600 (default 1).
        "secondsPerStep" => seconds_per_step: number;
        /// With `animate`: morph targets per step, 1 to 16 (default 4).
        "targetsPerStep" => targets_per_step: whole;
    }
    /// An SVG's picture settings: the CLI's `--background`, `--line-width`, `--size` and `--dpi`.
    "SvgLook" => SvgLookObject, SvgLookFields {
        /// `white`, `none` (transparent, the default) or a hex colour: `#` and six hex digits.
        "background" => background: text;
        /// Every line this wide in the picture's pixels, 0.5 to 60 (the Lines mode).
        "lineWidth" => line_width: number;
        /// The picture's width in pixels, 16 to 8192 (with its height, or neither).
        "width" => width: whole;
        /// The picture's height in pixels, 16 to 8192 (with its width, or neither).
        "height" => height: whole;
        /// Dots per inch, 10 to 2400: the width and height are then written in millimetres.
        "dpi" => dpi: number;
    }
}

impl BuildOptionsFields {
    /// No options: the grammar's own settings.
    #[cfg(feature = "studio-extras")]
    pub fn none() -> Self {
        Self {
            iterations: None,
            seed: None,
            time: None,
            sides: None,
            smooth_all: None,
            sketch: None,
            sketch_first: None,
            growth: None,
        }
    }

    /// The pipeline's options; a seed that is not a whole number from 0 to 2^53 is ignored. A
    /// build with a sketch first is a sketch (its mesh comes after, with the sketch's `tubes`).
    pub fn options(&self) -> BuildOptions {
        let seed = self.seed.filter(|s| {
            s.is_finite() && *s >= 0.0 && s.fract() == 0.0 && *s <= 9.007_199_254_740_992e15
        });
        let sketch = self.sketch == Some(true) || self.sketch_first.is_some();
        let mut mesh = MeshOptions::view(self.sides, self.smooth_all);
        mesh.growth = self.growth == Some(true);
        if sketch {
            mesh.max_vertices = 0;
        }
        BuildOptions {
            iterations: self.iterations,
            seed: seed.map(|s| s as u64),
            time: self.time,
            mesh,
            sketch,
        }
    }
}

impl ViewOptionsFields {
    /// The mesh options of a remesh.
    pub fn mesh(&self) -> MeshOptions {
        MeshOptions {
            tubes: self.tubes.unwrap_or(true),
            growth: self.growth == Some(true),
            ..MeshOptions::view(self.sides, self.smooth_all)
        }
    }
}

#[cfg(feature = "io")]
impl ExportOptionsFields {
    /// The growth animation asked for (`animate`), with its settings.
    pub fn animation(&self) -> Option<export::animation::Animation> {
        let defaults = export::animation::Animation::default();
        (self.animate == Some(true)).then(|| export::animation::Animation {
            seconds_per_step: self.seconds_per_step.unwrap_or(defaults.seconds_per_step),
            targets_per_step: self.targets_per_step.unwrap_or(defaults.targets_per_step),
        })
    }
}

#[cfg(feature = "io")]
impl SvgLookFields {
    /// The look, checked.
    pub fn look(&self) -> Result<export::svg::Look, String> {
        let size = match (self.width, self.height) {
            (Some(w), Some(h)) => Some((w, h)),
            (None, None) => None,
            _ => return Err("an SVG's size needs both its width and its height".into()),
        };
        export::svg::Look::read(self.background.as_deref(), self.line_width, size, self.dpi)
    }
}

#[cfg(test)]
mod tests {
    use super::{BUILD_TYPESCRIPT, EXPORT_TYPESCRIPT};

    #[test]
    fn the_typescript_interfaces_are_generated_from_the_rows() {
        for declaration in [
            "export interface BuildOptions {",
            "  iterations?: number;",
            "  smoothAll?: boolean;",
            "  growth?: boolean;",
            "  sketchFirst?: SketchFirst;",
            "export interface SketchFirst {",
            "  minSegments: number;",
            "  tubes?: boolean | \"unlessFlat\";",
            "export interface ViewOptions {",
            "export interface ExportOptions extends BuildOptions {",
            "  format: string;",
            "  svg?: SvgLook;",
            "export interface SvgLook {",
            "  lineWidth?: number;",
        ] {
            let typescript = format!("{BUILD_TYPESCRIPT}{EXPORT_TYPESCRIPT}");
            assert!(
                typescript.lines().any(|line| line == declaration),
                "{declaration:?} is not in\n{typescript}"
            );
        }
    }
}
