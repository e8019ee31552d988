//! VRML 2.0 (VRML97, `.wrl`): one `Shape` per colour index with a `Material`, all sharing one
//! `Coordinate` and one `Normal` node (`DEF` in the first shape, `USE` in the others), triangles
//! in an `IndexedFaceSet` (counter-clockwise, `solid`: leaves are already two-sided in the mesh),
//! a `Viewpoint` that frames the plant and a white `Background`. Colours are sRGB. A model too
//! large to mesh is written as an `IndexedLineSet` per colour index (emissive colour).

use super::scene::{coord_index, decimals_for, extent, number, srgb, Primitive, Scene, View};
use super::text::{xyz, xyz_lines};

/// The VRML text of `scene`.
pub fn write(scene: &Scene) -> String {
    let bounds = scene.bounds();
    let decimals = decimals_for(extent(bounds));
    let view = View::framing(bounds);
    let groups = scene.groups();
    let primitive = scene.primitive();
    let mut out = String::with_capacity(64 + scene.points().len() * 12);

    out.push_str("#VRML V2.0 utf8\n");
    out.push_str(&format!(
        "# Made with Meristem {}: {} {}, one shape per colour index.\n",
        env!("CARGO_PKG_VERSION"),
        groups.iter().map(|g| g.items.len()).sum::<usize>(),
        match primitive {
            Primitive::Triangles => "triangles",
            Primitive::Lines => "lines (too large to mesh)",
        }
    ));
    out.push_str("WorldInfo { title \"Meristem plant\" }\n");
    out.push_str("NavigationInfo { type [ \"EXAMINE\", \"ANY\" ] headlight TRUE }\n");
    out.push_str("Background { skyColor [ 1 1 1 ] }\n");
    out.push_str("Viewpoint {\n  position ");
    xyz(&mut out, view.eye.to_array(), decimals);
    out.push_str("\n  orientation ");
    let (axis, angle) = view.orientation();
    xyz(&mut out, axis.to_array(), 6);
    out.push(' ');
    number(&mut out, angle, 6);
    out.push_str("\n  fieldOfView ");
    number(&mut out, view.fov, 6);
    out.push_str("\n  description \"Whole plant\"\n}\n");

    for (k, group) in groups.iter().enumerate() {
        let [r, g, b] = srgb(group.color);
        out.push_str(&format!(
            "# colour index {}\nShape {{\n  appearance Appearance {{\n    material Material {{ ",
            group.index
        ));
        let color_field = match primitive {
            Primitive::Triangles => "diffuseColor",
            Primitive::Lines => "emissiveColor",
        };
        out.push_str(color_field);
        out.push(' ');
        xyz(&mut out, [r as f64, g as f64, b as f64], 4);
        out.push_str(" }\n  }\n");
        match primitive {
            Primitive::Triangles => out.push_str("  geometry IndexedFaceSet {\n"),
            Primitive::Lines => out.push_str("  geometry IndexedLineSet {\n"),
        }
        if k == 0 {
            out.push_str("    coord DEF Meristem_Points Coordinate { point [\n");
            xyz_lines(&mut out, scene.points(), decimals);
            out.push_str("    ] }\n");
            if primitive == Primitive::Triangles {
                out.push_str("    normal DEF Meristem_Normals Normal { vector [\n");
                xyz_lines(&mut out, &scene.mesh.normals, 4);
                out.push_str("    ] }\n");
            }
        } else {
            out.push_str("    coord USE Meristem_Points\n");
            if primitive == Primitive::Triangles {
                out.push_str("    normal USE Meristem_Normals\n");
            }
        }
        out.push_str("    coordIndex [\n");
        coord_index(&mut out, scene, &group.items, "");
        out.push_str("    ]\n  }\n}\n");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::tests::{assert_fallback_text, written_two_colour_plant};

    #[test]
    fn shapes_share_one_coordinate_node_and_index_it_in_range() {
        let (mesh, text) = written_two_colour_plant(
            write,
            "#VRML V2.0 utf8\n",
            &[
                ("Shape {", 2),
                ("DEF Meristem_Points", 1),
                ("USE Meristem_Points", 1),
                ("Viewpoint {", 1),
            ],
        );
        // Every triangle once, each index below the vertex count.
        let faces: Vec<&str> = text.lines().filter(|l| l.ends_with(" -1")).collect();
        assert_eq!(faces.len(), mesh.triangle_count());
        for face in faces {
            let corners: Vec<u32> = face
                .split_whitespace()
                .map(|w| w.parse().unwrap_or(0))
                .collect();
            assert_eq!(corners.len(), 4);
            assert!(corners[..3]
                .iter()
                .all(|&i| (i as usize) < mesh.vertex_count()));
        }
    }

    #[test]
    fn the_fallback_writes_line_sets() {
        assert_fallback_text(
            write,
            &["IndexedLineSet", "emissiveColor"],
            &["IndexedFaceSet"],
        );
    }
}
