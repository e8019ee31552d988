//! POV-Ray 3.7 scene (`.pov`), ready to render: `#version 3.7`, `assumed_gamma 1` (the palette's
//! linear colours as they are), a white background, a camera that frames the plant in a picture
//! of any aspect ratio, a key light and a shadowless fill light, and the plant as one `mesh2`
//! with per-vertex normals and a `texture_list` holding one texture per colour index (each face
//! names its texture). POV-Ray is left-handed, so z is negated (the plant is not mirrored). A model
//! too large to mesh becomes cylinders as wide as its segments, with a declared texture per
//! colour index.
//!
//! Textures: the mesh2 carries `uv_vectors` (v flipped: POV-Ray's image rows run bottom up) and
//! each colour index gets a texture per material kind it has: bark triangles `uv_mapping` the
//! bark image (`bark.png`) as a pattern scaled to the colour (the vertex colour multiplies the
//! texture, as in the view), leaf triangles the leaf image (`leaf.png`), fully transparent outside
//! the leaf's alpha, spheres plain. The mesh is `double_illuminate`d so leaves are lit on both
//! sides. The images are not in the text: [`super::export`] returns them beside the `.pov` (the
//! command-line tool writes them next to it, the studio zips them with it).
//!
//! Render: `povray +Iplant.pov +Oplant.png +W800 +H600 +A0.3` (run it in the file's folder:
//! POV-Ray's default I/O restrictions allow the current directory).

use super::scene::{decimals_for, extent, number, Primitive, Scene, View};
use super::text::{triple, triple_lines};
use crate::mesh::{MATERIAL_BARK, MATERIAL_LEAF};
use glam::DVec3;
use std::fmt::Write;

/// The POV-Ray scene text of `scene`.
pub fn write(scene: &Scene) -> String {
    let bounds = scene.bounds();
    let decimals = decimals_for(extent(bounds));
    let view = View::framing(bounds);
    let groups = scene.groups();
    let mut out = String::with_capacity(64 + scene.points().len() * 14);

    out.push_str("#version 3.7;\n");
    writeln!(
        out,
        "// Made with Meristem {}. Render: povray +Iplant.pov +Oplant.png +W800 +H600 +A0.3",
        env!("CARGO_PKG_VERSION")
    )
    .ok();
    out.push_str("global_settings { assumed_gamma 1.0 }\n");
    out.push_str("background { color rgb <1, 1, 1> }\n\n");

    // The camera sees the plant's bounding sphere across the picture's smaller side.
    out.push_str("#declare Meristem_Target = ");
    point(&mut out, view.target, decimals);
    out.push_str(";\n#declare Meristem_Eye = ");
    point(&mut out, view.eye, decimals);
    out.push_str(";\n#declare Meristem_Aspect = image_width / image_height;\n");
    out.push_str("#declare Meristem_Half_Fov = radians(");
    number(&mut out, view.fov.to_degrees() * 0.5, 6);
    out.push_str(");\ncamera {\n  perspective\n  location Meristem_Eye\n  right x * Meristem_Aspect\n  up y\n");
    out.push_str("  angle degrees(2 * atan(tan(Meristem_Half_Fov) * max(1, Meristem_Aspect)))\n");
    out.push_str("  look_at Meristem_Target\n}\n");
    // A key light above and to the left of the camera, and a fill from the other side.
    let direction = view.direction();
    let right = direction.cross(DVec3::Y).normalize_or(DVec3::X);
    let up = right.cross(direction);
    let key = view.eye + (up * 0.8 - right * 0.5) * view.distance;
    let fill = view.eye + (right * 0.8 - up * 0.2) * view.distance;
    out.push_str("light_source { ");
    point(&mut out, key, decimals);
    out.push_str(" color rgb <1, 1, 1> }\n");
    out.push_str("light_source { ");
    point(&mut out, fill, decimals);
    out.push_str(" color rgb <0.35, 0.35, 0.35> shadowless }\n\n");

    if groups.is_empty() {
        out.push_str("// The plant draws nothing.\n");
        return out;
    }
    match scene.primitive() {
        Primitive::Triangles => mesh2(&mut out, scene, &groups, decimals),
        Primitive::Lines => cylinders(&mut out, scene, &groups, decimals),
    }
    out
}

fn mesh2(out: &mut String, scene: &Scene, groups: &[super::scene::ColorGroup], decimals: usize) {
    let mesh = scene.mesh;
    out.push_str("#declare Meristem_Plant = mesh2 {\n");
    writeln!(out, "  vertex_vectors {{\n    {},", mesh.vertex_count()).ok();
    vectors(out, &mesh.positions, decimals);
    writeln!(
        out,
        "  }}\n  normal_vectors {{\n    {},",
        mesh.vertex_count()
    )
    .ok();
    vectors(out, &mesh.normals, 4);
    writeln!(out, "  }}\n  uv_vectors {{\n    {},", mesh.vertex_count()).ok();
    for (k, uv) in mesh.uvs.chunks_exact(2).enumerate() {
        out.push_str(if k == 0 { "    <" } else { ",\n    <" });
        number(out, uv[0] as f64, 4);
        out.push_str(", ");
        number(out, 1.0 - uv[1] as f64, 4);
        out.push('>');
    }
    out.push('\n');
    let kinds = mesh.triangle_materials();
    let kind_of = |item: u32| kinds.get(item as usize).map_or(2, |&k| k as u32);
    // A texture per (colour index, material kind) present, in colour order.
    let mut textures: Vec<(usize, u32)> = Vec::new();
    for (g, group) in groups.iter().enumerate() {
        for kind in [MATERIAL_BARK, MATERIAL_LEAF, 2] {
            if group.items.iter().any(|&t| kind_of(t) == kind) {
                textures.push((g, kind));
            }
        }
    }
    writeln!(out, "  }}\n  texture_list {{\n    {},", textures.len()).ok();
    for &(g, kind) in &textures {
        let group = &groups[g];
        let mut colour = String::new();
        rgb(&mut colour, group.color);
        match kind {
            MATERIAL_BARK => write!(
                out,
                "    texture {{ uv_mapping pigment {{ image_pattern {{ png \"bark.png\" interpolate 2 }} \
                 color_map {{ [0 rgb 0] [1 rgb <{colour}>] }} }}"
            ),
            // POV-Ray's `image_pattern … use_alpha` is the image's transparency (0 where it is
            // opaque), so the leaf image shows below 0.5 and the cut-out is clear above it.
            MATERIAL_LEAF => write!(
                out,
                "    texture {{ uv_mapping pigment {{ image_pattern {{ png \"leaf.png\" interpolate 2 use_alpha }} \
                 pigment_map {{ [0.5 image_pattern {{ png \"leaf.png\" interpolate 2 }} \
                 color_map {{ [0 rgb 0] [1 rgb <{colour}>] }}] [0.5 rgbt 1] }} }}"
            ),
            _ => write!(out, "    texture {{ pigment {{ color rgb <{colour}> }}"),
        }
        .ok();
        writeln!(
            out,
            " finish {{ ambient 0.15 diffuse 0.85 }} }} // colour index {}",
            group.index
        )
        .ok();
    }
    writeln!(
        out,
        "  }}\n  face_indices {{\n    {},",
        mesh.triangle_count()
    )
    .ok();
    // Faces in colour order, each followed by its texture's place in the list.
    for (t, &(g, kind)) in textures.iter().enumerate() {
        for &item in &groups[g].items {
            if kind_of(item) != kind {
                continue;
            }
            let [a, b, c] = scene.corners(item);
            // Negating z reverses the winding; POV-Ray does not cull, but keep faces consistent.
            writeln!(out, "    <{a}, {c}, {b}>, {t},").ok();
        }
    }
    out.push_str("  }\n}\nobject { Meristem_Plant double_illuminate }\n");
}

/// The fallback's lines as cylinders as wide as their segments (line `i` is segment `i`), so
/// POV-Ray draws the tubes the mesh could not hold; each names its colour index's texture.
fn cylinders(
    out: &mut String,
    scene: &Scene,
    groups: &[super::scene::ColorGroup],
    decimals: usize,
) {
    let lines = &scene.mesh.lines;
    let unit = scene.mesh.width_unit;
    for group in groups {
        write!(
            out,
            "#declare Meristem_Color_{} = texture {{ pigment {{ color rgb <",
            group.index
        )
        .ok();
        rgb(out, group.color);
        out.push_str("> } finish { ambient 0.15 diffuse 0.85 } }\n");
    }
    for group in groups {
        for &item in &group.items {
            let at = |k: usize| {
                let i = 6 * item as usize + 3 * k;
                DVec3::new(lines[i] as f64, lines[i + 1] as f64, lines[i + 2] as f64)
            };
            let (a, b) = (at(0), at(1));
            let width = scene
                .skeleton
                .segments
                .get(item as usize)
                .map_or(1.0, |s| s.width);
            let radius = 0.5 * width * unit;
            if !(radius > 0.0 && (b - a).length() > 0.0) {
                continue;
            }
            out.push_str("cylinder { ");
            point(out, a, decimals);
            out.push_str(", ");
            point(out, b, decimals);
            out.push_str(", ");
            number(out, radius, decimals + 2);
            writeln!(out, " texture {{ Meristem_Color_{} }} }}", group.index).ok();
        }
    }
}

/// `<x, y, -z>`: a model point in POV-Ray's left-handed coordinates.
fn point(out: &mut String, p: DVec3, decimals: usize) {
    out.push('<');
    triple(out, [p.x, p.y, -p.z], decimals, ", ");
    out.push('>');
}

/// One `<x, y, -z>,` line per vector of a flat `f32` × 3 array.
fn vectors(out: &mut String, flat: &[f32], decimals: usize) {
    triple_lines(out, flat, "    ", |out, [x, y, z]| {
        point(out, DVec3::new(x, y, z), decimals)
    });
}

fn rgb(out: &mut String, color: [f32; 3]) {
    triple(out, color.map(f64::from), 4, ", ");
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::tests::{assert_fallback_text, written_two_colour_plant};

    #[test]
    fn one_mesh2_with_a_texture_per_colour_index_and_every_face() {
        let (mesh, text) = written_two_colour_plant(write, "#version 3.7;\n", &[("mesh2 {", 1)]);
        assert!(text.contains(&format!("vertex_vectors {{\n    {},", mesh.vertex_count())));
        assert!(text.contains("texture_list {\n    2,"));
        assert!(text.contains(&format!("face_indices {{\n    {},", mesh.triangle_count())));
        let faces = text.lines().filter(|l| l.ends_with(">, 1,")).count();
        assert!(faces > 0, "faces of the second texture");
        assert!(text.contains("camera {") && text.contains("light_source {"));
    }

    #[test]
    fn the_fallback_writes_cylinders() {
        assert_fallback_text(write, &["cylinder {"], &["mesh2"]);
    }
}
