//! One declared surface as the studio's surface editor shows it (`#surface X …`, `#patch X …`):
//! its patches tessellated exactly as the plant draws them (the mesh stage's own
//! [`tessellate`](crate::mesh::bezier::tessellate), at the turtle's origin in its own frame at
//! scale 1), its control points, where each `#patch` point is written, the frame's map from
//! written points to the turtle's frame, and, for a library shape, the text that writes it out
//! as `#patch` lines so that its points can be edited; and, when asked, the colours the plant
//! draws each patch with.

use super::{build::steps_and_time, BuildOptions};
use crate::derive::{derive, DeriveOptions};
use crate::diagnostics::Diagnostic;
use crate::mesh::bezier::tessellate;
use crate::model::{
    organ_patches, resolve, Model, SurfaceShape, DEFAULT_PALETTE, LIBRARY_PRECISION, ORGAN_COLOR,
};
use crate::syntax::{parse, Directive, SourceFile, Span};
use crate::turtle::{Surface, SurfaceKind};
use crate::vocabulary::{directive, DirectiveKind, FrameWord};
use glam::DVec3;
use std::sync::Arc;

/// Surface X of a grammar, in the turtle's frame at scale 1 (x along L, y along H, z along U).
#[derive(Clone, Debug)]
pub struct SurfacePreview {
    pub shape: Arc<SurfaceShape>,
    /// The affine map from written points to the turtle's frame, column-major 4 × 4.
    pub to_turtle: [f64; 16],
    /// The tessellated patches: positions and unit normals (x y z each), and triangles.
    pub positions: Vec<f32>,
    pub normals: Vec<f32>,
    pub indices: Vec<u32>,
    /// For a library shape: the changes (byte spans of the text, replacement) that write it out
    /// as `#patch` lines of the same shape and precision; empty otherwise.
    pub write_out: Vec<(Span, String)>,
    /// When asked: each patch's colour on its front and its back (r, g, b, linear, 0 to 1), as
    /// the plant draws it ([`plant_colours`]); empty otherwise.
    pub colors: Vec<[[f32; 3]; 2]>,
}

/// Surface `letter` of `source` (None when the text declares none that resolves), with its
/// colours when `colours` (which derives the plant: an editor dragging a point, which changes no
/// colour, asks without), and the text's diagnostics.
pub fn surface_preview(
    source: &str,
    letter: char,
    colours: bool,
) -> (Option<SurfacePreview>, Vec<Diagnostic>) {
    let (file, mut diagnostics) = parse(source);
    let (model, more) = resolve(&file);
    diagnostics.extend(more);
    let shape = model.as_ref().and_then(|m| {
        m.settings
            .surfaces
            .iter()
            .find(|s| s.letter == letter)
            .cloned()
    });
    let preview = shape.map(|shape| {
        let colors = match &model {
            Some(model) if colours => plant_colours(model, &shape),
            _ => Vec::new(),
        };
        let (positions, normals, indices) = mesh_of(&shape);
        let write_out = match shape.organ {
            Some(_) => write_out(source, &file, &shape),
            None => Vec::new(),
        };
        SurfacePreview {
            to_turtle: to_turtle(&shape),
            positions,
            normals,
            indices,
            write_out,
            colors,
            shape,
        }
    });
    (preview, diagnostics)
}

/// Each patch's colours, front and back, as the plant draws them: the patch's own, else the
/// turtle's colour at the plant's first `~X` (the grammar derived as a build derives it), else
/// what a `~X` drawn before any colour is chosen takes (the organs' leaf green).
fn plant_colours(model: &Model, shape: &SurfaceShape) -> Vec<[[f32; 3]; 2]> {
    let patches = 0..shape.patches.len();
    let own = patches
        .clone()
        .all(|k| shape.patch_color(k, false, 0) != 0 && shape.patch_color(k, true, 0) != 0);
    let turtle = if own {
        ORGAN_COLOR
    } else {
        turtle_colour(model, shape.letter)
    };
    let palette: &[[f32; 3]] = match model.settings.palette.as_slice() {
        [] => &DEFAULT_PALETTE,
        p => p,
    };
    patches
        .map(|k| {
            [false, true]
                .map(|back| palette[shape.patch_color(k, back, turtle) as usize % palette.len()])
        })
        .collect()
}

/// The colour index of the plant's first `~letter`; leaf green when the plant draws none or
/// cannot be derived.
fn turtle_colour(model: &Model, letter: char) -> u16 {
    let (steps, time) = steps_and_time(model, &BuildOptions::default());
    let Ok(derivation) = derive(
        model,
        &DeriveOptions {
            steps,
            seed: None,
            time,
        },
    ) else {
        return ORGAN_COLOR;
    };
    let skeleton = crate::turtle::interpret(model, derivation.turtle_string());
    let drawn = skeleton.surfaces.iter().find(|s| match s.kind {
        SurfaceKind::Declared(k) => skeleton
            .shapes
            .get(k as usize)
            .is_some_and(|x| x.letter == letter),
        _ => false,
    });
    drawn.map_or(ORGAN_COLOR, |s| s.color)
}

/// The surface drawn at the origin in the turtle's own frame (L = x, H = y, U = z), scale 1.
fn mesh_of(shape: &SurfaceShape) -> (Vec<f32>, Vec<f32>, Vec<u32>) {
    let at = Surface {
        kind: SurfaceKind::Declared(0),
        origin: DVec3::ZERO,
        heading: DVec3::Y,
        left: DVec3::X,
        up: DVec3::Z,
        scale: DVec3::ONE,
        color: 0,
        module: 0,
        anchor: None,
    };
    let (mut positions, mut normals, mut indices) = (Vec::new(), Vec::new(), Vec::new());
    for grid in tessellate(&at, shape) {
        let base = (positions.len() / 3) as u32;
        for (p, n) in grid.points.iter().zip(&grid.normals) {
            positions.extend(p.to_array().map(|v| v as f32));
            normals.extend(n.to_array().map(|v| v as f32));
        }
        for t in grid.triangles() {
            indices.extend(t.map(|k| base + k));
        }
    }
    (positions, normals, indices)
}

/// The frame's map from written points to the turtle's frame, column-major: the axes scaled by
/// scale / size as columns, then the translation that takes the contact point to the origin.
fn to_turtle(shape: &SurfaceShape) -> [f64; 16] {
    let frame = shape.frame;
    let axes = frame.axes().unwrap_or([DVec3::X, DVec3::Y, DVec3::Z]);
    let k = frame.scale / frame.size;
    // Row r of the linear part is axes[r] · k: column c holds (axes[0][c], axes[1][c], axes[2][c]) · k.
    let mut m = [0.0; 16];
    for c in 0..3 {
        for (r, axis) in axes.iter().enumerate() {
            m[4 * c + r] = axis[c] * k;
        }
    }
    let t = frame.place(DVec3::ZERO, &axes);
    m[12..15].copy_from_slice(&t.to_array());
    m[15] = 1.0;
    m
}

/// The changes that write a library shape out: its name taken from its `#surface` line (with
/// the library's precision written when the line gives none, so that it looks the same), and
/// one `#patch` line per patch after that line.
fn write_out(source: &str, file: &SourceFile, shape: &SurfaceShape) -> Vec<(Span, String)> {
    let Some(line) = file.directives.iter().find(|d| {
        d.kind == Some(DirectiveKind::Surface)
            && d.target
                .as_ref()
                .is_some_and(|(t, _)| t.chars().eq([shape.letter]))
    }) else {
        return Vec::new();
    };
    let words = words_after_target(line);
    let Some((_, organ)) = words.first() else {
        return Vec::new();
    };
    let precision = FrameWord::Precision.name();
    let mut out = Vec::new();
    // The name and the blank before it.
    let before = source[..organ.start].trim_end_matches([' ', '\t']).len();
    out.push((before..organ.end, String::new()));
    let mut added = String::new();
    if !words.iter().any(|(w, _)| w == precision) {
        added.push_str(&format!(
            " {precision} {LIBRARY_PRECISION} {LIBRARY_PRECISION}"
        ));
    }
    let patch = format!("#{}", directive(DirectiveKind::Patch).name);
    for p in organ_patches(shape.organ.unwrap_or(crate::vocabulary::Organ::Leaf)) {
        let points: Vec<String> = p.iter().map(|q| point_text(*q)).collect();
        added.push_str(&format!("\n{patch} {} {}", shape.letter, points.join(", ")));
    }
    let end = line.args_span.end;
    out.push((end..end, added));
    out
}

/// The words of a `#surface` line after its letter, with their byte spans.
fn words_after_target(d: &Directive) -> Vec<(String, Span)> {
    let skip = d.target.as_ref().map_or(0, |(t, _)| t.len());
    let args = d.args.as_str();
    let mut out = Vec::new();
    let mut at = skip.min(args.len());
    for word in args[at..].split([' ', '\t', ',']) {
        if !word.is_empty() {
            let start = d.args_span.start + at;
            out.push((word.to_string(), start..start + word.len()));
        }
        at += word.len() + 1;
    }
    out
}

/// A point as the studio's editor writes it: each number to 4 decimals, no trailing zeros.
fn point_text(p: DVec3) -> String {
    let number = |v: f64| {
        let r = (v * 1e4).round() / 1e4;
        if r == 0.0 {
            "0".to_string()
        } else {
            format!("{r}")
        }
    };
    format!("{} {} {}", number(p.x), number(p.y), number(p.z))
}

#[cfg(test)]
mod tests {
    use super::*;

    const PETAL: &str = "axiom: ~P\n#surface P petal\n";

    #[test]
    fn a_patch_surface_gives_its_mesh_points_and_spans() {
        let points: Vec<String> = (0..16).map(|k| format!("{} {} 0", k % 4, k / 4)).collect();
        let text = format!("axiom: ~A\n#patch A {}\n", points.join(", "));
        let (preview, diagnostics) = surface_preview(&text, 'A', false);
        assert!(
            !crate::diagnostics::has_errors(&diagnostics),
            "{diagnostics:?}"
        );
        let p = preview.expect("surface A");
        assert_eq!(p.shape.written.len(), 16);
        // The 6th point (row 1, column 1) is written "1 1 0", where its span says.
        assert_eq!(&text[p.shape.written[5].span.clone()], "1 1 0");
        // Default precision 5: 6 × 6 points, 5 × 5 quads of 2 triangles.
        assert_eq!(p.positions.len(), 36 * 3);
        assert_eq!(p.indices.len(), 50 * 3);
        // The default frame: the identity.
        let identity = [
            1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        ];
        assert_eq!(p.to_turtle, identity);
        assert!(p.write_out.is_empty());
        assert!(surface_preview(&text, 'B', false).0.is_none());
    }

    #[test]
    fn the_frame_maps_written_points_to_the_turtle() {
        let points: Vec<String> = (0..16).map(|k| format!("{} {} 2", k % 4, k / 4)).collect();
        let text = format!(
            "axiom: ~A\n#surface A contact 0 0 2 heading 0 0 1 up 0 -1 0 size 2\n#patch A {}\n",
            points.join(", ")
        );
        let p = surface_preview(&text, 'A', false).0.expect("surface A");
        let m = p.to_turtle;
        for (w, placed) in p.shape.written.iter().zip(p.shape.patches[0].iter()) {
            let [x, y, z] = w.value;
            let q = DVec3::new(
                m[0] * x + m[4] * y + m[8] * z + m[12],
                m[1] * x + m[5] * y + m[9] * z + m[13],
                m[2] * x + m[6] * y + m[10] * z + m[14],
            );
            assert!((q - *placed).length() < 1e-12, "{q} {placed}");
        }
    }

    #[test]
    fn colours_are_the_patches_own_else_the_turtle_s_at_the_first_x_else_leaf_green() {
        let points: Vec<String> = (0..16).map(|k| format!("{} {} 0", k % 4, k / 4)).collect();
        let patch = format!("#patch A {}", points.join(", "));
        let palette = "#color 2 255 0 0\n#color 3 0 0 255\n#color 5 0 255 0\n";
        let colours = |text: &str| surface_preview(text, 'A', true).0.expect("A").colors;
        let (red, blue, green) = ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]);
        // The turtle's colour where the plant draws the first ~A: ;(2) before it, ;(3) after.
        let text = format!("{palette}{patch}\n{patch} color 3\naxiom: F;(2)~A;(3)~A\n");
        assert_eq!(colours(&text), [[red, red], [blue, blue]]);
        // Derived: the first ~A appears at step 2, after ;(3).
        let text = format!("{palette}{patch}\n#iterations 2\naxiom: X\nX -> ;(3)Y\nY -> ~A\n");
        assert_eq!(colours(&text), [[blue, blue]]);
        // Never drawn, or drawn before any colour: leaf green (index 5 here).
        let text = format!("{palette}{patch}\naxiom: F\n");
        assert_eq!(colours(&text), [[green, green]]);
        // Without colours asked, none.
        assert!(surface_preview(&text, 'A', false)
            .0
            .expect("A")
            .colors
            .is_empty());
    }

    #[test]
    fn a_library_shape_is_written_out_as_the_same_surface() {
        let (preview, _) = surface_preview(PETAL, 'P', false);
        let p = preview.expect("the petal");
        let mut text = PETAL.to_string();
        for (span, insert) in p.write_out.iter().rev() {
            text.replace_range(span.clone(), insert);
        }
        assert!(
            text.contains("#surface P precision 8 8\n#patch P "),
            "{text}"
        );
        let (written, diagnostics) = surface_preview(&text, 'P', false);
        assert!(
            !crate::diagnostics::has_errors(&diagnostics),
            "{diagnostics:?}"
        );
        let w = written.expect("written out");
        assert!(w.shape.organ.is_none());
        assert_eq!(w.shape.precision, p.shape.precision);
        assert_eq!(w.positions.len(), p.positions.len());
        // The same surface, up to the 4 decimals written.
        let far = w
            .positions
            .iter()
            .zip(&p.positions)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f32::max);
        assert!(far < 1e-4, "{far}");
    }
}
