//! L-Py's turtle commands that place the turtle by coordinates (`@LineTo`, `@LineRel`,
//! `@OLineTo`, `@OLineRel`, `@R`) and `@Frame`, against hand computations.

use super::tests::model_and_string;
use super::*;
use glam::DVec3;

fn run(src: &str) -> Skeleton {
    let (model, string) = model_and_string(src);
    interpret(&model, &string)
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-9
}

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

#[test]
fn line_to_draws_to_the_point_and_keeps_the_heading() {
    // L-Py's LineTo.lpy, in Meristem's axes: LineTo(0,0,3)[LineTo(0,1,4)]LineTo(0,0,5).
    let s = run("axiom: @LineTo(0,3,0)[@LineTo(1,4,0)]@LineTo(0,5,0)F(1)");
    let ends: Vec<DVec3> = s.segments.iter().map(|g| g.end).collect();
    assert_eq!(s.segments.len(), 4);
    assert!(close(ends[0], v(0.0, 3.0, 0.0)));
    assert!(close(s.segments[1].start, v(0.0, 3.0, 0.0)));
    assert!(close(ends[1], v(1.0, 4.0, 0.0)));
    assert!(close(ends[2], v(0.0, 5.0, 0.0)));
    // The heading is still +Y: F(1) goes on up from (0, 5, 0).
    assert!(close(ends[3], v(0.0, 6.0, 0.0)), "{}", ends[3]);
    // The branch's segment is drawn square to its own direction, and grows from the first.
    let branch = &s.segments[1];
    let direction = (branch.end - branch.start).normalize();
    assert!(branch.left.dot(direction).abs() < 1e-12 && branch.up.dot(direction).abs() < 1e-12);
    assert_eq!(branch.anchor, Some(0));
    assert_eq!(
        s.segments[2].previous,
        Some(0),
        "the axis goes on after the branch"
    );
}

#[test]
fn line_to_inside_a_turned_branch_still_reaches_its_point() {
    // LineTo.lpy's second axiom: [+(90)LineTo(0,1,4)]-(30)LineTo(0,0,5): the points are absolute.
    let s = run("axiom: @LineTo(0,3,0)[+(90)@LineTo(1,4,0)]-(30)@LineTo(0,5,0)");
    assert!(close(s.segments[1].end, v(1.0, 4.0, 0.0)));
    assert!(close(s.segments[2].end, v(0.0, 5.0, 0.0)));
}

#[test]
fn line_rel_moves_by_the_vector_and_the_o_forms_turn_along_the_line() {
    let s = run("axiom: F(1)@LineRel(1,0,0)F(1)");
    assert!(close(s.segments[1].end, v(1.0, 1.0, 0.0)));
    assert!(
        close(s.end, v(1.0, 2.0, 0.0)),
        "LineRel keeps H = +Y: {}",
        s.end
    );
    let s = run("axiom: F(1)@OLineRel(2,0,0)F(1)");
    assert!(
        close(s.end, v(3.0, 1.0, 0.0)),
        "OLineRel turns H to +X: {}",
        s.end
    );
    let s = run("axiom: @OLineTo(0,0,4)F(1)");
    assert!(close(s.end, v(0.0, 0.0, 5.0)), "{}", s.end);
    // Straight back: H turns about U by 180°, so L turns too and U stays.
    let s = run("axiom: F(1)@OLineRel(0,-3,0)F(1)?U(0,0,0)");
    assert!(close(s.end, v(0.0, -3.0, 0.0)), "{}", s.end);
    assert_eq!(s.queries.last().map(|q| q.value), Some([0.0, 0.0, 1.0]));
}

#[test]
fn a_fourth_parameter_sets_the_width_after_the_line_and_a_polygon_takes_its_end() {
    let s = run("#width 2\naxiom: @LineTo(0,1,0,0.5)F(1)");
    assert_eq!((s.segments[0].width, s.segments[1].width), (2.0, 0.5));
    let s = run("axiom: {@LineTo(1,0,0)@LineTo(1,1,0)}");
    assert!(s.segments.is_empty());
    assert_eq!(s.polygons.len(), 1);
    let points = &s.polygons[0].points;
    assert_eq!(points.len(), 3);
    assert!(close(points[1], v(1.0, 0.0, 0.0)) && close(points[2], v(1.0, 1.0, 0.0)));
}

#[test]
fn set_heading_takes_the_heading_and_the_up_vector_made_square() {
    // H = +X, U = +Y: L = U × H = −Z.
    let s = run("axiom: @R(1,0,0,0,1,0)F(2)?L(0,0,0)?U(0,0,0)");
    assert!(close(s.end, v(2.0, 0.0, 0.0)), "{}", s.end);
    assert_eq!(s.queries[0].value, [0.0, 0.0, -1.0]);
    assert_eq!(s.queries[1].value, [0.0, 1.0, 0.0]);
    // An up vector square to H is kept, only made unit: (1,1,0) with H = +Z is U = (1,1,0)/√2.
    let s = run("axiom: @R(0,0,3,1,1,0)?U(0,0,0)F(1)");
    let u = s.queries[0].value;
    let r = std::f64::consts::FRAC_1_SQRT_2;
    assert!(
        (u[0] - r).abs() < 1e-12 && (u[1] - r).abs() < 1e-12 && u[2].abs() < 1e-12,
        "{u:?}"
    );
    assert!(close(s.end, v(0.0, 0.0, 1.0)));
    // One not square to H is made square (PlantGL's setHead): (1,1,0) with H = +X is U = +Y.
    let s = run("axiom: @R(1,0,0,1,1,0)?U(0,0,0)");
    let u = s.queries[0].value;
    assert!(
        u[0].abs() < 1e-12 && (u[1] - 1.0).abs() < 1e-12 && u[2].abs() < 1e-12,
        "{u:?}"
    );
    // Without an up vector (or with one along H), the least turn: from H = +Y to +X about U.
    let s = run("axiom: @R(5,0,0)?U(0,0,0)F(1)");
    assert_eq!(s.queries[0].value, [0.0, 0.0, 1.0]);
    assert!(close(s.end, v(1.0, 0.0, 0.0)));
    let s = run("axiom: @R(0,2,0,0,1,0)F(1)");
    assert!(close(s.end, v(0.0, 1.0, 0.0)));
    // Nothing to point along: the frame stays.
    let s = run("axiom: @R(0,0,0)F(1)");
    assert!(close(s.end, v(0.0, 1.0, 0.0)));
}

#[test]
fn frame_draws_h_l_and_u_in_red_green_and_blue_and_the_turtle_stays() {
    let s = run("axiom: @Frame(2)F(1)");
    assert_eq!(s.segments.len(), 4);
    let arms: Vec<(DVec3, u16)> = s.segments[..3].iter().map(|g| (g.end, g.color)).collect();
    assert!(
        close(arms[0].0, v(0.0, 2.0, 0.0)) && arms[0].1 == 10,
        "H, red: {arms:?}"
    );
    assert!(
        close(arms[1].0, v(-2.0, 0.0, 0.0)) && arms[1].1 == 5,
        "L, green"
    );
    assert!(
        close(arms[2].0, v(0.0, 0.0, 2.0)) && arms[2].1 == 13,
        "U, blue"
    );
    assert!(close(s.end, v(0.0, 1.0, 0.0)));
    assert_eq!(
        s.segments[3].previous, None,
        "a frame is not part of the axis"
    );
    assert_eq!(s.segments[3].color, 0);
    // After a turn, the frame turns with the turtle (L-Py's rotation.lpy: Frame(2) /(60) Frame(2)).
    let s = run("#angle 90\naxiom: +@Frame(1)");
    assert!(close(s.segments[0].end, v(-1.0, 0.0, 0.0)));
    assert!(run("axiom: @Frame(0)@Frame(-1)").segments.is_empty());
}

#[test]
fn a_sketch_draws_the_same_lines_as_the_skeleton() {
    let src = "axiom: @Frame(1)@LineTo(0,3,0)[@OLineRel(1,1,0)F]@R(1,0,0)F";
    let s = run(src);
    let (model, string) = model_and_string(src);
    let sketch = sketch(&model, &string);
    assert_eq!(sketch.segments(), s.segments.len());
}
