//! The turtle against hand computations.

use super::*;
use crate::maths;
use crate::{derive, model, syntax};
use glam::DVec3;

fn run(src: &str) -> Skeleton {
    let (model, string) = model_and_string(src);
    interpret(&model, &string)
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-9
}

#[test]
fn f_plus_f_at_90_degrees_turns_left() {
    let s = run("#angle 90\naxiom: F+F");
    assert_eq!(s.segments.len(), 2);
    assert!(close(s.segments[0].end, DVec3::new(0.0, 1.0, 0.0)));
    assert!(close(s.end, DVec3::new(-1.0, 1.0, 0.0)), "{}", s.end);
}

#[test]
fn minus_turns_right_and_f_moves_without_drawing() {
    let s = run("#angle 90\naxiom: f-F");
    assert_eq!(s.segments.len(), 1);
    assert!(close(s.end, DVec3::new(1.0, 1.0, 0.0)), "{}", s.end);
}

#[test]
fn pitch_down_tips_the_heading_away_from_up() {
    // H = +Y, U = +Z: '&' by 90° heads to −Z; '^' heads to +Z.
    assert!(close(
        run("#angle 90\naxiom: &F").end,
        DVec3::new(0.0, 0.0, -1.0)
    ));
    assert!(close(
        run("#angle 90\naxiom: ^F").end,
        DVec3::new(0.0, 0.0, 1.0)
    ));
}

#[test]
fn roll_then_turn_leaves_the_plane() {
    // '/' by 90° rolls L (−X) to U (+Z); then '+' turns H towards the new L.
    assert!(close(
        run("#angle 90\naxiom: /+F").end,
        DVec3::new(0.0, 0.0, 1.0)
    ));
    assert!(close(
        run("#angle 90\naxiom: \\+F").end,
        DVec3::new(0.0, 0.0, -1.0)
    ));
}

#[test]
fn parameters_set_length_and_angle() {
    let s = run("#angle 10\naxiom: F(2)+(90)f(3)F");
    assert!(close(s.segments[0].end, DVec3::new(0.0, 2.0, 0.0)));
    assert!(close(s.end, DVec3::new(-4.0, 2.0, 0.0)), "{}", s.end);
}

#[test]
fn turn_around_and_branches_restore_the_state() {
    assert!(close(run("axiom: F|F").end, DVec3::ZERO));
    let s = run("#angle 90\naxiom: F[+F]F");
    assert!(close(s.segments[1].end, DVec3::new(-1.0, 1.0, 0.0)));
    assert!(close(s.end, DVec3::new(0.0, 2.0, 0.0)));
}

#[test]
fn the_frame_stays_orthonormal_after_many_rotations() {
    let s = run(&format!("#angle 13.7\naxiom: {}F", "+&/".repeat(2000)));
    let seg = &s.segments[0];
    let h = (seg.end - seg.start).normalize();
    assert!((seg.left.length() - 1.0).abs() < 1e-12 && (seg.up.length() - 1.0).abs() < 1e-12);
    assert!(
        h.dot(seg.left).abs() < 1e-12
            && h.dot(seg.up).abs() < 1e-12
            && seg.left.dot(seg.up).abs() < 1e-12
    );
}

#[test]
fn fig_1_37a_row_of_trees_ends_on_its_baseline() {
    // F(x) -> F(x*p)+F(x*h)--F(x*h)+F(x*q): the bump is symmetric, so the polyline ends on the line
    // of its first heading. With δ = 90° (the construction ABOP's text describes) it ends at
    // distance exactly 1; at the book's δ = 86° each step stretches it by 1 + 2h·cos 86°.
    let grammar = |angle: f64| {
        format!(
            "#define c 1\n#define p 0.3\n#define q c - p\n#define h (p*q)^0.5\n#angle {angle}\n#iterations 5\n\
             axiom: F(1)\nF(x) -> F(x*p)+F(x*h)--F(x*h)+F(x*q)"
        )
    };
    let s = run(&grammar(90.0));
    assert_eq!(s.segments.len(), 4usize.pow(5));
    assert!(close(s.segments[0].start, DVec3::ZERO));
    assert!(close(s.end, DVec3::new(0.0, 1.0, 0.0)), "{}", s.end);
    let s = run(&grammar(86.0));
    let h = (0.3f64 * 0.7).sqrt();
    let stretch = (1.0 + 2.0 * h * maths::cos(86f64.to_radians())).powi(5);
    assert!(close(s.end, DVec3::new(0.0, stretch, 0.0)), "{}", s.end);
}

#[test]
fn heading_turns_the_start_as_plus_would() {
    // `#heading 90` starts heading −X (left), as `+(90)` at the start would; −90 starts +X, and
    // the frame turns with it (U stays +Z, so `+` still turns left and the plant stays flat).
    let s = run("#angle 90\n#heading 90\naxiom: F+F");
    assert!(
        close(s.segments[0].end, DVec3::new(-1.0, 0.0, 0.0)),
        "{}",
        s.segments[0].end
    );
    assert!(close(s.end, DVec3::new(-1.0, -1.0, 0.0)), "{}", s.end);
    assert_eq!(s.end, run("#angle 90\naxiom: +F+F").end);
    let s = run("#heading -90\naxiom: F");
    assert!(close(s.end, DVec3::X), "{}", s.end);
    assert!(close(s.segments[0].up, DVec3::Z) && close(s.segments[0].left, DVec3::Y));
    assert!(s.is_flat());
    // The row of trees (ABOP 1.37a) heading right lies along +X, its trees above the line.
    let row = run("#angle 86\n#heading -90\n#iterations 2\naxiom: F(1)\nF(x) -> F(x*0.3)+F(x*0.46)--F(x*0.46)+F(x*0.7)");
    assert!(row.end.y.abs() < 1e-9 && row.end.x > 1.0, "{}", row.end);
    assert!(row.segments.iter().all(|s| s.end.y > -1e-9));
}

#[test]
fn tropism_bends_the_heading_towards_t_by_e_times_sin() {
    // H = +Y, T = +X, e = 0.5: |H × T| = 1, so after one F the heading turns 0.5 rad towards +X.
    let s = run("#tropism 1 0 0 0.5\naxiom: FF");
    let second = &s.segments[1];
    let h = (second.end - second.start).normalize();
    assert!(
        close(h, DVec3::new(maths::sin(0.5), maths::cos(0.5), 0.0)),
        "{h}"
    );
    // Again: |H × T| is now cos 0.5, so the next bend is 0.5·cos 0.5.
    let s = run("#tropism 1 0 0 0.5\naxiom: FFF");
    let third = &s.segments[2];
    let h = (third.end - third.start).normalize();
    let angle = 0.5 + 0.5 * maths::cos(0.5);
    assert!(
        close(h, DVec3::new(maths::sin(angle), maths::cos(angle), 0.0)),
        "{h}"
    );
    // A heading along T does not bend; @Ts(0) turns tropism off for a branch.
    let s = run("#tropism 0 1 0 0.9\naxiom: FF");
    assert!(close(s.end, DVec3::new(0.0, 2.0, 0.0)));
    let s = run("#tropism 1 0 0 0.5\naxiom: [@Ts(0)FF]FF");
    assert!(close(s.segments[1].end, DVec3::new(0.0, 2.0, 0.0)));
    // @Tp sets T for the branch only.
    let s = run("#tropism 1 0 0 0.5\naxiom: [@Tp(0,1,0)FF]FF");
    assert!(close(s.segments[1].end, DVec3::new(0.0, 2.0, 0.0)));
    assert!(s.segments[3].end.x > 0.4);
}

#[test]
fn dollar_rolls_l_horizontal() {
    // Heading +X after '-'(90) with a roll: '$' makes L horizontal and U point up.
    let s = run("#angle 90\naxiom: -/(30)$F?L(0,0,0)?U(0,0,0)");
    let left = DVec3::from_array(s.queries[0].value);
    let up = DVec3::from_array(s.queries[1].value);
    assert!(left.y.abs() < 1e-12, "{left}");
    assert!(up.y > 0.99, "{up}");
    assert!(close(s.end, DVec3::new(1.0, 0.0, 0.0)));
}

#[test]
fn widths_and_colours() {
    let s = run("#width 2\n#width_step 0.5\naxiom: F!F!(7)F'F;(5)F;F'(-2)F!(0)!F");
    let widths: Vec<f64> = s.segments.iter().map(|x| x.width).collect();
    let colours: Vec<u16> = s.segments.iter().map(|x| x.color).collect();
    assert_eq!(widths, [2.0, 1.5, 7.0, 7.0, 7.0, 7.0, 7.0, 0.0]);
    assert_eq!(colours, [0, 0, 0, 1, 5, 6, 4, 4]);
}

#[test]
fn polygons_record_f_and_dots_but_not_g() {
    let s = run("#angle 90\naxiom: {F+F+g.+F}F");
    assert_eq!(s.polygons.len(), 1);
    let points = &s.polygons[0].points;
    let expected = [
        DVec3::ZERO,
        DVec3::Y,
        DVec3::new(-1.0, 1.0, 0.0),
        DVec3::new(-1.0, 0.0, 0.0),
        DVec3::new(0.0, 0.0, 0.0),
    ];
    assert_eq!(points.len(), expected.len());
    for (p, e) in points.iter().zip(expected) {
        assert!(close(*p, e), "{p} vs {e}");
    }
    // Inside the polygon F traced the outline; only the F after '}' drew a segment.
    assert_eq!(s.segments.len(), 1);
}

#[test]
fn fig_1_25_bush_has_its_leaves() {
    let src = "#angle 22.5\n#iterations 3\naxiom: A\nA -> [&FL!A]/////'[&FL!A]///////'[&FL!A]\nF -> S/////F\nS -> FL\nL -> ['''^^{-f+f+f-|-f+f+f}]";
    let s = run(src);
    assert!(!s.polygons.is_empty());
    for p in &s.polygons {
        assert_eq!(
            p.points.len(),
            7,
            "a leaf is traced by six f moves from its base"
        );
        assert!(
            close(p.points[0], p.points[6]),
            "the outline returns to its base"
        );
        assert!(p.color >= 3, "leaves are coloured three steps on");
    }
}

#[test]
fn surfaces_spheres_and_move_to() {
    let s = run("axiom: ~l(2)F@O(0.5)@M(3,4,5)~p@O");
    assert_eq!(s.surfaces.len(), 2);
    assert_eq!(
        (s.surfaces[0].kind, s.surfaces[0].scale),
        (SurfaceKind::Leaf, DVec3::splat(2.0))
    );
    assert!(close(s.surfaces[1].origin, DVec3::new(3.0, 4.0, 5.0)));
    assert_eq!(s.spheres.len(), 2);
    assert!(close(s.spheres[0].center, DVec3::Y) && s.spheres[0].radius == 0.5);
    assert_eq!(s.spheres[1].radius_width, Some(0.5));
}

#[test]
fn axes_chain_segments_and_branches_start_new_axes() {
    let s = run("#angle 30\naxiom: FF[+F]F-F");
    let previous: Vec<Option<u32>> = s.segments.iter().map(|x| x.previous).collect();
    // F F [+F] F -F: the branch is its own axis; the main axis goes on after it, through the turn.
    assert_eq!(previous, [None, Some(0), None, Some(1), Some(3)]);
    let s = run("axiom: FfF@M(0,5,0)F");
    assert_eq!(
        s.segments.iter().map(|x| x.previous).collect::<Vec<_>>(),
        [None, None, None]
    );
}

#[test]
fn queries_read_the_turtle_where_they_stand() {
    let s = run("#angle 90\naxiom: F?P(0,0,0)+F?H(0,0,0)");
    assert_eq!(s.queries.len(), 2);
    assert_eq!(s.queries[0].module, 1);
    assert!(close(DVec3::from_array(s.queries[0].value), DVec3::Y));
    assert!(close(DVec3::from_array(s.queries[1].value), DVec3::NEG_X));
}

#[test]
fn smooth_marks_segments_between_gc_and_ge() {
    let s = run("axiom: F@GcFF@GeF");
    assert_eq!(
        s.segments.iter().map(|x| x.smooth).collect::<Vec<_>>(),
        [false, true, true, false]
    );
}

#[test]
fn color_sets_palette_entries_and_ramps() {
    let s = run("#color 2 255 0 0\n#color 20 22 0 0 0 100 200 255\naxiom: F");
    // One entry, in 0..=1.
    assert_eq!(s.color(2), [1.0, 0.0, 0.0]);
    // A ramp: the ends and the middle, linear in each component.
    assert_eq!(s.color(20), [0.0, 0.0, 0.0]);
    assert_eq!(s.color(22), [100.0 / 255.0, 200.0 / 255.0, 1.0]);
    assert_eq!(s.color(21), [50.0 / 255.0, 100.0 / 255.0, 127.5 / 255.0]);
    // Entries the ramp skipped over keep the colours they had by wrapping; untouched ones stay.
    let default = crate::model::DEFAULT_PALETTE;
    assert_eq!(s.color(17), default[17 % default.len()]);
    assert_eq!(s.color(0), default[0]);
    // Past the end, indices wrap modulo the palette's length (23 here).
    assert_eq!(s.color(23 + 2), [1.0, 0.0, 0.0]);
}

#[test]
fn organs_are_leaf_green_until_a_colour_is_chosen() {
    use crate::model::ORGAN_COLOR;
    // Nothing chosen: segments start at entry 0 (bark), the polygon, leaf and petal are green.
    let s = run("axiom: F{.f+f+f}~l~p");
    assert_eq!(s.segments[0].color, 0);
    assert_eq!(s.polygons[0].color, ORGAN_COLOR);
    assert!(s.surfaces.iter().all(|x| x.color == ORGAN_COLOR));
    // A choice on the path (`;`, `'`, even `;(0)`) is kept; a branch's choice ends with it.
    let s = run("axiom: [;(0){.f+f+f}]['{.f+f+f}]{.f+f+f}");
    let colors: Vec<_> = s.polygons.iter().map(|p| p.color).collect();
    assert_eq!(colors, [0, 1, ORGAN_COLOR]);
    // A grammar that sets entry 0 chose its starting colour for everything (imported colour maps).
    let s = run("#color 0 10 200 10\naxiom: F{.f+f+f}~l");
    assert_eq!((s.polygons[0].color, s.surfaces[0].color), (0, 0));
    // Setting another entry chooses nothing.
    let s = run("#color 8 240 200 40\naxiom: {.f+f+f}");
    assert_eq!(s.polygons[0].color, ORGAN_COLOR);
    assert_eq!(s.color(ORGAN_COLOR), crate::model::DEFAULT_PALETTE[5]);
}

#[test]
fn a_grammar_that_only_turns_with_plus_and_minus_is_flat() {
    assert!(run("#angle 30\naxiom: F[+F]F[-F]F").is_flat());
    assert!(run("#angle 90\naxiom: F+F{.f+f+f}").is_flat());
    assert!(!run("#angle 30\naxiom: F&F").is_flat());
    assert!(
        !run("#angle 30\naxiom: F/(45)+F").is_flat(),
        "a roll takes + out of the plane"
    );
    assert!(
        !run("axiom: A").is_flat(),
        "nothing drawn is not a flat drawing"
    );
}

#[test]
fn anchors_name_the_segment_a_state_grew_from() {
    // seg 0 F, seg 1 in [+F], seg 2 after `f` inside [fF], seg 3 continues seg 0; then a leaf,
    // a polygon and a sphere at seg 3's end; @M starts a new root (seg 4).
    let s = run("axiom: F[+F][fF]F~l{.f.f.}@O@M(5,0,0)F");
    let anchors: Vec<_> = s.segments.iter().map(|x| (x.previous, x.anchor)).collect();
    assert_eq!(
        anchors,
        vec![
            (None, None),
            (None, Some(0)),
            (None, Some(0)),
            (Some(0), Some(0)),
            (None, None),
        ]
    );
    assert_eq!(s.surfaces[0].anchor, Some(3));
    assert_eq!(s.polygons[0].anchor, Some(3));
    assert_eq!(s.spheres[0].anchor, Some(3));
    // A nested branch grows from the segment before its bracket, not from nothing.
    let s = run("axiom: F[[+F]-F]");
    assert_eq!(s.segments[1].anchor, Some(0));
    assert_eq!(s.segments[2].anchor, Some(0));
}

/// The model and the derived string of `src`.
pub(super) fn model_and_string(src: &str) -> (crate::model::Model, crate::model::LString) {
    let (file, diags) = syntax::parse(src);
    assert!(diags.is_empty(), "{diags:?}");
    let (model, diags) = model::resolve(&file);
    assert!(diags.is_empty(), "{diags:?}");
    let model = model.expect("model");
    let steps = model.settings.iterations;
    let derivation =
        derive::derive(&model, &derive::DeriveOptions::of_steps(steps)).expect("derives");
    (model, derivation.string)
}

/// Grammars the plain sketch loop draws: turns about every axis, `$`, `|`, colours, widths,
/// parameters, `#heading`, moves without drawing, zero-length steps.
const PLAIN_SKETCHES: &[&str] = &[
    "#angle 20\n#iterations 6\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF\n",
    "#angle 22.5\n#iterations 4\naxiom: A\nA -> [&FL!A]/////'[&FL!A]///////'[&FL!A]\nF -> S/////F\nS -> F L\nL -> ['''^^F]\n",
    "#angle 30\n#heading 15\n#iterations 3\naxiom: F\nF -> F[&F]f[^F]G[\\F]g[/F]|F$F;F;(3)F'(2)F\n",
    "#iterations 5\naxiom: A(1,10)\nA(l,w) -> !(w)F(l)[&(45)B(l*0.6,w*0.7)]/(137.5)A(l*0.9,w*0.7)\nB(l,w) -> !(w)F(l)[-(45)$C(l*0.6,w*0.7)]C(l*0.9,w*0.7)\nC(l,w) -> !(w)F(l)[+(45)$B(l*0.6,w*0.7)]B(l*0.9,w*0.7)\n",
    "#angle 90\naxiom: F(0)F(1)+(30)F(2)-F(-1);(5)F\n",
];

/// Grammars the plain loop leaves to the interpreter: polygons, leaves, spheres, tropism, `@M`.
const INTERPRETED_SKETCHES: &[&str] = &[
    "#angle 30\naxiom: F[+F{.-F.+F.}]F[~l]F@O(0.5)F\n",
    "#angle 30\n#tropism 0 -1 0 0.2\n#iterations 3\naxiom: X\nX -> F[+X][-X]FX\n",
    "#angle 30\naxiom: F@M(1,2,3)F+F\n",
];

/// The sketch's lines against the skeleton's segments: the same modules and colours, ends equal
/// up to `tolerance` (0: bit for bit).
fn assert_sketch_draws_the_skeleton(src: &str, tolerance: f32) {
    let (model, string) = model_and_string(src);
    let skeleton = interpret(&model, &string);
    let expected = crate::mesh::segment_lines(&skeleton);
    let sketch = sketch(&model, &string);
    assert_eq!(sketch.segments(), skeleton.segments.len(), "{src}");
    assert_eq!(sketch.lines.modules, expected.modules, "{src}");
    assert_eq!(sketch.lines.colors, expected.colors, "{src}");
    assert_eq!(sketch.lines.ends.len(), expected.ends.len(), "{src}");
    let size = expected.ends.iter().fold(1f32, |m, v| m.max(v.abs()));
    for (i, (a, b)) in sketch.lines.ends.iter().zip(&expected.ends).enumerate() {
        assert!(
            (a - b).abs() <= tolerance * size,
            "{src}: end value {i}: {a} against {b}"
        );
    }
    assert_eq!(sketch.is_flat(), skeleton.is_flat(), "{src}");
    assert_eq!(sketch.clamped(), skeleton.clamped, "{src}");
    let lines = crate::mesh::MeshBuffers {
        lines: sketch.lines.ends.clone(),
        ..Default::default()
    };
    assert_eq!(sketch.line_bounds(), lines.bounds(), "{src}");
}

/// `src` is drawn by the plain sketch loop when `plain` (else it is left to the interpreter), and
/// its sketch draws the skeleton's segments within `tolerance`.
fn assert_sketched_by(src: &str, plain: bool, tolerance: f32) {
    let (model, string) = model_and_string(src);
    let others = interpreter::empty_skeleton(&model.settings, false);
    assert_eq!(
        sketch::plain_sketch(&model, &string, &[], others).is_some(),
        plain,
        "should the plain loop draw {src}?"
    );
    assert_sketch_draws_the_skeleton(src, tolerance);
}

#[test]
fn the_plain_sketch_loop_draws_the_skeletons_segments() {
    for src in PLAIN_SKETCHES {
        // Frames are not re-orthonormalised after each turn: far below a pixel.
        assert_sketched_by(src, true, 1e-6);
    }
}

#[test]
fn other_sketches_are_drawn_by_the_interpreter_exactly() {
    for src in INTERPRETED_SKETCHES {
        assert_sketched_by(src, false, 0.0);
    }
}

#[test]
fn a_sketch_clamps_as_the_skeleton_does() {
    // Far past MAX_COORDINATE: the interpreter draws it, and the first clamped module agrees.
    for src in [
        "axiom: F(1)F(1e31)F(1)\n",
        "axiom: F!(1e40)F\n",
        "#angle 90\naxiom: F+F(1e300)F(1e300)F\n",
    ] {
        let (model, string) = model_and_string(src);
        let skeleton = interpret(&model, &string);
        assert!(skeleton.clamped.is_some(), "{src}");
        assert_sketch_draws_the_skeleton(src, 0.0);
    }
}

#[test]
fn the_skeleton_clamps_what_was_drawn_past_the_bounds_and_only_that() {
    // The interpreter checks each segment as it draws it and the skeleton clamps its segments
    // only when one needs it; polygons are clamped in any case. (source, first clamped module)
    for (src, first) in [
        ("axiom: F(1)F(2)\n", None),
        ("axiom: f(1e31)F(1)\n", Some(1)),
        ("axiom: F!(1e40)F\n", Some(2)),
        ("axiom: F(1){.f(1e31).}\n", Some(1)),
    ] {
        let (model, string) = model_and_string(src);
        let skeleton = interpret(&model, &string);
        assert_eq!(skeleton.clamped, first, "{src}");
        let mut again = skeleton.clone();
        again.clamp_to_finite();
        assert_eq!(
            again.segments, skeleton.segments,
            "{src}: nothing left to clamp"
        );
        assert_eq!(
            again.polygons, skeleton.polygons,
            "{src}: nothing left to clamp"
        );
    }
}

#[test]
fn a_flat_sketch_and_a_solid_one() {
    let (model, string) = model_and_string(PLAIN_SKETCHES[0]);
    assert!(sketch(&model, &string).is_flat());
    let (model, string) = model_and_string(PLAIN_SKETCHES[1]);
    assert!(!sketch(&model, &string).is_flat());
    let (model, string) = model_and_string("axiom: A\n");
    assert!(
        !sketch(&model, &string).is_flat(),
        "nothing drawn is not flat"
    );
}
