//! OpenInventor 2.1 ASCII (`.iv`): one `Separator` with a `PerspectiveCamera` that frames the
//! plant, a `DirectionalLight`, `ShapeHints` (counter-clockwise, solid: leaves are two-sided in
//! the mesh already), one `Coordinate3` and one `Normal` (bound per vertex, indexed by
//! `coordIndex`) that every face set shares, then per colour index a `Material` (sRGB) and an
//! `IndexedFaceSet`. A model too large to mesh becomes `IndexedLineSet`s drawn in their base
//! colour.

use super::scene::{
    coord_index, decimals_for, extent, number, srgb, ColorGroup, Primitive, Scene, View,
};
use super::text::{xyz, xyz_lines};
use std::fmt::Write;

/// The Inventor text of `scene`.
pub fn write(scene: &Scene) -> String {
    let bounds = scene.bounds();
    let decimals = decimals_for(extent(bounds));
    let groups = scene.groups();
    let points = scene.points();
    let mut out = String::with_capacity(64 + points.len() * 12);

    out.push_str("#Inventor V2.1 ascii\n\n");
    writeln!(
        out,
        "# Made with Meristem {}: one Material and face set per colour index",
        env!("CARGO_PKG_VERSION")
    )
    .ok();
    out.push_str("Separator {\n");
    camera_and_light(&mut out, &View::framing(bounds), decimals);
    if !groups.is_empty() {
        shared_vertices(&mut out, scene, decimals);
        for group in &groups {
            shape(&mut out, scene, group);
        }
    }
    out.push_str("}\n");
    out
}

/// The `PerspectiveCamera` that frames the plant as `view` does, and a `DirectionalLight` along
/// the view.
fn camera_and_light(out: &mut String, view: &View, decimals: usize) {
    out.push_str("  PerspectiveCamera {\n    position ");
    xyz(out, view.eye.to_array(), decimals);
    let (axis, angle) = view.orientation();
    out.push_str("\n    orientation ");
    xyz(out, axis.to_array(), 6);
    out.push(' ');
    number(out, angle, 6);
    out.push_str("\n    nearDistance ");
    number(
        out,
        (view.distance - view.radius).max(view.distance * 0.01),
        decimals,
    );
    out.push_str("\n    farDistance ");
    number(out, view.distance + view.radius * 2.0, decimals);
    out.push_str("\n    focalDistance ");
    number(out, view.distance, decimals);
    out.push_str("\n    heightAngle ");
    number(out, view.fov, 6);
    out.push_str("\n  }\n  DirectionalLight {\n    direction ");
    xyz(out, view.direction().to_array(), 6);
    out.push_str("\n  }\n");
}

/// What every shape shares: `ShapeHints` (or, for lines, a `LightModel` of base colours), the
/// `Coordinate3` and, for triangles, the `Normal` bound per vertex.
fn shared_vertices(out: &mut String, scene: &Scene, decimals: usize) {
    let primitive = scene.primitive();
    match primitive {
        Primitive::Triangles => {
            out.push_str(
                "  ShapeHints {\n    vertexOrdering COUNTERCLOCKWISE\n    shapeType SOLID\n  }\n",
            );
        }
        Primitive::Lines => out.push_str("  LightModel {\n    model BASE_COLOR\n  }\n"),
    }
    out.push_str("  Coordinate3 {\n    point [\n");
    xyz_lines(out, scene.points(), decimals);
    out.push_str("    ]\n  }\n");
    if primitive == Primitive::Triangles {
        out.push_str("  Normal {\n    vector [\n");
        xyz_lines(out, &scene.mesh.normals, 4);
        out.push_str("    ]\n  }\n  NormalBinding {\n    value PER_VERTEX_INDEXED\n  }\n");
    }
}

/// The `Material` of a colour group and its `IndexedFaceSet` (or `IndexedLineSet`).
fn shape(out: &mut String, scene: &Scene, group: &ColorGroup) {
    let [r, g, b] = srgb(group.color);
    write!(
        out,
        "  # colour index {}\n  Material {{\n    diffuseColor ",
        group.index
    )
    .ok();
    xyz(out, [r as f64, g as f64, b as f64], 4);
    out.push_str("\n  }\n");
    match scene.primitive() {
        Primitive::Triangles => out.push_str("  IndexedFaceSet {\n    coordIndex [\n"),
        Primitive::Lines => out.push_str("  IndexedLineSet {\n    coordIndex [\n"),
    }
    coord_index(out, scene, &group.items, ",");
    out.push_str("    ]\n  }\n");
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::tests::{assert_fallback_text, written_two_colour_plant};

    #[test]
    fn shared_coordinates_and_a_face_set_per_colour_index() {
        let (mesh, text) = written_two_colour_plant(
            write,
            "#Inventor V2.1 ascii\n",
            &[("Coordinate3 {", 1), ("IndexedFaceSet {", 2)],
        );
        assert_eq!(text.matches('{').count(), text.matches('}').count());
        assert_eq!(
            text.lines().filter(|l| l.ends_with(" -1,")).count(),
            mesh.triangle_count()
        );
    }

    #[test]
    fn the_fallback_writes_line_sets() {
        assert_fallback_text(write, &["IndexedLineSet {"], &["IndexedFaceSet"]);
    }
}
