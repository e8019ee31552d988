//! The cpfg objects of vlab's course collection (`tests/collections/cpfg/`, issue 49) that need
//! cpfg's loops, contours, block variables drawn once, `func` named by a `#define`, circles and
//! predecessors of several modules: each opened whole, as the CLI opens it, built, and checked
//! against what its source implies (a hand count where the source gives one).
#![cfg(not(target_arch = "wasm32"))]

mod shared;

use meristem::import::{self, Import};
use meristem::pipeline::{build, Build, BuildOptions};
use shared::object;
use std::path::PathBuf;

fn open(name: &str) -> (Import, Build) {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/collections/cpfg")
        .join(name);
    let import = import::import_object(&object(&dir));
    let built = build(&import.text, &BuildOptions::default());
    let errors: Vec<_> = built
        .diagnostics
        .iter()
        .filter(|d| d.severity == meristem::diagnostics::Severity::Error)
        .collect();
    assert!(errors.is_empty(), "{name}: {errors:?}\n{}", import.text);
    (import, built)
}

fn count(text: &str, piece: &str) -> usize {
    text.matches(piece).count()
}

#[test]
fn vogel_draws_one_disc_for_each_of_its_500_primordia() {
    // `A(n) : n < NUMBER --> [+(n*137.5)f(0.5*n^0.5)C(n)]A(n+1)`, NUMBER 500, and
    // `C(n) --> ;(…)@c(RADIUS)`: 500 discs, each a polygon.
    let (_, b) = open("05-phyllotaxis-Vogel");
    let polygons = &b.plant.skeleton.polygons;
    assert_eq!(polygons.len(), 500);
    assert_eq!(b.plant.stats.segments, 0);
    // Primordium n stands 0.5·√n from the centre: the last, n = 499, at 11.17.
    let far = polygons
        .iter()
        .flat_map(|p| &p.points)
        .map(|p| p.length())
        .fold(0.0, f64::max);
    let expected = 0.5 * 499f64.sqrt() + 0.91 / 2.0;
    assert!((far - expected).abs() < 0.01, "{far} vs {expected}");
}

#[test]
fn the_fern_leaf_draws_three_segments_an_internode_and_its_two_leaves() {
    // Derivation length 1; the homomorphism expands A until x reaches x_max, each expansion an
    // internode F and two leaves L, each one F inside its generalized cylinder.
    let (import, b) = open("02-fern-leaf");
    assert!(!import.text.contains("not imported"), "{}", import.text);
    let segments = b.plant.stats.segments;
    assert!(segments > 30 && segments % 3 == 0, "{segments}");
    // The axis runs from 0 to L0 = 1 up the screen.
    let top = b
        .plant
        .skeleton
        .segments
        .iter()
        .map(|s| s.end.y)
        .fold(0.0, f64::max);
    assert!(top > 0.9 && top < 1.05, "{top}");
}

#[test]
fn weeping_birch_grows_exactly_its_internodes_whatever_the_draws() {
    // `A(n) : n>1 {nl = floor(n*bran(5,16)); nr = n-nl-1;} --> …F…[…A(nl)][…A(nr)]`: A(n)
    // becomes exactly n internodes, as nl and nr are drawn once. 17 steps do not finish 22,500
    // (the larger part shrinks by about 0.76 a step), so a smaller total is checked whole.
    let (import, b) = open("WeepingBirch");
    assert_eq!(
        count(&import.text, "betavariate(5,16)"),
        1,
        "{}",
        import.text
    );
    assert!(b.plant.stats.segments > 1000);
    let small = import
        .text
        .replace("#define TOTAL 22500", "#define TOTAL 300")
        .replace("derivation length: STEPS+1", "derivation length: 301");
    for seed in [1, 2, 3] {
        let options = BuildOptions {
            seed: Some(seed),
            ..BuildOptions::default()
        };
        let b = build(&small, &options);
        // 300 internodes, and at each A(1) a leaf: F(LEN) and a polygon of two F each side.
        let leaves = b.plant.skeleton.polygons.len();
        assert_eq!(b.plant.stats.segments, 300, "seed {seed}");
        assert!(leaves > 0, "seed {seed}");
    }
}

#[test]
fn ridleys_loops_fill_the_contour_with_primordia_up_to_its_length() {
    // `Start: {L=curveGAL(1);}`, then A's loop walks along the contour by ds = 0.001 until the
    // ring area reaches the primordium's: one sphere a primordium, the last near s = L.
    for name in ["Ridley", "06-phyllotaxis-ridley"] {
        let (import, b) = open(name);
        assert!(import.text.contains("#define L (0."), "{name}");
        assert!(count(&import.text, "_w1(") >= 3, "{name}");
        let spheres = &b.plant.skeleton.spheres;
        assert!(spheres.len() > 100, "{name}: {}", spheres.len());
        // Every primordium stands on the contour's surface of revolution: its distance from
        // the axis is the contour's x there, within the contour's bounds (x ≤ 0.28).
        for s in spheres {
            let r = (s.center.x * s.center.x + s.center.z * s.center.z).sqrt();
            assert!(r <= 0.28, "{name}: {r}");
        }
    }
}

#[test]
fn the_celtic_knots_tries_run_without_its_obstacle_program() {
    // obcheck (a C program) is not Meristem's: every ?E keeps the 1 the L-system writes, so
    // each strand tries its 7 directions and ends in its @o circle (a sphere of diameter 0.2).
    let (import, b) = open("CPFG-CelticKnot");
    assert!(
        import.text.contains("#consider ?E [ ] A"),
        "{}",
        import.text
    );
    let spheres = &b.plant.skeleton.spheres;
    assert_eq!(spheres.len(), 2);
    assert!((spheres[0].radius - 0.1).abs() < 1e-9);
    assert!(import.notes.iter().any(|n| n.message.contains("obcheck")));
}

#[test]
fn sierpinski_grows_pascal_s_triangle_modulo_2_through_honda81() {
    // `?E(x) : x==1 --> ;[F?E(0)]-(60)/(180)[F?E(0)]`, 15 steps, honda81 with radius 0.01 in
    // space: two tips that meet both stop, so the live tips of row n are Pascal's triangle
    // modulo 2, 2^popcount(n) of them, each drawing two segments in the next step:
    // 2·Σ_{n<15} 2^popcount(n) = 2·(3^4 − 2^4) = 130.
    let (import, b) = open("CPFG-Sierpinski");
    assert!(
        import.text.contains("#environment collision radius 0.01\n"),
        "{}",
        import.text
    );
    assert!(import.notes.is_empty(), "{:?}", import.notes);
    let by_hand: u32 = (0..15u32).map(|n| 2 << n.count_ones()).sum();
    assert_eq!(by_hand, 130);
    assert_eq!(b.plant.stats.segments, by_hand as usize);
}

/// The straight distance from where the first segment starts to where the last one ends, in
/// units of the first segment's length (every F of these curves is as long as the first).
fn span_in_steps(b: &Build) -> f64 {
    let segments = &b.plant.skeleton.segments;
    let unit = (segments[0].end - segments[0].start).length();
    for s in segments {
        assert!(((s.end - s.start).length() - unit).abs() < 1e-9 * unit);
    }
    (segments[segments.len() - 1].end - segments[0].start).length() / unit
}

#[test]
fn the_quadratic_koch_curve_draws_8_to_the_4_segments_spanning_4_to_the_4() {
    // `F --> F+F-F-FF+F+F-F`, 4 steps, no homomorphism: each F becomes 8, so 8^4 = 4096 F.
    // With the view file's 90°, the eight F go east, north, east, south, south, east, north,
    // east: 4 east, 1 + 1 − 2 = 0 north, so each F's ends move 4 times as far apart a step and
    // the curve's ends stand 4^4 = 256 F apart.
    let (_, b) = open("01-quadratic-Koch");
    assert_eq!(b.plant.stats.segments, 8usize.pow(4));
    let span = span_in_steps(&b);
    assert!((span - 256.0).abs() < 1e-6, "{span}");
}

#[test]
fn the_dragon_curve_draws_2_to_the_8_segments_spanning_16() {
    // `L --> +L--R+`, `R --> -L++R-`, 8 steps, then `L --> F`, `R --> F`: each letter becomes
    // one L and one R, so 2^8 = 256 letters and 256 F. Angle factor 8 gives 45°: +L--R+
    // draws L turned 45° left and R 45° right of the heading and returns to it, so the ends
    // move √2 times as far apart a step: (√2)^8 = 16 F.
    let (_, b) = open("DragonCurve");
    assert_eq!(b.plant.stats.segments, 256);
    let span = span_in_steps(&b);
    assert!((span - 16.0).abs() < 1e-6, "{span}");
}

#[test]
fn the_koch_snowflake_object_draws_4_to_the_4_segments_spanning_3_to_the_4() {
    // `F --> F+F--F+F`, 4 steps, 60°: 4^4 = 256 F. The four F go at 0°, 60°, −60°, 0°: their
    // ends stand 1 + 2·cos 60° + 1 = 3 F apart along the heading, so 3^4 = 81 after 4 steps.
    let (_, b) = open("03-snowflake");
    assert_eq!(b.plant.stats.segments, 256);
    let span = span_in_steps(&b);
    assert!((span - 81.0).abs() < 1e-6, "{span}");
}

#[test]
fn the_compound_leaf_draws_2_times_3_to_the_4_minus_2_to_the_4_segments_30_high() {
    // `A --> F[+A][-A]FA`, `F --> FF`, 4 steps, A not drawn. A step makes 3 A of each A, so
    // 3^n A after n; F count f(n+1) = 2·f(n) + 2·3^n, f(0) = 0: f(n) = 2·(3^n − 2^n), 130.
    // The main axis: A after n steps is 2 F after n − 1 steps (2^(n−1) each) then A after
    // n − 1, so h(n) = 2^n + h(n−1) = 2 + 4 + 8 + 16 = 30 F. No path in a side A after k
    // steps is longer than its main axis h(k), and the main axis goes on from the branch point
    // for 2^k + h(k) > h(k): the top is the main axis's, 30 F above the base.
    let (_, b) = open("04-compound");
    assert_eq!(b.plant.stats.segments, 2 * (81 - 16));
    let segments = &b.plant.skeleton.segments;
    let unit = (segments[0].end - segments[0].start).length();
    let base = segments[0].start.y;
    let top = segments.iter().map(|s| s.end.y).fold(f64::MIN, f64::max);
    assert!(
        ((top - base) / unit - 30.0).abs() < 1e-6,
        "{}",
        (top - base) / unit
    );
}

#[test]
fn the_recursive_leaf_draws_2_to_the_8_minus_1_segments_from_a_8() {
    // Derivation length 1 from `A(8)`; the homomorphism (depth 100) expands
    // `A(t) : t >= 2 --> M(t-2) A(t-1)`, `M(t) --> I(x)[+A(t)][-A(t)]I(x)` with x = 0.5·1.5^t,
    // `A(t) : t < 2 --> ;F(t)`, `I(x) --> F(x)`. F modules: S(t) = 1 for t < 2 and
    // S(t) = S(t−1) + 2 + 2·S(t−2): S(2..8) = 5, 9, 21, 41, 85, 169, 341. But the A(0) tips
    // draw F(0), a step of length 0 that draws nothing (cpfg's line has no length either):
    // Z(0) = 1, Z(1) = 0, Z(t) = Z(t−1) + 2·Z(t−2): Z(2..8) = 2, 2, 6, 10, 22, 42, 86.
    // Drawn: S(n) − Z(n) = (2^(n+2) + 2·(−1)^n)/3 − 1 − (2^n + 2·(−1)^n)/3 = 2^n − 1 = 255.
    let s = |n: u32| (2i64.pow(n + 2) + 2 * (-1i64).pow(n)) / 3 - 1;
    let z = |n: u32| (2i64.pow(n) + 2 * (-1i64).pow(n)) / 3;
    assert_eq!((s(8), z(8)), (341, 86));
    let (_, b) = open("10-recursive");
    assert_eq!(b.plant.stats.segments, (s(8) - z(8)) as usize);
    assert_eq!(b.plant.stats.segments, 255);
    // The shortest segments are M(0)'s I(0.5), the longest M(6)'s I(0.5·1.5^6), from A(8).
    let lengths: Vec<f64> = b
        .plant
        .skeleton
        .segments
        .iter()
        .map(|s| (s.end - s.start).length())
        .collect();
    let shortest = lengths.iter().copied().fold(f64::MAX, f64::min);
    let longest = lengths.iter().copied().fold(0.0, f64::max);
    assert!(
        (longest / shortest - 1.5f64.powi(6)).abs() < 1e-9,
        "{shortest} {longest}"
    );
}
