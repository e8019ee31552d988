//! cpfg's constructs that the course objects of vlab need (issue 49), each imported from a
//! small text and built: what the plant has, counted by hand from the source.

use super::super::{import, Flavour};
use crate::import::test_support::assert_resolves;
use crate::pipeline::Build;

fn build(text: &str) -> (String, Build) {
    let import = import(text, Flavour::Cpfg);
    assert_resolves(&import);
    let built = crate::pipeline::build(&import.text, &crate::BuildOptions::default());
    (import.text, built)
}

#[test]
fn a_block_variable_that_draws_is_drawn_once_for_every_place_that_reads_it() {
    // WeepingBirch's split: nl and nr = n-nl-1 add up to n-1, so A(n) grows exactly n
    // internodes F, whatever the draws. Substituted, bran would be drawn apart for nl and nr.
    let text = "Lsystem: 1\nderivation length: 40\nAxiom: A(60)\n\
        A(n) : n>1 {nl=floor(n*bran(2,3)+0.0); nr = n-nl-1;} --> F[+A(nl)][-A(nr)]\n\
        A(n) : n==1 --> F\nA(n) : n<=0 --> *\nendlsystem\n";
    let (translated, built) = build(text);
    assert!(translated.contains("betavariate(2,3)"), "{translated}");
    assert_eq!(
        translated.matches("betavariate(").count(),
        1,
        "{translated}"
    );
    for seed in 1..4 {
        let options = crate::BuildOptions {
            seed: Some(seed),
            ..Default::default()
        };
        let import = import(text, Flavour::Cpfg);
        let built = crate::pipeline::build(&import.text, &options);
        assert_eq!(built.plant.skeleton.segments.len(), 60, "seed {seed}");
    }
    assert_eq!(built.plant.skeleton.segments.len(), 60);
}

#[test]
fn a_draw_read_by_the_condition_stays_substituted() {
    let text = "Lsystem: 1\nderivation length: 1\nAxiom: A(1)\n\
        A(n) : {r=ran(1);} r<2 --> F(r)\nendlsystem\n";
    let (translated, built) = build(text);
    assert!(!translated.contains("decomposition"), "{translated}");
    assert_eq!(built.plant.skeleton.segments.len(), 1);
}

#[test]
fn a_function_named_by_a_define_and_a_macro_continued_by_two_backslashes_are_read() {
    // 02-fern-leaf: `#define int_length(x) \\` then the value on the next line, and
    // func(INT_LENGTH, x) with `#define INT_LENGTH 1`. Without its view file the function is
    // not there: the note says the view file, not that the number is an expression.
    let text = "#define INT_LENGTH 1\n#define len(x) \\\\\n\t(2 * x)\n\
        Lsystem: 1\nderivation length: 1\nAxiom: A\nA --> F(len(3))\nendlsystem\n";
    let (translated, built) = build(text);
    assert!(translated.contains("F((2 * 3))"), "{translated}");
    assert_eq!(built.plant.skeleton.segments.len(), 1);
    let end = built.plant.skeleton.segments[0].end;
    assert!((end.y - 6.0).abs() < 1e-9, "{end:?}");
    let funcs = "#define INT_LENGTH 1\nLsystem: 1\nderivation length: 1\nAxiom: A\n\
        A --> F(func(INT_LENGTH, 0.5))\nendlsystem\n";
    let import = import(funcs, Flavour::Cpfg);
    assert!(
        import
            .notes
            .iter()
            .any(|n| n.message.contains("view file (.v)")),
        "{:?}",
        import.notes
    );
}

#[test]
fn a_circle_in_the_hl_plane_is_a_polygon_of_its_diameter_and_a_screen_circle_a_sphere() {
    // 05-phyllotaxis-Vogel: `@c(d)` at each of 3 primordia; CelticKnot's `@o(d)`.
    let text = "Lsystem: 1\nderivation length: 1\nAxiom: A\n\
        A --> [f(1)@c(2)][f(2)@c(2)][f(3)@c(2)]@o(0.5)\nendlsystem\n";
    let (_, built) = build(text);
    let skeleton = &built.plant.skeleton;
    assert_eq!(skeleton.segments.len(), 0);
    assert_eq!(skeleton.polygons.len(), 3);
    for (k, polygon) in skeleton.polygons.iter().enumerate() {
        assert_eq!(polygon.points.len(), super::circles::SIDES);
        let centre = glam::DVec3::new(0.0, k as f64 + 1.0, 0.0);
        for p in &polygon.points {
            // Radius 1 around the turtle, in its H–L plane (z = 0).
            assert!(((*p - centre).length() - 1.0).abs() < 1e-9, "{p:?}");
            assert!(p.z.abs() < 1e-9);
        }
    }
    assert_eq!(skeleton.spheres.len(), 1);
    assert!((skeleton.spheres[0].radius - 0.25).abs() < 1e-12);
}
