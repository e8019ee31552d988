//! Issue 47's models end to end: the gallery's open L-systems (`public/examples/open-*.lsys`)
//! built through the whole pipeline with their environmental programs answering `?E` between
//! steps, and what each plant does measured on its skeleton: a plant beside a wall grows away
//! from its shadow, a shaded branch stops, a sheared hedge stays in its box, space colonisation
//! fills its ball, and the middle tree of a row gets less light.

mod shared;

use glam::DVec3;
use meristem::diagnostics::Severity;
use meristem::pipeline::{build, Build, BuildOptions};
use meristem::turtle::Segment;
use shared::example;

/// `source` built with `iterations` steps (and `seed`, when given), with no error.
fn built(source: &str, iterations: u32, seed: Option<u64>) -> Build {
    let options = BuildOptions {
        iterations: Some(iterations),
        seed,
        ..BuildOptions::default()
    };
    let b = build(source, &options);
    let errors: Vec<_> = (b.diagnostics.iter())
        .filter(|d| d.severity == Severity::Error)
        .collect();
    assert!(errors.is_empty(), "{errors:?}");
    b
}

/// The segments drawn in colour `color`, or in any other colour (`!=`).
fn coloured(b: &Build, color: u16, same: bool) -> Vec<&Segment> {
    (b.plant.skeleton.segments.iter())
        .filter(|s| (s.color == color) == same)
        .collect()
}

fn midpoint(s: &Segment) -> DVec3 {
    0.5 * (s.start + s.end)
}

/// The smallest box around the segments' ends: (lowest corner, highest corner).
fn extent<'a>(segments: impl IntoIterator<Item = &'a Segment>) -> (DVec3, DVec3) {
    let mut lo = DVec3::splat(f64::INFINITY);
    let mut hi = DVec3::splat(f64::NEG_INFINITY);
    for s in segments {
        lo = lo.min(s.start).min(s.end);
        hi = hi.max(s.start).max(s.end);
    }
    (lo, hi)
}

/// The wall (colour 2) stands at x = −2 … −4, the plant at the origin. Without the wall the
/// same plant leans the other way (its 137.5° phyllotaxis puts more of it at x < 0), so the
/// asymmetry is the wall's shadow, not the grammar's.
#[test]
fn a_plant_beside_a_wall_grows_away_from_its_shadow() {
    let source = example("open-wall-shadow.lsys");
    let b = built(&source, 8, None);
    let plant = coloured(&b, 2, false);
    let wall = coloured(&b, 2, true);
    assert_eq!(wall.len(), 45, "three layers of 15 columns");
    let wall_side = plant.iter().filter(|s| midpoint(s).x < 0.0).count();
    let lit_side = plant.iter().filter(|s| midpoint(s).x > 0.0).count();
    // Measured: 6 internodes on the wall's side and 188 on the lit side (at 8 steps).
    assert!(lit_side >= 150, "{lit_side} on the lit side");
    assert!(
        lit_side >= 10 * wall_side.max(1),
        "{wall_side} on the wall's side, {lit_side} on the lit side"
    );
    // The same plant without the wall: both sides grow (measured 159 at x < 0, 92 at x > 0).
    let open = source.replacen(
        "axiom: [;(2) @M(-2, 0, -7) W(15)] [;(2) @M(-3, 0, -7) W(15)] [;(2) @M(-4, 0, -7) W(15)] ",
        "axiom: ",
        1,
    );
    assert_ne!(open, source);
    let free = built(&open, 8, None);
    let segments = &free.plant.skeleton.segments;
    let left = segments.iter().filter(|s| midpoint(s).x < 0.0).count();
    let right = segments.iter().filter(|s| midpoint(s).x > 0.0).count();
    assert!(left >= 100 && right >= 60, "{left} left, {right} right");
}

/// The lower branch (colour 3) grows one internode a step while lit; the crown above darkens it.
#[test]
fn a_shaded_branch_of_a_self_organising_tree_stops_growing() {
    let source = example("open-shaded-branch.lsys");
    let counts: Vec<(usize, usize)> = (4..=12)
        .map(|n| {
            let b = built(&source, n, None);
            (coloured(&b, 3, true).len(), coloured(&b, 3, false).len())
        })
        .collect();
    let (branch, crown): (Vec<usize>, Vec<usize>) = counts.iter().copied().unzip();
    // Measured: the branch 4, 5, … 9 internodes at steps 4 to 9, then 9 at steps 10, 11 and 12.
    assert_eq!(branch[0], 4, "{branch:?}");
    assert!(branch[5] > branch[0], "it grows while lit: {branch:?}");
    let last = branch[5..].to_vec();
    assert!(
        last.iter().all(|&b| b == last[0]),
        "it stops in the crown's shade: {branch:?}"
    );
    // …while the crown goes on growing, step after step (471 to 1983 internodes).
    assert!(crown.windows(2).all(|w| w[1] > w[0]), "{crown:?}");
    assert!(crown[8] > 3 * crown[5], "{crown:?}");
    // In the open (the crown's buds stop at a threshold that the branch always passes), the same
    // branch goes on: the stop is the crown's shadow, not its length.
    let lit = source.replace("B > ?E(e, x, y, z) : e >= T", "B > ?E(e, x, y, z) : e >= 0");
    assert_ne!(lit, source);
    assert_eq!(coloured(&built(&lit, 12, None), 3, true).len(), 12);
}

/// The hedge's box: |x| ≤ 2.6, 0 ≤ y ≤ 5.2, |z| ≤ 2.6 (`SIZE` in the grammar).
const SIZE: f64 = 2.6;

#[test]
fn a_sheared_hedge_leaves_no_segment_outside_its_box_and_fills_it() {
    let source = example("open-topiary-hedge.lsys");
    let b = built(&source, 40, None);
    let segments = &b.plant.skeleton.segments;
    assert!(segments.len() > 150, "{}", segments.len());
    let inside = |p: DVec3| {
        p.x.abs() <= SIZE + 1e-9 && p.z.abs() <= SIZE + 1e-9 && p.y >= -1e-9 && p.y <= 2.0 * SIZE
    };
    for s in segments {
        for k in 0..=10 {
            let p = s.start.lerp(s.end, k as f64 / 10.0);
            assert!(inside(p), "a segment reaches {p} outside the hedge's box");
        }
    }
    // It fills the box: measured x −2.54 … 2.47, y 0 … 5.07, z −2.53 … 2.47.
    let (lo, hi) = extent(segments);
    for axis in [0, 2] {
        assert!(
            lo[axis] < -0.85 * SIZE && hi[axis] > 0.85 * SIZE,
            "{lo} {hi}"
        );
    }
    assert!(hi.y > 0.9 * 2.0 * SIZE, "{hi}");
    // A gardener with a larger box (4) lets the same shrub grow past the first one's sides.
    let larger = source.replace("#define SIZE 2.6", "#define SIZE 4");
    let (lo, hi) = extent(&built(&larger, 40, None).plant.skeleton.segments);
    assert!(
        lo.x < -SIZE || hi.x > SIZE || hi.y > 2.0 * SIZE,
        "{lo} {hi}"
    );
}

/// The ball: centre (0, 7, 0), radius 4; the trunk reaches it at y = 3.
#[test]
fn space_colonisation_fills_its_ball_and_the_same_seed_gives_the_same_tree() {
    let source = example("open-space-colonisation.lsys");
    let b = built(&source, 20, None);
    let segments = &b.plant.skeleton.segments;
    let (lo, hi) = extent(segments);
    // Measured: x −3.77 … 3.68, y 0 … 10.89, z −3.56 … 3.58, of the ball's ±4 and 3 … 11.
    for axis in [0, 2] {
        assert!(lo[axis] < -3.0 && hi[axis] > 3.0, "{lo} {hi}");
    }
    assert!(hi.y > 10.0 && hi.y < 11.5, "{hi}");
    // Nothing grows far outside the ball (a bud steps 0.5 past a point it was drawn to at most).
    let centre = DVec3::new(0.0, 7.0, 0.0);
    for s in segments.iter().filter(|s| s.start.y >= 3.0) {
        assert!(s.end.distance(centre) < 4.0 + 1.0, "{}", s.end);
    }
    // The points are used up: a step more grows nothing (measured: 428 internodes from step 19).
    let more = built(&source, 21, None);
    assert_eq!(more.plant.skeleton.segments.len(), segments.len());
    let text = b.derived_text();
    // The same seed, the same tree; another seed, other points, another tree.
    assert_eq!(built(&source, 20, None).derived_text(), text);
    assert_ne!(built(&source, 20, Some(7)).derived_text(), text);
}

/// The internodes (`F`) of each plant of a stand, in the stand's order: its derived string
/// holds each plant as `[@M(x,y,z)…]`.
fn internodes_per_plant(b: &Build) -> Vec<usize> {
    let text = b.derived_text();
    text.split("[@M(")
        .skip(1)
        .map(|p| p.matches('F').count())
        .collect()
}

#[test]
fn the_middle_tree_of_a_row_gets_less_light_and_grows_less() {
    let source = example("open-row-competing.lsys");
    let b = built(&source, 11, None);
    let per = internodes_per_plant(&b);
    assert_eq!(per.len(), 3, "{per:?}");
    // Measured: [1196, 940, 1224].
    let outer = per[0].min(per[2]);
    assert!(
        (per[1] as f64) < 0.85 * outer as f64,
        "the middle tree {} against {outer}: {per:?}",
        per[1]
    );
    // Apart (spacing 8), the three trees grow alike: the middle one is at most a tenth behind.
    let apart = source.replace("#stand row 3 spacing 3", "#stand row 3 spacing 8");
    let per = internodes_per_plant(&built(&apart, 11, None));
    let (least, most) = (per.iter().min().unwrap(), per.iter().max().unwrap());
    // Measured: [1488, 1402, 1492].
    assert!(*least as f64 > 0.9 * *most as f64, "{per:?}");
}

#[test]
fn the_middle_tree_of_a_grid_is_the_most_shaded() {
    let per = internodes_per_plant(&built(&example("open-grid-competing.lsys"), 9, None));
    assert_eq!(per.len(), 9, "{per:?}");
    // Measured: [400, 328, 380, 332, 262, 306, 346, 312, 342] (`F`s, the trunks' included): the
    // middle tree (index 4) has neighbours on all four sides.
    let middle = per[4];
    assert!(per.iter().all(|&p| p >= middle), "{per:?}");
    let corners = [per[0], per[2], per[6], per[8]];
    assert!(
        (middle as f64) < 0.85 * *corners.iter().min().unwrap() as f64,
        "{per:?}"
    );
}

/// The ball: centre (0, 4, 0), radius 2.6; the stem from the ground to y = 2 starts below it.
#[test]
fn a_standard_clipped_to_a_ball_ends_every_segment_in_it() {
    let b = built(&example("open-topiary-ball.lsys"), 50, None);
    let segments = &b.plant.skeleton.segments;
    assert!(segments.len() > 150, "{}", segments.len());
    let centre = DVec3::new(0.0, 4.0, 0.0);
    for s in segments {
        assert!(
            s.end.distance(centre) <= 2.6 + 1e-9,
            "a segment ends at {} outside the ball",
            s.end
        );
    }
    // Round: it reaches most of the way to the ball's sides and top (measured ±2.2 or more, 6.5).
    let (lo, hi) = extent(segments);
    assert!(
        lo.x < -2.0 && hi.x > 2.0 && lo.z < -2.0 && hi.z > 2.0,
        "{lo} {hi}"
    );
    assert!(hi.y > 6.2, "{hi}");
}
