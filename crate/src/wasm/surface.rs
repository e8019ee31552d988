//! `surfacePreview`: one declared surface for the studio's surface editor
//! ([`crate::pipeline::surface_preview`]), as JSON: small (a few patches' points and their
//! tessellation, at most 64 patches of 33 × 33 points).

use crate::diagnostics::locate_all;
use crate::pipeline::surface_preview;
use serde_json::{json, Value};
use wasm_bindgen::prelude::*;

/// Surface `letter` (one letter X of `#surface X` / `#patch X`) of `source`: JSON
/// `{surface, diagnostics}`, `surface` null when the text declares none that resolves, else
/// `{letter, organ, net, written, toTurtle, end, precision, positions, normals, indices, writeOut,
/// colors}` with byte spans (`web/src/core/surface-preview.ts` reads it); `colors` (each patch's
/// front and back colour as the plant draws it, linear r g b) is empty unless `colours`, which
/// derives the plant.
#[wasm_bindgen(js_name = surfacePreview)]
pub fn surface_preview_json(source: &str, letter: &str, colours: bool) -> String {
    let mut chars = letter.chars();
    let (preview, diagnostics) = match (chars.next(), chars.next()) {
        (Some(c), None) => surface_preview(source, c, colours),
        _ => (None, Vec::new()),
    };
    let surface = preview.map_or(Value::Null, |p| {
        let s = &p.shape;
        json!({
            "letter": s.letter.to_string(),
            "organ": s.organ.map(|o| o.name()),
            "net": s.patches.iter().flatten().flat_map(|q| q.to_array()).collect::<Vec<f64>>(),
            "written": s.written.iter().map(|w| json!({
                "patch": w.patch, "index": w.index, "value": w.value, "from": w.span.start, "to": w.span.end,
            })).collect::<Vec<Value>>(),
            "toTurtle": p.to_turtle.to_vec(),
            "end": s.end.map(|e| e.to_array()),
            "precision": s.precision,
            "positions": p.positions,
            "normals": p.normals,
            "indices": p.indices,
            "writeOut": p.write_out.iter().map(|(span, insert)| json!({
                "from": span.start, "to": span.end, "insert": insert,
            })).collect::<Vec<Value>>(),
            "colors": p.colors,
        })
    });
    json!({ "surface": surface, "diagnostics": locate_all(source, &diagnostics) }).to_string()
}
