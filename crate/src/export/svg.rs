//! SVG (`.svg`) of the skeleton projected orthographically onto the X–Y plane (the plane flat
//! grammars draw in, seen from +Z; a 3D plant is flattened the same way, its z dropped). Y points
//! up in the model and down in SVG, so y is negated. Segments are stroked lines (`stroke-width`
//! = the segment's width in model units, round caps and joins; consecutive segments of one axis
//! with the same colour and width are one `path`), polygons and leaves are filled, spheres are
//! circles; colours are the palette's in sRGB. Everything is drawn in the order the turtle drew
//! it (by module), so later shapes cover earlier ones. The `viewBox` fits the drawing with a 2 %
//! margin; the picture is 800 px on its longer side. Zero-width segments are not drawn, as in
//! the mesh.

use super::scene::{decimals_for, number, srgb};
use crate::mesh::{polygon, surfaces, MeshBuffers};
use crate::turtle::{Skeleton, SurfaceKind};
use glam::{DVec2, DVec3};
use std::fmt::Write;

/// Longer side of the picture, in CSS pixels.
const PICTURE_SIZE: f64 = 800.0;

/// One thing to draw, in model units.
enum Shape {
    /// A stroked segment: (start, end, width, colour index).
    Line(DVec2, DVec2, f64, u16),
    /// A filled outline.
    Fill(Vec<DVec2>, u16),
    /// A filled circle: (centre, radius, colour index).
    Circle(DVec2, f64, u16),
}

/// The point on the drawing: x, and y negated (SVG's y points down).
fn project(p: DVec3) -> DVec2 {
    DVec2::new(p.x, -p.y)
}

/// The shapes of the skeleton in drawing order (by the module that drew them).
fn shapes(skeleton: &Skeleton, unit: f64) -> Vec<Shape> {
    let mut keyed: Vec<(u32, Shape)> = Vec::new();
    for s in &skeleton.segments {
        if s.width > 0.0 {
            let shape = Shape::Line(project(s.start), project(s.end), s.width * unit, s.color);
            keyed.push((s.module, shape));
        }
    }
    let mut fill = |points: Vec<DVec3>, color: u16, module: u32| {
        if !polygon::triangulate(&points).triangles.is_empty() {
            keyed.push((
                module,
                Shape::Fill(points.into_iter().map(project).collect(), color),
            ));
        }
    };
    for p in &skeleton.polygons {
        fill(p.points.clone(), p.color, p.module);
    }
    for s in &skeleton.surfaces {
        let kind = match s.kind {
            SurfaceKind::Leaf => surfaces::SurfaceKind::Leaf,
            SurfaceKind::Petal => surfaces::SurfaceKind::Petal,
        };
        fill(
            surfaces::place(kind, s.origin, s.heading, s.left, s.scale),
            s.color,
            s.module,
        );
    }
    for s in &skeleton.spheres {
        let radius = s.radius_width.map_or(s.radius, |w| w * unit);
        if radius > 0.0 && radius.is_finite() {
            keyed.push((s.module, Shape::Circle(project(s.center), radius, s.color)));
        }
    }
    // Stable: shapes of one module keep the order above.
    keyed.sort_by_key(|(module, _)| *module);
    keyed.into_iter().map(|(_, shape)| shape).collect()
}

/// The box around the shapes, strokes and circles included: (min, max).
fn extent_of(shapes: &[Shape]) -> Option<(DVec2, DVec2)> {
    let mut min = DVec2::INFINITY;
    let mut max = DVec2::NEG_INFINITY;
    let mut grow = |p: DVec2, r: f64| {
        min = min.min(p - DVec2::splat(r));
        max = max.max(p + DVec2::splat(r));
    };
    for shape in shapes {
        match shape {
            Shape::Line(a, b, w, _) => {
                grow(*a, w * 0.5);
                grow(*b, w * 0.5);
            }
            Shape::Fill(points, _) => points.iter().for_each(|p| grow(*p, 0.0)),
            Shape::Circle(c, r, _) => grow(*c, *r),
        }
    }
    (min.x <= max.x && min.is_finite() && max.is_finite()).then_some((min, max))
}

/// `#rrggbb` of a palette colour (sRGB).
fn hex(skeleton: &Skeleton, index: u16) -> String {
    let [r, g, b] = srgb(skeleton.color(index)).map(|c| (c * 255.0).round() as u8);
    format!("#{r:02x}{g:02x}{b:02x}")
}

/// The SVG text of the skeleton (the mesh gives the width unit).
pub fn write(mesh: &MeshBuffers, skeleton: &Skeleton) -> String {
    let shapes = shapes(skeleton, mesh.width_unit);
    let (min, max) = extent_of(&shapes).unwrap_or((DVec2::ZERO, DVec2::ONE));
    let size = (max - min).max(DVec2::splat(1e-9));
    let margin = size.max_element() * 0.02;
    let (min, size) = (
        min - DVec2::splat(margin),
        size + DVec2::splat(2.0 * margin),
    );
    let decimals = decimals_for(size.max_element()).saturating_sub(2);

    let mut out = String::with_capacity(256 + shapes.len() * 48);
    header(&mut out, min, size, decimals);
    out.push_str("<g stroke-linecap=\"round\" stroke-linejoin=\"round\">\n");
    let mut k = 0;
    while k < shapes.len() {
        match &shapes[k] {
            Shape::Line(..) => k = path(&mut out, skeleton, &shapes, k, decimals),
            Shape::Fill(points, color) => {
                out.push_str("<polygon points=\"");
                for (i, p) in points.iter().enumerate() {
                    if i > 0 {
                        out.push(' ');
                    }
                    pair(&mut out, *p, decimals);
                }
                writeln!(out, "\" fill=\"{}\"/>", hex(skeleton, *color)).ok();
            }
            Shape::Circle(center, radius, color) => {
                out.push_str("<circle cx=\"");
                number(&mut out, center.x, decimals);
                out.push_str("\" cy=\"");
                number(&mut out, center.y, decimals);
                out.push_str("\" r=\"");
                number(&mut out, *radius, decimals + 1);
                writeln!(out, "\" fill=\"{}\"/>", hex(skeleton, *color)).ok();
            }
        }
        k += 1;
    }
    out.push_str("</g>\n</svg>\n");
    out
}

/// The XML declaration, the `svg` element (its `viewBox` from `min` over `size`, the picture
/// [`PICTURE_SIZE`] on its longer side), its title and description.
fn header(out: &mut String, min: DVec2, size: DVec2, decimals: usize) {
    let scale = PICTURE_SIZE / size.max_element();
    out.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    out.push_str("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"");
    for (k, v) in [min.x, min.y, size.x, size.y].into_iter().enumerate() {
        if k > 0 {
            out.push(' ');
        }
        number(out, v, decimals);
    }
    out.push_str("\" width=\"");
    number(out, size.x * scale, 1);
    out.push_str("\" height=\"");
    number(out, size.y * scale, 1);
    out.push_str("\">\n<title>Meristem plant</title>\n");
    writeln!(
        out,
        "<desc>Made with Meristem {}: the plant projected onto the X-Y plane, Y up.</desc>",
        env!("CARGO_PKG_VERSION")
    )
    .ok();
}

/// One `path` for the line `shapes[k]` and the lines after it that continue it with the same
/// colour and width; returns the index of the last line it drew.
fn path(
    out: &mut String,
    skeleton: &Skeleton,
    shapes: &[Shape],
    mut k: usize,
    decimals: usize,
) -> usize {
    let Shape::Line(start, end, width, color) = &shapes[k] else {
        return k;
    };
    out.push_str("<path d=\"M");
    pair(out, *start, decimals);
    out.push('L');
    pair(out, *end, decimals);
    let mut last = *end;
    while let Some(Shape::Line(a, b, w, c)) = shapes.get(k + 1) {
        if *a != last || w != width || c != color {
            break;
        }
        out.push('L');
        pair(out, *b, decimals);
        last = *b;
        k += 1;
    }
    out.push_str("\" fill=\"none\" stroke=\"");
    out.push_str(&hex(skeleton, *color));
    out.push_str("\" stroke-width=\"");
    number(out, *width, decimals + 1);
    out.push_str("\"/>\n");
    k
}

/// `x,y` (path data and polygon points).
fn pair(out: &mut String, p: DVec2, decimals: usize) {
    number(out, p.x, decimals);
    out.push(',');
    number(out, p.y, decimals);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::tests::built;

    #[test]
    fn segments_that_continue_each_other_are_one_path() {
        let (mesh, skeleton) = built("#angle 90\naxiom: FF[+F]F\n");
        let text = write(&mesh, &skeleton);
        // The trunk F F and the branch +F, which starts where the trunk ends, are one path; the
        // last F starts back at the joint, so it is a second.
        assert_eq!(text.matches("<path ").count(), 2, "{text}");
        assert!(text.contains("d=\"M0,0L0,-1L0,-2L-1,-2\""), "{text}");
        assert!(text.contains("d=\"M0,-2L0,-3\""), "{text}");
        assert!(text.contains("stroke=\"#"));
    }

    #[test]
    fn polygons_are_filled_and_y_points_down() {
        let (mesh, skeleton) = built("#angle 90\naxiom: {F+F+F+F}\n");
        let text = write(&mesh, &skeleton);
        assert_eq!(text.matches("<polygon ").count(), 1);
        assert!(
            text.contains("points=\"0,0 0,-1 -1,-1 -1,0 0,0\""),
            "{text}"
        );
        assert!(!text.contains("<path "));
    }

    #[test]
    fn the_view_box_holds_the_strokes() {
        let (mesh, skeleton) = built("#width 30\naxiom: F\n");
        let text = write(&mesh, &skeleton);
        let start = text.find("viewBox=\"").map(|i| i + 9).unwrap_or(0);
        let fields: Vec<f64> = text[start..]
            .split('"')
            .next()
            .unwrap_or("")
            .split(' ')
            .map(|v| v.parse().unwrap_or(f64::NAN))
            .collect();
        let half_width = 30.0 * mesh.width_unit * 0.5;
        assert!(
            fields[0] <= -half_width && fields[0] + fields[2] >= half_width,
            "{fields:?}"
        );
        assert!(fields[1] <= -1.0 - half_width && fields[1] + fields[3] >= half_width);
    }
}
