//! glTF 2.0 binary (`.glb`): one mesh whose primitives are the colour indices, each with its own
//! PBR material (`baseColorFactor` = the palette colour, linear; metallic 0, roughness 0.85 as in
//! the preview), sharing one `POSITION` and one `NORMAL` accessor (with `min`/`max` on
//! `POSITION`) and indexing them with `u32` indices. The JSON chunk is padded with spaces and the
//! binary chunk with zeros to 4 bytes. A model too large to mesh becomes `LINES` primitives.
//!
//! Written here rather than with three.js's GLTFExporter so that the command-line tool and the
//! studio give the same bytes, and so that it runs wherever the core runs (a worker, Node) with
//! no `FileReader`.

use super::scene::{Primitive, Scene};
use serde_json::{json, Value};

const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;
const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const TRIANGLES: u32 = 4;
const LINES: u32 = 1;

/// The GLB bytes of `scene`.
pub fn write(scene: &Scene) -> Vec<u8> {
    let primitive = scene.primitive();
    let points = scene.points();
    let groups = scene.groups();
    let mut bin: Vec<u8> = Vec::new();
    let mut buffer_views: Vec<Value> = Vec::new();
    let mut accessors: Vec<Value> = Vec::new();
    let mut materials: Vec<Value> = Vec::new();
    let mut primitives: Vec<Value> = Vec::new();

    if !groups.is_empty() {
        let count = points.len() / 3;
        let (min, max) = min_max(points);
        buffer_views.push(view(&mut bin, floats(points), Some(ARRAY_BUFFER)));
        accessors.push(json!({
            "bufferView": 0, "componentType": FLOAT, "count": count, "type": "VEC3",
            "min": min, "max": max,
        }));
        let mut attributes = json!({ "POSITION": 0 });
        if primitive == Primitive::Triangles {
            buffer_views.push(view(
                &mut bin,
                floats(&scene.mesh.normals),
                Some(ARRAY_BUFFER),
            ));
            accessors.push(json!({
                "bufferView": 1, "componentType": FLOAT, "count": count, "type": "VEC3",
            }));
            attributes["NORMAL"] = json!(1);
        }
        let arity = scene.arity();
        let index_view = buffer_views.len();
        let start = bin.len();
        for group in &groups {
            let offset = bin.len() - start;
            for &item in &group.items {
                for corner in &scene.corners(item)[..arity] {
                    bin.extend_from_slice(&corner.to_le_bytes());
                }
            }
            let [r, g, b] = group.color;
            materials.push(json!({
                "name": format!("color_{}", group.index),
                "pbrMetallicRoughness": {
                    "baseColorFactor": [r as f64, g as f64, b as f64, 1.0],
                    "metallicFactor": 0.0,
                    "roughnessFactor": 0.85,
                },
            }));
            primitives.push(json!({
                "attributes": attributes,
                "indices": accessors.len(),
                "material": materials.len() - 1,
                "mode": if primitive == Primitive::Triangles { TRIANGLES } else { LINES },
            }));
            accessors.push(json!({
                "bufferView": index_view, "byteOffset": offset, "componentType": UNSIGNED_INT,
                "count": group.items.len() * arity, "type": "SCALAR",
            }));
        }
        buffer_views.push(json!({
            "buffer": 0, "byteOffset": start, "byteLength": bin.len() - start,
            "target": ELEMENT_ARRAY_BUFFER,
        }));
    }

    let mut document = json!({
        "asset": {
            "version": "2.0",
            "generator": format!("Meristem {}", env!("CARGO_PKG_VERSION")),
        },
        "scene": 0,
        "scenes": [{ "name": "Meristem plant" }],
    });
    if !primitives.is_empty() {
        document["scenes"][0]["nodes"] = json!([0]);
        document["nodes"] = json!([{ "name": "plant", "mesh": 0 }]);
        document["meshes"] = json!([{ "name": "plant", "primitives": primitives }]);
        document["materials"] = Value::Array(materials);
        document["accessors"] = Value::Array(accessors);
        document["bufferViews"] = Value::Array(buffer_views);
        document["buffers"] = json!([{ "byteLength": bin.len() }]);
    }
    glb(&serde_json::to_vec(&document).unwrap_or_default(), &bin)
}

/// Appends `bytes` to the binary chunk (at a 4-byte boundary) and returns its buffer view.
fn view(bin: &mut Vec<u8>, bytes: Vec<u8>, target: Option<u32>) -> Value {
    let offset = bin.len();
    bin.extend_from_slice(&bytes);
    let mut view = json!({ "buffer": 0, "byteOffset": offset, "byteLength": bytes.len() });
    if let Some(target) = target {
        view["target"] = json!(target);
    }
    view
}

fn floats(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// Per-component minimum and maximum of `f32` × 3 points, as the exact `f32` values (written as
/// the `f64` that equals them, so a reader comparing in either precision finds them equal).
fn min_max(points: &[f32]) -> (Vec<f64>, Vec<f64>) {
    let mut min = [f32::INFINITY; 3];
    let mut max = [f32::NEG_INFINITY; 3];
    for p in points.chunks_exact(3) {
        for k in 0..3 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    (
        min.iter().map(|&v| v as f64).collect(),
        max.iter().map(|&v| v as f64).collect(),
    )
}

/// The GLB container: a 12-byte header, the JSON chunk padded with spaces, and (when there is
/// binary data) the BIN chunk padded with zeros, every chunk 4-byte aligned.
fn glb(json: &[u8], bin: &[u8]) -> Vec<u8> {
    let pad = |n: usize| (4 - n % 4) % 4;
    let json_length = json.len() + pad(json.len());
    let bin_length = bin.len() + pad(bin.len());
    let total = 12 + 8 + json_length + if bin.is_empty() { 0 } else { 8 + bin_length };
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json_length as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(json);
    out.resize(out.len() + pad(json.len()), b' ');
    if !bin.is_empty() {
        out.extend_from_slice(&(bin_length as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(bin);
        out.resize(out.len() + pad(bin.len()), 0);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::tests::{small_scene, two_colour_plant};

    fn u32_at(bytes: &[u8], at: usize) -> u32 {
        u32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
    }

    /// The JSON document and the binary chunk of a GLB, checking the container on the way.
    fn parse(glb: &[u8]) -> (Value, Vec<u8>) {
        assert_eq!(&glb[..4], b"glTF");
        assert_eq!(u32_at(glb, 4), 2);
        assert_eq!(u32_at(glb, 8) as usize, glb.len());
        let json_length = u32_at(glb, 12) as usize;
        assert_eq!(json_length % 4, 0);
        assert_eq!(&glb[16..20], b"JSON");
        let document: Value = serde_json::from_slice(&glb[20..20 + json_length]).expect("JSON");
        let at = 20 + json_length;
        if at == glb.len() {
            return (document, Vec::new());
        }
        let bin_length = u32_at(glb, at) as usize;
        assert_eq!(bin_length % 4, 0);
        assert_eq!(&glb[at + 4..at + 8], b"BIN\0");
        assert_eq!(at + 8 + bin_length, glb.len());
        (document, glb[at + 8..].to_vec())
    }

    #[test]
    fn one_material_and_primitive_per_colour_index_over_shared_vertices() {
        let (mesh, skeleton) = two_colour_plant();
        let (document, bin) = parse(&write(&Scene::new(&mesh, &skeleton)));
        let primitives = document["meshes"][0]["primitives"]
            .as_array()
            .expect("primitives");
        assert_eq!(primitives.len(), 2);
        assert_eq!(document["materials"].as_array().map(Vec::len), Some(2));
        assert_eq!(document["materials"][1]["name"], "color_1");
        let position = &document["accessors"][0];
        assert_eq!(position["count"], mesh.vertex_count());
        let [min, max] = mesh.bounds();
        for k in 0..3 {
            assert_eq!(position["min"][k].as_f64(), Some(min[k]));
            assert_eq!(position["max"][k].as_f64(), Some(max[k]));
        }
        let indices: u64 = primitives
            .iter()
            .map(|p| {
                document["accessors"][p["indices"].as_u64().unwrap_or(0) as usize]["count"]
                    .as_u64()
                    .unwrap_or(0)
            })
            .sum();
        assert_eq!(indices as usize, mesh.indices.len());
        assert_eq!(document["buffers"][0]["byteLength"], bin.len());
    }

    #[test]
    fn an_empty_model_is_a_scene_with_nothing_in_it() {
        let (document, bin) = parse(&write(&Scene::new(
            &crate::mesh::MeshBuffers::default(),
            &crate::turtle::Skeleton::default(),
        )));
        assert!(bin.is_empty());
        assert!(document.get("meshes").is_none());
        assert_eq!(document["asset"]["version"], "2.0");
    }

    #[test]
    fn the_fallback_writes_line_primitives() {
        let (mesh, skeleton) = small_scene(10);
        let (document, _) = parse(&write(&Scene::new(&mesh, &skeleton)));
        assert_eq!(document["meshes"][0]["primitives"][0]["mode"], LINES);
        assert!(document["meshes"][0]["primitives"][0]["attributes"]
            .get("NORMAL")
            .is_none());
    }
}
