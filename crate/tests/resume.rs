//! Property: a build continued from an earlier build of fewer steps (`build_on`) is the build
//! made from the axiom, byte for byte: derived string, provenance of the last step, id counts,
//! diagnostics, skeleton and mesh. For the gallery's examples and for random grammars (D0L,
//! parametric, stochastic, with contexts, decomposition, cut and homomorphism), from several
//! earlier step counts, and chained (n₁ → n₂ → m). Grammars that cannot be continued exactly
//! (`MaxIt`, `@Repeat`, growth attributes) are built whole and must still be equal.
//! Native only: proptest is not a wasm32 dependency.
#![cfg(not(target_arch = "wasm32"))]

use meristem::pipeline::{
    build, build_on, why_not_continued, Build, BuildOptions, Hooks, Progress,
};
use proptest::prelude::*;

mod shared;

fn options(iterations: u32, seed: Option<u64>) -> BuildOptions {
    BuildOptions {
        iterations: Some(iterations),
        seed,
        ..BuildOptions::default()
    }
}

/// Builds `source` on `from`, and the derivation steps the build was told it ran.
fn on(source: &str, options: &BuildOptions, from: &Build) -> (Build, Vec<u32>) {
    let mut told = Vec::new();
    let mut progress = |p: Progress| {
        if let Progress::Derived { step, .. } = p {
            told.push(step);
        }
    };
    let mut hooks = Hooks {
        clock: None,
        progress: Some(&mut progress),
    };
    let built = build_on(source, options, from, &mut hooks);
    (built, told)
}

/// Asserts that two builds are the same, byte for byte (the timings aside).
fn assert_same(whole: &Build, continued: &Build, what: &str) {
    assert_eq!(
        whole.diagnostics, continued.diagnostics,
        "{what}: diagnostics"
    );
    assert_eq!(whole.model, continued.model, "{what}: model");
    assert!(
        whole.derivation == continued.derivation,
        "{what}: derivation\n{:?}\n{:?}",
        whole.derived_text(),
        continued.derived_text()
    );
    assert_eq!(
        whole.derivation.origin(),
        continued.derivation.origin(),
        "{what}: origin"
    );
    assert_eq!(
        whole.derivation.parent(),
        continued.derivation.parent(),
        "{what}: parent"
    );
    let kept = |b: &Build| b.derivation.resume.as_ref().map(|r| (r.steps, r.seed));
    assert_eq!(kept(whole), kept(continued), "{what}: resume state");
    assert_eq!(
        format!("{:?}", whole.derived_with),
        format!("{:?}", continued.derived_with),
        "{what}: options"
    );
    assert_eq!(
        whole.plant.skeleton, continued.plant.skeleton,
        "{what}: skeleton"
    );
    let (a, b) = (&whole.plant.mesh, &continued.plant.mesh);
    let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    for (name, x, y) in [
        ("positions", &a.positions, &b.positions),
        ("normals", &a.normals, &b.normals),
        ("colors", &a.colors, &b.colors),
        ("uvs", &a.uvs, &b.uvs),
        ("lines", &a.lines, &b.lines),
    ] {
        assert!(bits(x) == bits(y), "{what}: mesh {name}");
    }
    assert_eq!(a.indices, b.indices, "{what}: indices");
    assert_eq!(a, b, "{what}: mesh");
    assert_eq!(
        format!("{:?}", whole.plant.stats),
        format!("{:?}", continued.plant.stats),
        "{what}: stats"
    );
}

/// For every `n` in `from`, build(m) == build(n) continued to m; and a chain through them.
/// Returns whether the continuations ran only the new steps.
fn check(source: &str, m: u32, from: &[u32], seed: Option<u64>, what: &str) -> bool {
    let whole = build(source, &options(m, seed));
    let mut continued = true;
    let mut chain: Option<Build> = None;
    for &n in from.iter().filter(|&&n| n < m) {
        let earlier = build(source, &options(n, seed));
        let (on_earlier, told) = on(source, &options(m, seed), &earlier);
        assert_same(&whole, &on_earlier, &format!("{what}: {n} → {m}"));
        continued &= told.get(1) == Some(&(n + 1)) || !earlier.ok();
        chain = Some(match chain {
            None => earlier,
            Some(before) => on(source, &options(n, seed), &before).0,
        });
    }
    if let Some(before) = chain {
        let (chained, _) = on(source, &options(m, seed), &before);
        assert_same(&whole, &chained, &format!("{what}: chained to {m}"));
    }
    continued
}

#[test]
fn every_gallery_example_continued_is_the_build_from_its_axiom() {
    let mut continued = 0;
    for (path, text) in shared::examples() {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let grammar = build(&text, &BuildOptions::default());
        let full = grammar.derived_with.steps;
        // Big plants at fewer steps, and at most 80 (a Vogel head adds one floret a step for
        // 600): the property is per step, the test must stay quick.
        let small = |m: u32| build(&text, &options(m, None)).plant.stats.segments <= 4_000;
        let m = (1..=full.min(80))
            .take_while(|&m| small(m))
            .last()
            .unwrap_or(1);
        let from = [m / 3, m.saturating_sub(1)];
        let blocked = why_not_continued(&grammar);
        let stepped = check(&text, m, &from, None, &name);
        assert!(
            stepped || blocked.is_some() || m == 0,
            "{name}: derived from the axiom again although nothing blocks continuing"
        );
        assert!(
            blocked.is_some() || grammar.derivation.resume.is_some(),
            "{name}: kept no state to continue from"
        );
        continued += usize::from(blocked.is_none());
        // Another seed: continued only from a build with that seed.
        check(&text, m, &[m.saturating_sub(1)], Some(7), &name);
    }
    assert!(continued >= 30, "only {continued} examples continue");
}

#[test]
fn a_build_is_not_continued_from_another_seed_grammar_or_more_steps() {
    let source = "#seed 3\naxiom: A\nA -> (1) A B\nA -> (1) A C\n";
    let earlier = build(source, &options(4, Some(1)));
    let (other_seed, told) = on(source, &options(6, Some(2)), &earlier);
    assert_same(&build(source, &options(6, Some(2))), &other_seed, "seed");
    assert_eq!(told.first(), Some(&0), "derived from the axiom");
    let other = "#seed 3\naxiom: A\nA -> (1) A B\nA -> (2) A C\n";
    let (other_grammar, told) = on(other, &options(6, Some(1)), &earlier);
    assert_same(
        &build(other, &options(6, Some(1))),
        &other_grammar,
        "grammar",
    );
    assert_eq!(told.first(), Some(&0), "derived from the axiom");
    let (fewer, told) = on(source, &options(3, Some(1)), &earlier);
    assert_same(&build(source, &options(3, Some(1))), &fewer, "fewer steps");
    assert_eq!(told.first(), Some(&0), "derived from the axiom");
    let (same, told) = on(source, &options(5, Some(1)), &earlier);
    assert_same(&build(source, &options(5, Some(1))), &same, "one more");
    assert_eq!(told, vec![4, 5], "one step");
}

#[test]
fn grammars_that_cannot_continue_exactly_are_built_whole() {
    let blocked = [
        "axiom: A(0)\nA(x) -> F(1) A(x + MaxIt)\n",
        "axiom: @Repeat(2, A)\nA -> A B\n",
        "axiom: A\nA -> A F\nhomomorphism:\nF -> (1) F\nF -> (1) G\n",
        "#lifetime 3 1\naxiom: A\nA -> F[+A][-A]\n",
    ];
    for source in blocked {
        let earlier = build(source, &options(2, None));
        assert!(why_not_continued(&earlier).is_some(), "{source}");
        assert!(earlier.derivation.resume.is_none(), "{source}");
        check(source, 4, &[1, 2, 3], None, source);
    }
}

#[test]
fn a_dt_grammar_continues_step_by_step() {
    let source = "#define dt 0.01\naxiom: X(0)\n\
                  X(k) : k < 6 -> /(137.5)[&(30)X(k+1)]X(k+1)\n\
                  X(k) : k >= 6 -> A(0)\n\
                  A(t) -> A(t + dt)\n\
                  homomorphism:\nA(t) -> F(0.1 + t)\n";
    let mut last = build(source, &options(10, None));
    for m in 11..40 {
        let (next, told) = on(source, &options(m, None), &last);
        assert_eq!(told, vec![m - 1, m], "only step {m} was derived");
        assert_same(&build(source, &options(m, None)), &next, "dt");
        last = next;
    }
}

const PIECES: [&str; 8] = ["A(1)", "B(2)", "F(1)", "+", "-", "C", "[", "]"];

/// A balanced parametric string of pieces (brackets opened and closed by the choices).
fn string_of(choices: &[u8]) -> String {
    let mut out = String::new();
    let mut depth = 0;
    for &c in choices {
        match PIECES[c as usize % PIECES.len()] {
            "[" => {
                depth += 1;
                out.push('[');
            }
            "]" if depth == 0 => out.push('C'),
            "]" => {
                depth -= 1;
                out.push(']');
            }
            piece => out.push_str(piece),
        }
    }
    out.extend(std::iter::repeat_n(']', depth));
    out
}

/// Productions a random grammar picks from: every kind of rule the derivation runs.
const RULES: [&str; 14] = [
    "A(x) : x < 3 -> F(x) [+A(x + 1)] A(x + 0.5)",
    "A(x) -> (1) B(x) F(0.5)",
    "A(x) -> (2) A(x * 0.9) [-C]",
    "B(y) < A(x) -> A(x + y)",
    "A(x) > B(y) : y > 1 -> A(x) %",
    "B(y) -> F(uniform(0.5, 1.5)) B(y + 1)",
    "B(y) : p < 0.5 -> B(y - 1) C",
    "C -> (1) F(1) C",
    "C -> (1) [+F(0.3)]",
    "F(l) -> F(l * 1.1)",
    "decomposition:\nB(y) : y > 3 -> C B(y - 3)\nproductions:",
    "homomorphism:\nC -> F(0.2) +\nA(x) -> F(x / 2)\nproductions:",
    "A(x) < F(l) -> F(l + x)",
    "C > [F(l)] -> D",
];

proptest! {
    #![proptest_config(ProptestConfig { cases: 120, ..ProptestConfig::default() })]

    #[test]
    fn random_parametric_grammars_continued_are_built_from_the_axiom(
        axiom in prop::collection::vec(any::<u8>(), 1..10),
        rules in prop::collection::vec(0usize..RULES.len(), 1..7),
        seed in 0u64..1000,
        m in 1u32..7,
        n in 0u32..6,
    ) {
        let mut source = format!(
            "#random p = uniform(0, 1)\n#max_modules 20000\naxiom: {}\n",
            string_of(&axiom)
        );
        for &r in &rules {
            source.push_str(RULES[r]);
            source.push('\n');
        }
        let n = n % m;
        let stepped = check(&source, m, &[n, (n + m) / 2], Some(seed), &source);
        let whole = build(&source, &options(m, Some(seed)));
        prop_assert!(stepped || why_not_continued(&whole).is_some() || !whole.ok());
    }

    #[test]
    fn random_d0l_grammars_continued_are_built_from_the_axiom(
        axiom in prop::collection::vec(any::<u8>(), 1..8),
        successors in prop::collection::vec((0usize..5, prop::collection::vec(any::<u8>(), 0..7)), 0..5),
        m in 1u32..6,
        n in 0u32..5,
    ) {
        let letters = ["A", "B", "F", "+", "-"];
        let plain = |choices: &[u8]| {
            string_of(choices).replace("A(1)", "A").replace("B(2)", "B").replace("F(1)", "F")
        };
        let mut source = format!("axiom: {}\n", plain(&axiom));
        for (letter, choices) in &successors {
            source.push_str(&format!("{} -> {}\n", letters[*letter], plain(choices)));
        }
        check(&source, m, &[n % m], None, &source);
    }
}
