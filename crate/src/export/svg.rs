//! SVG (`.svg`) of the skeleton projected orthographically onto the X–Y plane (the plane flat
//! grammars draw in, seen from +Z; a 3D plant is flattened the same way, its z dropped). Y points
//! up in the model and down in SVG, so y is negated. Segments are stroked lines (`stroke-width`
//! = the segment's width in model units, round caps and joins; consecutive segments of one axis
//! with the same colour and width are one `path`), polygons and leaves are filled, spheres are
//! circles; colours are the palette's in sRGB. Everything is drawn in the order the turtle drew
//! it (by module), so later shapes cover earlier ones. The `viewBox` fits the drawing with a 2 %
//! margin; the picture is 800 px on its longer side. Zero-width segments are not drawn, as in
//! the mesh.
//!
//! A [`Look`] sets the picture as the studio's Picture settings do for a PNG: a background (a
//! rectangle over the whole picture; none by default, so the drawing is transparent), lines of
//! one width in the picture's pixels (the Lines mode) instead of the model's widths, the
//! picture's size in pixels (the drawing centred in it with the same margin), and a DPI that
//! gives the size in millimetres, so a 1748 × 2480 picture at 300 DPI prints as A5.

use super::scene::{decimals_for, number, srgb};
#[cfg(feature = "surfaces")]
use crate::mesh::bezier;
use crate::mesh::{polygon, surfaces, MeshBuffers};
use crate::turtle::{Skeleton, SurfaceKind};
use glam::{DVec2, DVec3};
use std::fmt::Write;

/// Longer side of the picture, in CSS pixels.
const PICTURE_SIZE: f64 = 800.0;

/// How the picture looks: the studio's Picture settings. The default is the plain drawing.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Look {
    /// The background's sRGB colour; `None` leaves the picture transparent.
    pub background: Option<[u8; 3]>,
    /// Every segment this wide, in pixels of the picture (the Lines mode); `None`: the model's
    /// widths.
    pub line_width: Option<f64>,
    /// The picture's width and height in pixels; `None`: 800 on the drawing's longer side.
    pub size: Option<(u32, u32)>,
    /// Dots per inch: the picture's `width` and `height` are then in millimetres.
    pub dpi: Option<f64>,
}

impl Look {
    /// The ranges the studio's Picture settings allow.
    pub const LINE_WIDTH: (f64, f64) = (0.5, 60.0);
    pub const SIDE: (u32, u32) = (16, 8192);
    pub const DPI: (f64, f64) = (10.0, 2400.0);

    /// The look, or a message naming the value out of range.
    pub fn checked(self) -> Result<Look, String> {
        // `what` must be within `(lo, hi)` (in `unit`, when it has one).
        let within = |value: Option<f64>, (lo, hi): (f64, f64), what: &str, unit: &str| match value
        {
            Some(v) if !(v.is_finite() && v >= lo && v <= hi) => {
                Err(format!("{what} must be from {lo} to {hi}{unit}, not {v}"))
            }
            _ => Ok(()),
        };
        within(
            self.line_width,
            Self::LINE_WIDTH,
            "the line width",
            " pixels",
        )?;
        if let Some((w, h)) = self.size {
            let (lo, hi) = Self::SIDE;
            if !(lo..=hi).contains(&w) || !(lo..=hi).contains(&h) {
                return Err(format!(
                    "the picture's width and height must be from {lo} to {hi} pixels, not {w} × {h}"
                ));
            }
        }
        within(self.dpi, Self::DPI, "the DPI", "")?;
        Ok(self)
    }

    /// The look of the settings as given (the CLI's flags, the boundary's `SvgLook`): the
    /// background by name ([`Look::parse_background`]), checked ([`Look::checked`]).
    pub fn read(
        background: Option<&str>,
        line_width: Option<f64>,
        size: Option<(u32, u32)>,
        dpi: Option<f64>,
    ) -> Result<Look, String> {
        let background = match background {
            Some(text) => Look::parse_background(text)?,
            None => None,
        };
        Look {
            background,
            line_width,
            size,
            dpi,
        }
        .checked()
    }

    /// A background by name: `#rrggbb`, `white`, or `none` / `transparent` (no background).
    pub fn parse_background(text: &str) -> Result<Option<[u8; 3]>, String> {
        let text = text.trim();
        match text.to_ascii_lowercase().as_str() {
            "none" | "transparent" => return Ok(None),
            "white" => return Ok(Some([255; 3])),
            _ => {}
        }
        let hex = text
            .strip_prefix('#')
            .filter(|h| h.len() == 6 && h.is_ascii());
        let channel =
            |k: usize| hex.and_then(|h| u8::from_str_radix(&h[2 * k..2 * k + 2], 16).ok());
        match (channel(0), channel(1), channel(2)) {
            (Some(r), Some(g), Some(b)) => Ok(Some([r, g, b])),
            _ => Err(format!(
                "unknown background '{text}'; give #rrggbb, white, or none"
            )),
        }
    }
}

/// Where the drawing sits: the `viewBox` (model units, y down) and the `width` and `height`
/// attributes.
struct Frame {
    min: DVec2,
    size: DVec2,
    /// The picture's size in pixels.
    pixels: DVec2,
    width: String,
    height: String,
    /// A segment's stroke in model units when the look fixes it in pixels.
    line_width: Option<f64>,
}

impl Frame {
    /// The frame of `shapes` in `look`; with a line width in pixels, the lines' own widths are
    /// left out of the extent (their stroke is added as pixels).
    fn new(shapes: &[Shape], look: &Look) -> Frame {
        let (min, max) =
            extent_of(shapes, look.line_width.is_none()).unwrap_or((DVec2::ZERO, DVec2::ONE));
        let content = (max - min).max(DVec2::splat(1e-9));
        if look.size.is_none() && look.line_width.is_none() {
            // The plain drawing: a 2 % margin, 800 px on the longer side.
            let margin = content.max_element() * 0.02;
            let size = content + DVec2::splat(2.0 * margin);
            let pixels = size * (PICTURE_SIZE / size.max_element());
            return Frame {
                min: min - DVec2::splat(margin),
                size,
                pixels,
                width: length(pixels.x, look.dpi),
                height: length(pixels.y, look.dpi),
                line_width: None,
            };
        }
        // In pixels: the picture, and a margin of 2 % of its longer side plus half a line.
        let pixels = match look.size {
            Some((w, h)) => DVec2::new(w as f64, h as f64),
            None => content * (PICTURE_SIZE / content.max_element()),
        };
        let margin = 0.02 * pixels.max_element() + look.line_width.unwrap_or(0.0) * 0.5;
        let room = (pixels - DVec2::splat(2.0 * margin)).max(DVec2::splat(1.0));
        let scale = (room / content).min_element(); // pixels per model unit
        let size = pixels / scale;
        Frame {
            min: (min + max) * 0.5 - size * 0.5,
            size,
            pixels,
            width: length(pixels.x, look.dpi),
            height: length(pixels.y, look.dpi),
            line_width: look.line_width.map(|w| w / scale),
        }
    }
}

/// A picture's side: pixels, or millimetres at `dpi`.
fn length(pixels: f64, dpi: Option<f64>) -> String {
    let mut out = String::new();
    match dpi {
        Some(dpi) => {
            number(&mut out, pixels / dpi * 25.4, 2);
            out.push_str("mm");
        }
        None => number(&mut out, pixels, 1),
    }
    out
}

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
            SurfaceKind::Declared(k) => {
                // Each patch filled within its outline (its grid's border).
                #[cfg(feature = "surfaces")]
                if let Some(shape) = skeleton.shapes.get(k as usize) {
                    for (k, grid) in bezier::tessellate(s, shape).iter().enumerate() {
                        fill(
                            grid_border(grid),
                            shape.patch_color(k, false, s.color),
                            s.module,
                        );
                    }
                }
                let _ = k;
                continue;
            }
        };
        fill(surfaces::outline_of(kind, s), s.color, s.module);
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

#[cfg(feature = "surfaces")]
/// The border of a patch's grid, once around: its first row, last column, last row backwards
/// and first column backwards.
fn grid_border(grid: &bezier::Grid) -> Vec<DVec3> {
    let (rows, cols) = (grid.rows, grid.cols);
    let at = |i: usize, j: usize| grid.points[i * cols + j];
    let mut border: Vec<DVec3> = (0..cols).map(|j| at(0, j)).collect();
    border.extend((1..rows).map(|i| at(i, cols - 1)));
    border.extend((0..cols - 1).rev().map(|j| at(rows - 1, j)));
    border.extend((1..rows - 1).rev().map(|i| at(i, 0)));
    border
}

/// The box around the shapes, circles included, and the lines' strokes when `strokes`:
/// (min, max).
fn extent_of(shapes: &[Shape], strokes: bool) -> Option<(DVec2, DVec2)> {
    let mut min = DVec2::INFINITY;
    let mut max = DVec2::NEG_INFINITY;
    let mut grow = |p: DVec2, r: f64| {
        min = min.min(p - DVec2::splat(r));
        max = max.max(p + DVec2::splat(r));
    };
    for shape in shapes {
        match shape {
            Shape::Line(a, b, w, _) => {
                let half = if strokes { w * 0.5 } else { 0.0 };
                grow(*a, half);
                grow(*b, half);
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

/// The SVG text of the skeleton (the mesh gives the width unit): the plain drawing.
pub fn write(mesh: &MeshBuffers, skeleton: &Skeleton) -> String {
    write_with(mesh, skeleton, &Look::default())
}

/// The SVG text of the skeleton in `look` (checked by [`Look::checked`]).
pub fn write_with(mesh: &MeshBuffers, skeleton: &Skeleton, look: &Look) -> String {
    write_framed(mesh, skeleton, None, look)
}

/// [`write_with`], framed on the drawing of `framing` when given (the frames of a growing plant,
/// each framed on the whole plant) rather than on the skeleton's own.
pub fn write_framed(
    mesh: &MeshBuffers,
    skeleton: &Skeleton,
    framing: Option<&Skeleton>,
    look: &Look,
) -> String {
    let (shapes, frame) = framed_shapes(mesh, skeleton, framing, look);
    let decimals = decimals_for(frame.size.max_element()).saturating_sub(2);

    let mut out = String::with_capacity(256 + shapes.len() * 48);
    header(&mut out, &frame, decimals);
    if let Some([r, g, b]) = look.background {
        // A rectangle over the whole viewBox, under the drawing.
        out.push_str("<rect");
        let (min, size) = (frame.min, frame.size);
        for (name, v) in [
            ("x", min.x),
            ("y", min.y),
            ("width", size.x),
            ("height", size.y),
        ] {
            write!(out, " {name}=\"").ok();
            number(&mut out, v, decimals);
            out.push('"');
        }
        writeln!(out, " fill=\"#{r:02x}{g:02x}{b:02x}\"/>").ok();
    }
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

/// The shapes of `skeleton` and the frame they are drawn in (see [`write_framed`]), the lines'
/// widths those of the look when it fixes them.
fn framed_shapes(
    mesh: &MeshBuffers,
    skeleton: &Skeleton,
    framing: Option<&Skeleton>,
    look: &Look,
) -> (Vec<Shape>, Frame) {
    let mut shapes = shapes(skeleton, mesh.width_unit);
    let frame = match framing {
        Some(whole) => Frame::new(&self::shapes(whole, mesh.width_unit), look),
        None => Frame::new(&shapes, look),
    };
    if let Some(width) = frame.line_width {
        for shape in &mut shapes {
            if let Shape::Line(_, _, w, _) = shape {
                *w = width;
            }
        }
    }
    (shapes, frame)
}

/// A shape of a [`Flat`] picture, in its pixels (x right, y down).
#[derive(Clone, Debug, PartialEq)]
pub enum FlatShape {
    /// A stroke with round caps: start, end, width.
    Line(DVec2, DVec2, f64),
    /// A filled outline.
    Fill(Vec<DVec2>),
    /// A filled circle: centre, radius.
    Circle(DVec2, f64),
}

/// The picture [`write_framed`] writes, as its shapes in its pixels: what a raster of the same
/// picture fills (the command line's PNG frames of the growth).
#[derive(Clone, Debug, PartialEq)]
pub struct Flat {
    pub width: u32,
    pub height: u32,
    /// The background's sRGB colour; `None`: transparent.
    pub background: Option<[u8; 3]>,
    /// Each shape and its sRGB colour, in drawing order.
    pub shapes: Vec<(FlatShape, [u8; 3])>,
}

/// [`write_framed`]'s picture as a [`Flat`].
pub fn flat_framed(
    mesh: &MeshBuffers,
    skeleton: &Skeleton,
    framing: Option<&Skeleton>,
    look: &Look,
) -> Flat {
    let (shapes, frame) = framed_shapes(mesh, skeleton, framing, look);
    let scale = frame.pixels.x / frame.size.x; // (the same both ways)
    let at = |p: &DVec2| (*p - frame.min) * scale;
    let colour = |index: u16| srgb(skeleton.color(index)).map(|c| (c * 255.0).round() as u8);
    let shapes = shapes
        .iter()
        .map(|shape| match shape {
            Shape::Line(a, b, w, c) => (FlatShape::Line(at(a), at(b), w * scale), colour(*c)),
            Shape::Fill(points, c) => {
                (FlatShape::Fill(points.iter().map(at).collect()), colour(*c))
            }
            Shape::Circle(centre, r, c) => (FlatShape::Circle(at(centre), r * scale), colour(*c)),
        })
        .collect();
    Flat {
        width: frame.pixels.x.round().max(1.0) as u32,
        height: frame.pixels.y.round().max(1.0) as u32,
        background: look.background,
        shapes,
    }
}

/// The XML declaration, the `svg` element (its `viewBox` and size from `frame`), its title and
/// description.
fn header(out: &mut String, frame: &Frame, decimals: usize) {
    out.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    out.push_str("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"");
    let (min, size) = (frame.min, frame.size);
    for (k, v) in [min.x, min.y, size.x, size.y].into_iter().enumerate() {
        if k > 0 {
            out.push(' ');
        }
        number(out, v, decimals);
    }
    write!(
        out,
        "\" width=\"{}\" height=\"{}\"",
        frame.width, frame.height
    )
    .ok();
    out.push_str(">\n<title>Meristem plant</title>\n");
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

    /// The `viewBox` and the `width` and `height` attributes of an SVG's text.
    fn frame_of(text: &str) -> ([f64; 4], String, String) {
        let attribute = |name: &str| {
            let start = text
                .find(&format!(" {name}=\""))
                .map(|i| i + name.len() + 3);
            text[start.unwrap_or(0)..]
                .split('"')
                .next()
                .unwrap_or("")
                .to_string()
        };
        let fields: Vec<f64> = attribute("viewBox")
            .split(' ')
            .map(|v| v.parse().unwrap_or(f64::NAN))
            .collect();
        (
            [fields[0], fields[1], fields[2], fields[3]],
            attribute("width"),
            attribute("height"),
        )
    }

    #[test]
    fn a_background_covers_the_whole_picture_under_the_drawing() {
        let (mesh, skeleton) = built("#angle 90\naxiom: F+F\n");
        let look = Look {
            background: Some([255, 255, 255]),
            ..Look::default()
        };
        let text = write_with(&mesh, &skeleton, &look);
        let ([x, y, w, h], ..) = frame_of(&text);
        let rect =
            format!("<rect x=\"{x}\" y=\"{y}\" width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>");
        assert!(text.contains(&rect), "{text}");
        assert!(text.find("<rect").unwrap() < text.find("<path").unwrap());
        // The plain drawing has none, and is otherwise the same.
        let plain = write(&mesh, &skeleton);
        assert!(!plain.contains("<rect"));
        assert_eq!(text.replace(&format!("{rect}\n"), ""), plain);
    }

    #[test]
    fn lines_of_a_width_in_pixels_fill_a_picture_of_a_size() {
        // A 1 × 1 square outline (its own widths 30 units) in a 100 × 200 picture with 5 px lines.
        let (mesh, skeleton) = built("#angle 90\n#width 30\naxiom: F+F+F+F\n");
        let look = Look {
            line_width: Some(5.0),
            size: Some((100, 200)),
            ..Look::default()
        };
        let text = write_with(&mesh, &skeleton, &look);
        let ([x, y, w, h], width, height) = frame_of(&text);
        assert_eq!((width.as_str(), height.as_str()), ("100", "200"));
        assert!(
            (h / w - 2.0).abs() < 1e-3,
            "the picture's aspect: {w} × {h}"
        );
        // The square is centred, with a margin of 2 % of 200 px plus half a line on each side.
        let per_pixel = w / 100.0;
        assert!((w - (1.0 + 2.0 * 6.5 * per_pixel)).abs() < 1e-3, "{text}");
        assert!((x + w / 2.0 + 0.5).abs() < 1e-3 && (y + h / 2.0 + 0.5).abs() < 1e-3);
        let stroke = text
            .split("stroke-width=\"")
            .nth(1)
            .unwrap()
            .split('"')
            .next()
            .unwrap();
        let stroke: f64 = stroke.parse().unwrap();
        assert!(
            (stroke / per_pixel - 5.0).abs() < 0.05,
            "{stroke} units = {} px",
            stroke / per_pixel
        );
    }

    #[test]
    fn a_dpi_gives_the_size_in_millimetres() {
        let (mesh, skeleton) = built("axiom: F\n");
        let look = Look {
            size: Some((1748, 2480)),
            dpi: Some(300.0),
            ..Look::default()
        };
        let (_, width, height) = frame_of(&write_with(&mesh, &skeleton, &look));
        assert_eq!(
            (width.as_str(), height.as_str()),
            ("148mm", "209.97mm"),
            "A5 at 300 DPI"
        );
    }

    #[test]
    fn a_look_out_of_range_is_refused_by_name() {
        let refused = |look: Look| look.checked().unwrap_err();
        assert!(refused(Look {
            line_width: Some(0.0),
            ..Look::default()
        })
        .contains("line width"));
        assert!(refused(Look {
            line_width: Some(f64::NAN),
            ..Look::default()
        })
        .contains("line width"));
        assert!(refused(Look {
            size: Some((10, 300)),
            ..Look::default()
        })
        .contains("10 × 300"));
        assert!(refused(Look {
            dpi: Some(1e9),
            ..Look::default()
        })
        .contains("DPI"));
        assert!(Look {
            line_width: Some(60.0),
            size: Some((8192, 16)),
            dpi: Some(10.0),
            ..Look::default()
        }
        .checked()
        .is_ok());
        assert_eq!(Look::parse_background("white"), Ok(Some([255; 3])));
        assert_eq!(Look::parse_background("None"), Ok(None));
        assert_eq!(
            Look::parse_background("#1A2b3c"),
            Ok(Some([0x1a, 0x2b, 0x3c]))
        );
        for bad in ["#12345", "#12345g", "red", "#ééé", ""] {
            assert!(Look::parse_background(bad).is_err(), "{bad}");
        }
    }
}
