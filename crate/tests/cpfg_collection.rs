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
