//! glTF 2.0 binary (`.glb`): one mesh whose primitives are the colour indices, each with its own
//! PBR material (`baseColorFactor` = the palette colour, linear; metallic 0, roughness 0.85 as in
//! the preview), sharing one `POSITION` and one `NORMAL` accessor (with `min`/`max` on
//! `POSITION`) and indexing them with `u32` indices. The JSON chunk is padded with spaces and the
//! binary chunk with zeros to 4 bytes. A model too large to mesh becomes `LINES` primitives.
//!
//! Textures: a `TEXCOORD_0` accessor (`MeshBuffers::uvs`) and, within each colour index, one
//! primitive per material kind (`MeshBuffers::material_ranges`): bark triangles (material
//! `color_3`) with the bark texture, leaf triangles (`color_3_leaf`) with the leaf texture,
//! `alphaMode` `MASK` and `doubleSided`, and sphere triangles (`color_3_plain`) untextured. The
//! textures (`public/textures/*.png`, compiled in) are embedded in the binary chunk as
//! `image/png` buffer views, only those some triangle uses, with a repeating, mipmapped sampler.
//!
//! Written here rather than with three.js's GLTFExporter so that the command-line tool and the
//! studio give the same bytes, and so that it runs wherever the core runs (a worker, Node) with
//! no `FileReader`.

use super::animation::Keyframes;
use super::scene::{ColorGroup, Primitive, Scene};
use super::textures::{BARK_PNG, LEAF_PNG};
use crate::mesh::{MATERIAL_BARK, MATERIAL_LEAF, MATERIAL_PLAIN};
use serde_json::{json, Value};

const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;
const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const TRIANGLES: u32 = 4;
const LINES: u32 = 1;
const LINEAR: u32 = 9729;
const LINEAR_MIPMAP_LINEAR: u32 = 9987;
const REPEAT: u32 = 10497;

/// The GLB bytes of `scene`.
pub fn write(scene: &Scene) -> Vec<u8> {
    write_animated(scene, None)
}

/// The GLB bytes of `scene`, with the plant's growth as an animation when `growth` holds its
/// keyframes ([`super::animation`]): a morph target per keyframe but the last on every
/// primitive, and an animation `growth` of the mesh's weights.
pub fn write_animated(scene: &Scene, growth: Option<&Keyframes>) -> Vec<u8> {
    let groups = scene.groups();
    let mut document = Document::default();
    if !groups.is_empty() {
        let mut attributes = document.vertex_attributes(scene);
        if let Some(keyframes) = growth.filter(|k| !k.targets.is_empty()) {
            attributes = document.morph_targets(keyframes, attributes);
        }
        document.primitives(scene, &groups, &attributes);
        if let Some(keyframes) = growth.filter(|k| !k.targets.is_empty()) {
            document.animation(keyframes);
        }
        document.embed_textures();
        document.pad_bin();
    }
    document.into_glb()
}

/// The glTF document as it is written: the binary chunk and the JSON arrays that point into it.
#[derive(Default)]
struct Document {
    /// The binary chunk: vertex attributes, then indices, then the embedded images.
    bin: Vec<u8>,
    buffer_views: Vec<Value>,
    accessors: Vec<Value>,
    materials: Vec<Value>,
    primitives: Vec<Value>,
    images: Vec<Value>,
    /// The material kind each texture shows (bark or leaf), in the order they were first used;
    /// texture `i` shows image `i`.
    textures: Vec<u32>,
    /// With a growth animation: the morph targets' count and the animation.
    morph_targets: usize,
    animation: Option<Value>,
}

impl Document {
    /// Writes the vertex attributes every primitive shares (`POSITION` with `min`/`max`, and for
    /// triangles `NORMAL` and `TEXCOORD_0`) and returns the `attributes` object naming them.
    fn vertex_attributes(&mut self, scene: &Scene) -> Value {
        let points = scene.points();
        let count = points.len() / 3;
        let (min, max) = min_max(points);
        self.attribute(
            floats(points),
            json!({
                "bufferView": 0, "componentType": FLOAT, "count": count, "type": "VEC3",
                "min": min, "max": max,
            }),
        );
        let mut attributes = json!({ "POSITION": 0 });
        if scene.primitive() == Primitive::Triangles {
            self.attribute(
                floats(&scene.mesh.normals),
                json!({
                    "bufferView": 1, "componentType": FLOAT, "count": count, "type": "VEC3",
                }),
            );
            attributes["NORMAL"] = json!(1);
            self.attribute(
                floats(&scene.mesh.uvs),
                json!({
                    "bufferView": 2, "componentType": FLOAT, "count": count, "type": "VEC2",
                }),
            );
            attributes["TEXCOORD_0"] = json!(2);
        }
        attributes
    }

    /// The morph targets of `keyframes` (a `POSITION` accessor each, with `min`/`max`), after
    /// the vertex attributes: `attributes` and `{"targets": [...]}`, split again by
    /// [`Document::primitives`].
    fn morph_targets(&mut self, keyframes: &Keyframes, attributes: Value) -> Value {
        let mut targets = Vec::with_capacity(keyframes.targets.len());
        for displacement in &keyframes.targets {
            let (min, max) = min_max(displacement);
            let accessor = self.accessors.len();
            self.buffer_views.push(view(
                &mut self.bin,
                floats(displacement),
                Some(ARRAY_BUFFER),
            ));
            self.accessors.push(json!({
                "bufferView": self.buffer_views.len() - 1, "componentType": FLOAT,
                "count": displacement.len() / 3, "type": "VEC3", "min": min, "max": max,
            }));
            targets.push(json!({ "POSITION": accessor }));
        }
        self.morph_targets = targets.len();
        json!({ "attributes": attributes, "targets": targets })
    }

    /// The animation `growth`: the keyframes' times (seconds) and the weights at each, linearly
    /// interpolated, on node 0's weights.
    fn animation(&mut self, keyframes: &Keyframes) {
        let times = &keyframes.seconds;
        let input = self.accessors.len();
        self.buffer_views
            .push(view(&mut self.bin, floats(times), None));
        self.accessors.push(json!({
            "bufferView": self.buffer_views.len() - 1, "componentType": FLOAT,
            "count": times.len(), "type": "SCALAR",
            "min": [times.first().copied().unwrap_or(0.0)],
            "max": [times.last().copied().unwrap_or(0.0)],
        }));
        let weights = keyframes.weights();
        self.buffer_views
            .push(view(&mut self.bin, floats(&weights), None));
        self.accessors.push(json!({
            "bufferView": self.buffer_views.len() - 1, "componentType": FLOAT,
            "count": weights.len(), "type": "SCALAR",
        }));
        self.animation = Some(json!({
            "name": "growth",
            "samplers": [{ "input": input, "output": input + 1, "interpolation": "LINEAR" }],
            "channels": [{ "sampler": 0, "target": { "node": 0, "path": "weights" } }],
        }));
    }

    /// Appends a vertex attribute's `bytes` in a buffer view of its own, and its `accessor`.
    fn attribute(&mut self, bytes: Vec<u8>, accessor: Value) {
        self.buffer_views
            .push(view(&mut self.bin, bytes, Some(ARRAY_BUFFER)));
        self.accessors.push(accessor);
    }

    /// One primitive per colour group and (for triangles) material kind that has any items, with
    /// its material; their indices one after the other in one buffer view.
    fn primitives(&mut self, scene: &Scene, groups: &[ColorGroup], attributes: &Value) {
        let primitive = scene.primitive();
        let (kinds, materials_of): (&[u32], Vec<u8>) = if primitive == Primitive::Triangles {
            (
                &[MATERIAL_BARK, MATERIAL_LEAF, MATERIAL_PLAIN],
                scene.mesh.triangle_materials(),
            )
        } else {
            (&[MATERIAL_PLAIN], Vec::new())
        };
        let kind_of = |item: u32| {
            materials_of
                .get(item as usize)
                .map_or(MATERIAL_PLAIN, |&m| m as u32)
        };
        let index_view = self.buffer_views.len();
        let start = self.bin.len();
        for group in groups {
            for &kind in kinds {
                let offset = self.bin.len() - start;
                let items = group
                    .items
                    .iter()
                    .copied()
                    .filter(|&item| primitive != Primitive::Triangles || kind_of(item) == kind);
                let count = self.indices(scene, items);
                if count == 0 {
                    continue;
                }
                let material = self.material(group, kind, primitive);
                self.materials.push(material);
                let mut p = json!({
                    "attributes": attributes.get("attributes").unwrap_or(attributes),
                    "indices": self.accessors.len(),
                    "material": self.materials.len() - 1,
                    "mode": if primitive == Primitive::Triangles { TRIANGLES } else { LINES },
                });
                if let Some(targets) = attributes.get("targets") {
                    p["targets"] = targets.clone();
                }
                self.primitives.push(p);
                self.accessors.push(json!({
                    "bufferView": index_view, "byteOffset": offset, "componentType": UNSIGNED_INT,
                    "count": count, "type": "SCALAR",
                }));
            }
        }
        self.buffer_views.push(json!({
            "buffer": 0, "byteOffset": start, "byteLength": self.bin.len() - start,
            "target": ELEMENT_ARRAY_BUFFER,
        }));
    }

    /// Appends the corners of `items` (triangles or lines) to the binary chunk as `u32`s;
    /// returns how many it wrote.
    fn indices(&mut self, scene: &Scene, items: impl Iterator<Item = u32>) -> usize {
        let arity = scene.arity();
        let mut count = 0;
        for item in items {
            count += arity;
            for corner in &scene.corners(item)[..arity] {
                self.bin.extend_from_slice(&corner.to_le_bytes());
            }
        }
        count
    }

    /// The material of `group`'s items of material `kind`: the group's colour, with the bark or
    /// leaf texture (leaves alpha-masked and two-sided) or none.
    fn material(&mut self, group: &ColorGroup, kind: u32, primitive: Primitive) -> Value {
        let [r, g, b] = group.color;
        let (suffix, textured) = match (primitive, kind) {
            (Primitive::Lines, _) => ("", false),
            (_, MATERIAL_BARK) => ("", true),
            (_, MATERIAL_LEAF) => ("_leaf", true),
            _ => ("_plain", false),
        };
        let mut material = json!({
            "name": format!("color_{}{}", group.index, suffix),
            "pbrMetallicRoughness": {
                "baseColorFactor": [r as f64, g as f64, b as f64, 1.0],
                "metallicFactor": 0.0,
                "roughnessFactor": 0.85,
            },
        });
        if textured {
            material["pbrMetallicRoughness"]["baseColorTexture"] =
                json!({ "index": self.texture(kind), "texCoord": 0 });
        }
        if kind == MATERIAL_LEAF && primitive == Primitive::Triangles {
            material["alphaMode"] = json!("MASK");
            material["alphaCutoff"] = json!(0.5);
            material["doubleSided"] = json!(true);
        }
        material
    }

    /// The index of the texture of material `kind`, added when no material used it before.
    fn texture(&mut self, kind: u32) -> usize {
        match self.textures.iter().position(|&k| k == kind) {
            Some(texture) => texture,
            None => {
                self.textures.push(kind);
                self.textures.len() - 1
            }
        }
    }

    /// Embeds the image of each texture after the indices, each in its own buffer view at a
    /// 4-byte boundary.
    fn embed_textures(&mut self) {
        for texture in 0..self.textures.len() {
            let (bytes, name) = if self.textures[texture] == MATERIAL_LEAF {
                (LEAF_PNG, "leaf")
            } else {
                (BARK_PNG, "bark")
            };
            self.pad_bin();
            self.buffer_views
                .push(view(&mut self.bin, bytes.to_vec(), None));
            self.images.push(json!({
                "name": name, "bufferView": self.buffer_views.len() - 1, "mimeType": "image/png",
            }));
        }
    }

    /// Pads the binary chunk with zeros to a 4-byte boundary.
    fn pad_bin(&mut self) {
        self.bin.resize(self.bin.len().next_multiple_of(4), 0);
    }

    /// The GLB container of the document: its JSON and its binary chunk.
    fn into_glb(mut self) -> Vec<u8> {
        let bin = std::mem::take(&mut self.bin);
        let json = self.json(bin.len());
        glb(&serde_json::to_vec(&json).unwrap_or_default(), &bin)
    }

    /// The JSON document (its binary chunk `bin_length` bytes long): one scene, and when there are
    /// primitives one node with one mesh.
    fn json(self, bin_length: usize) -> Value {
        let mut document = json!({
            "asset": {
                "version": "2.0",
                "generator": format!("Meristem {}", env!("CARGO_PKG_VERSION")),
            },
            "scene": 0,
            "scenes": [{ "name": "Meristem plant" }],
        });
        if self.primitives.is_empty() {
            return document;
        }
        document["scenes"][0]["nodes"] = json!([0]);
        document["nodes"] = json!([{ "name": "plant", "mesh": 0 }]);
        document["meshes"] = json!([{ "name": "plant", "primitives": self.primitives }]);
        if self.morph_targets > 0 {
            document["meshes"][0]["weights"] = json!(vec![0.0; self.morph_targets]);
        }
        if let Some(animation) = self.animation {
            document["animations"] = json!([animation]);
        }
        document["materials"] = Value::Array(self.materials);
        if !self.images.is_empty() {
            let textures: Vec<Value> = (0..self.textures.len())
                .map(|i| json!({ "sampler": 0, "source": i }))
                .collect();
            document["images"] = Value::Array(self.images);
            document["textures"] = Value::Array(textures);
            document["samplers"] = json!([{
                "magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_LINEAR,
                "wrapS": REPEAT, "wrapT": REPEAT,
            }]);
        }
        document["accessors"] = Value::Array(self.accessors);
        document["bufferViews"] = Value::Array(self.buffer_views);
        document["buffers"] = json!([{ "byteLength": bin_length }]);
        document
    }
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
    fn texture_coordinates_and_embedded_textures_for_bark_and_two_sided_leaves() {
        let (mesh, skeleton) =
            crate::export::tests::built("#angle 30\naxiom: F[+F~l][-;{.f+f+f.}]@O(0.2)\n");
        let (document, bin) = parse(&write(&Scene::new(&mesh, &skeleton)));
        let primitives = document["meshes"][0]["primitives"].as_array().expect("p");
        let texcoord = &document["accessors"][primitives[0]["attributes"]["TEXCOORD_0"]
            .as_u64()
            .expect("TEXCOORD_0") as usize];
        assert_eq!(texcoord["type"], "VEC2");
        assert_eq!(texcoord["count"], mesh.vertex_count());
        let materials = document["materials"].as_array().expect("materials");
        let names: Vec<&str> = materials
            .iter()
            .filter_map(|m| m["name"].as_str())
            .collect();
        // The leaf `~l` drawn before any colour was chosen is leaf green (entry 5).
        assert_eq!(
            names,
            ["color_0", "color_0_plain", "color_1_leaf", "color_5_leaf"]
        );
        assert_eq!(materials[3]["alphaMode"], "MASK");
        assert_eq!(materials[3]["doubleSided"], true);
        assert!(materials[0]["pbrMetallicRoughness"]["baseColorTexture"].is_object());
        assert!(materials[1]["pbrMetallicRoughness"]
            .get("baseColorTexture")
            .is_none());
        // Two images (bark, leaf), each an exact copy of the shipped PNG in the binary chunk.
        let images = document["images"].as_array().expect("images");
        assert_eq!(images.len(), 2);
        for (image, png) in images.iter().zip([BARK_PNG, LEAF_PNG]) {
            assert_eq!(image["mimeType"], "image/png");
            let view = &document["bufferViews"][image["bufferView"].as_u64().unwrap() as usize];
            let at = view["byteOffset"].as_u64().unwrap() as usize;
            assert_eq!(at % 4, 0);
            assert_eq!(&bin[at..at + png.len()], png);
        }
        assert_eq!(document["samplers"][0]["wrapS"], REPEAT);
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
