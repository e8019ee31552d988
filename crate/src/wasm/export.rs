//! Exports at the boundary: a model written as one file to download (`exportModel`).

use super::options::{ExportOptionsFields, ExportOptionsObject};
use crate::branches::parse_edits;
use crate::export::{self, Format};
use crate::pipeline::{self, Hooks, Progress, Stage};
use wasm_bindgen::prelude::*;

/// Builds and writes the model as one file to download (a zip when the format has several: OBJ
/// and its MTL, POV-Ray's scene and its textures). The bytes are those of `meristem export` for
/// the same grammar and options. `progress(stage, index, count)` is told each stage as it starts
/// (`parsing`, `deriving`, `interpreting`, `meshing`, `applying edits`, `writing`). Throws when
/// the format is unknown, the edits are malformed or the grammar has errors.
#[wasm_bindgen(js_name = exportModel)]
pub fn export_model(
    source: &str,
    options: &ExportOptionsObject,
    progress: Option<js_sys::Function>,
) -> Result<ExportedModel, JsError> {
    let fields = ExportOptionsFields::read(options)?;
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
    let animation = fields.animation();
    // The name comes from any caller of the API: it is made a safe stem before it names a file
    // or is written into one (`"../../x"` would name zip entries outside the folder unpacked,
    // a line break would add a line to the OBJ).
    let stem = export::safe_stem(fields.name.as_deref().unwrap_or("plant"));
    let options = pipeline::ExportOptions {
        build: fields.base.options(),
        format,
        stem: stem.clone(),
        edits,
        look,
        animation,
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
    let exported = pipeline::export(source, &options, &mut hooks).map_err(|e| match e {
        pipeline::ExportError::Grammar(_) => {
            JsError::new("the grammar has errors: nothing to export")
        }
        pipeline::ExportError::Refused(message) => JsError::new(&message),
    })?;
    // Several files go in one zip named after the format too: `fern-pov.zip`, `fern-obj.zip`.
    let file = export::bundle(exported.files, &format!("{stem}-{}", format.extension()))
        .ok_or_else(|| JsError::new("the export is larger than 4 GiB"))?;
    Ok(ExportedModel { file })
}

/// One file to download. Free it with `.free()` once its bytes are copied.
#[wasm_bindgen]
pub struct ExportedModel {
    file: export::ExportedFile,
}

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
