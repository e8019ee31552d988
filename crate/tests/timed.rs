//! Timed D0L-systems (ABOP section 6.1) and growth functions (section 6.2): the string at a time
//! t, ages between replacements, several replacements in one interval, `#dt`, the growth
//! functions' values, continuity of lengths across a replacement, and bad input as diagnostics.
//!
//! The text of ABOP chapter 6 was not at hand when these were written: the expected strings are
//! ABOP section 1.2's D0L words (which a timed system of lifetimes 1 reproduces at whole times)
//! and hand computation, each spelled out next to its test.

mod shared;
use meristem::maths;
use shared::model;

use meristem::derive::{derive, derive_traced, DeriveOptions, Unobserved};
use meristem::model::resolve;
use meristem::pipeline::{build, BuildOptions};
use meristem::syntax::parse;

const ANABAENA: &str = include_str!("../../public/examples/abop-6.1-timed-anabaena.lsys");

/// The derived string at growth time `t` (in steps).
fn at(src: &str, t: f64) -> String {
    let m = model(src);
    let options = DeriveOptions {
        steps: t.ceil() as u32,
        seed: None,
        time: Some(t),
    };
    let d = derive(&m, &options).unwrap_or_else(|e| panic!("{}", e.message));
    d.string.to_text(&m.alphabet)
}

/// The derived string at each time of `expected` is the one given there.
fn check_times(src: &str, expected: &[(f64, &str)]) {
    for &(t, string) in expected {
        assert_eq!(at(src, t), string, "t = {t}");
    }
}

/// The total length the turtle draws at growth time `t`: the `F` lengths of the homomorphism's
/// string.
fn length_at(src: &str, t: f64) -> f64 {
    let b = build(
        src,
        &BuildOptions {
            time: Some(t),
            ..BuildOptions::default()
        },
    );
    assert!(b.ok(), "{:?}", b.diagnostics);
    let m = b.model.as_ref().expect("model");
    let s = b.derivation.turtle_string();
    let f = m.alphabet.get("F").expect("F");
    (0..s.len())
        .filter(|&i| s.ids[i] == f)
        .map(|i| s.params_of(i)[0])
        .sum()
}

/// The error codes of a grammar's parse and resolve, with the text each span covers.
fn errors(src: &str) -> Vec<(String, String)> {
    let (file, mut diags) = parse(src);
    diags.extend(resolve(&file).1);
    diags
        .iter()
        .map(|d| (d.code.to_string(), src[d.span.clone()].to_string()))
        .collect()
}

#[test]
fn at_whole_times_the_timed_filament_is_the_d0l_word_of_section_1_2() {
    // ABOP section 1.2's words of the Anabaena D0L-system, steps 0 to 4.
    let printed = [
        "a_r",
        "a_l b_r",
        "b_l a_r a_r",
        "a_l a_l b_r a_l b_r",
        "b_l a_r b_l a_r a_r b_l a_r a_r",
    ];
    for (n, word) in printed.iter().enumerate() {
        let timed = at(ANABAENA, n as f64);
        assert_eq!(timed.replace("(0)", " ").trim_end(), *word, "t = {n}");
    }
    // Further on, the same as the D0L-system itself.
    let d0l = "axiom: a_r\na_r -> a_l b_r\na_l -> b_l a_r\nb_r -> a_r\nb_l -> a_l";
    let m = model(d0l);
    for n in 5..=9 {
        let options = DeriveOptions::of_steps(n);
        let word = derive(&m, &options).expect("derives").string;
        assert_eq!(
            at(ANABAENA, n as f64).replace("(0)", ""),
            word.to_text(&m.alphabet)
        );
    }
}

#[test]
fn between_replacements_every_module_ages_with_time() {
    check_times(
        ANABAENA,
        &[(2.5, "b_l(0.5)a_r(0.5)a_r(0.5)"), (0.25, "a_r(0.25)")],
    );
}

#[test]
fn lifetimes_that_differ_replace_modules_at_their_own_times() {
    // By hand: A lives 2, B lives 1; A is replaced by A at age 1 and a new B.
    //   t = 0: A(0)
    //   t = 2: A reaches 2 -> A(1) B(0)
    //   t = 3: both reach their ends -> A(1) B(0) A(0)
    //   t = 4: A(1)'s A at 2 -> A(1) B(0); B -> A(0); A(0) is only 1 -> A(1)
    let src = "#terminal_age A 2 B 1\naxiom: A(0)\nA(x) -> A(1) B(0)\nB(x) -> A(0)";
    check_times(
        src,
        &[
            (1.5, "A(1.5)"),
            (2.0, "A(1)B(0)"),
            (2.5, "A(1.5)B(0.5)"),
            (3.0, "A(1)B(0)A(0)"),
            (3.5, "A(1.5)B(0.5)A(0.5)"),
            (4.0, "A(1)B(0)A(0)A(1)"),
        ],
    );
    // One derivation from 0 to 4 runs the three rounds (t = 2, 3, 4) on its way.
    let m = model(src);
    let options = DeriveOptions::of_steps(4);
    let (_, trace) = derive_traced(&m, &options, &mut Unobserved).expect("derives");
    let texts: Vec<String> = trace
        .iter()
        .map(|s| s.string.to_text(&m.alphabet))
        .collect();
    assert_eq!(
        texts,
        ["A(0)", "A(1)B(0)", "A(1)B(0)A(0)", "A(1)B(0)A(0)A(1)"]
    );
}

#[test]
fn a_production_reads_the_age_and_other_parameters() {
    // An apex that counts its internodes: replaced at age 1, with its count, which a condition
    // reads; the internode I is not timed and stays.
    let src = "#terminal_age A 1\naxiom: A(0, 0)\nA(t, n): n < 2 -> I(n) A(0, n + 1)\nA(t, n): n >= 2 -> B";
    check_times(
        src,
        &[
            (1.0, "I(0)A(0,1)"),
            (2.75, "I(0)I(1)A(0.75,2)"),
            (3.0, "I(0)I(1)B"),
        ],
    );
    // A module at its terminal age that no production rewrites keeps ageing, and is never
    // rewritten later (no endless rounds).
    let stuck = "#terminal_age A 1\naxiom: A(0)\nA(t): t > 5 -> B";
    assert_eq!(at(stuck, 3.0), "A(3)");
    // A successor written at its terminal age by an expression (no constant to check) is never
    // due again either: one round, then it only ages.
    let at_end = "#terminal_age A 1\naxiom: A(0)\nA(t) -> A(t) B";
    assert_eq!(at(at_end, 5.0), "A(5)B");
}

#[test]
fn dt_is_the_time_a_step_covers() {
    let half = ANABAENA.replace("#iterations 6", "#dt 0.5\n#iterations 4");
    let b = build(&half, &BuildOptions::default());
    assert!(b.ok(), "{:?}", b.diagnostics);
    let m = b.model.as_ref().expect("model");
    assert_eq!(
        b.derivation.string.to_text(&m.alphabet),
        "b_l(0)a_r(0)a_r(0)"
    );
    // Expressions read dt: L-Py's continuous-growth idiom, without timed modules.
    let lpy = "#dt 0.25\n#iterations 3\naxiom: A(0)\nA(x) -> A(x + dt)";
    let b = build(lpy, &BuildOptions::default());
    let m = b.model.as_ref().expect("model");
    assert_eq!(b.derivation.string.to_text(&m.alphabet), "A(0.75)");
    // Without #dt, dt is 1.
    assert_eq!(at("axiom: A(dt)", 0.0), "A(1)");
}

#[test]
fn growth_functions_take_their_values() {
    let values = |expr: &str| {
        let text = at(&format!("axiom: A({expr})"), 0.0);
        text["A(".len()..text.len() - 1]
            .split(',')
            .map(|v| v.parse::<f64>().expect("a number"))
            .collect::<Vec<f64>>()
    };
    let close = |a: &[f64], b: &[f64]| {
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() < 1e-12, "{a:?} != {b:?}");
        }
    };
    // linear: a straight line from a to b, level outside 0 … 1.
    close(
        &values("linear(0.25, 2, 6), linear(-1, 2, 6), linear(3, 2, 6)"),
        &[3.0, 2.0, 6.0],
    );
    // exponential_growth: the same factor in equal times: 1 -> 2 -> 4.
    close(
        &values("exponential_growth(0, 1, 4), exponential_growth(0.5, 1, 4), exponential_growth(1, 1, 4)"),
        &[1.0, 2.0, 4.0],
    );
    // logistic: exactly a and b at the ends, halfway at the middle, steeper with k.
    close(
        &values("logistic(0, 1, 3, 10), logistic(0.5, 1, 3, 10), logistic(1, 1, 3, 10)"),
        &[1.0, 2.0, 3.0],
    );
    let shallow = values("logistic(0.25, 0, 1, 1)")[0];
    let steep = values("logistic(0.25, 0, 1, 20)")[0];
    assert!(
        steep < shallow && shallow < 0.25 + 1e-9,
        "{steep} {shallow}"
    );
    // sigmoid: x²(3 − 2x): 0.25 -> 0.15625, 0.5 -> 0.5.
    close(
        &values("sigmoid(0.25, 0, 1), sigmoid(0.5, 0, 1), sigmoid(2, 0, 1)"),
        &[0.15625, 0.5, 1.0],
    );
    // #curve at age / terminal age.
    let curve = "#curve c 0 0, 0.3 0.1, 0.7 0.9, 1 1\n#define age 1\naxiom: A(c(0 / 2), c(age / 2), c(2 / 2))";
    let text = at(curve, 0.0);
    let read: Vec<f64> = text[2..text.len() - 1]
        .split(',')
        .map(|v| v.parse().expect("a number"))
        .collect();
    assert!(
        read[0].abs() < 1e-12 && (read[2] - 1.0).abs() < 1e-12,
        "{text}"
    );
    assert!(
        (read[1] - 0.5).abs() < 1e-9,
        "the symmetric curve's middle: {text}"
    );
}

#[test]
fn growth_functions_with_bad_arguments_stop_with_an_error() {
    for expr in ["exponential_growth(0.5, 0, 1)", "logistic(0.5, 0, 1, 0)"] {
        let src = format!("axiom: A(x)\nA(x) -> A({expr})");
        let m = model(&src.replace("axiom: A(x)", "axiom: A(1)"));
        let options = DeriveOptions::of_steps(1);
        let e = derive(&m, &options).expect_err(expr);
        assert_eq!(e.code, "E0500", "{expr}: {}", e.message);
    }
}

#[test]
fn the_filament_is_as_long_just_before_a_division_as_just_after() {
    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    for t in [1.0, 2.0, 3.0, 5.0] {
        let before = length_at(ANABAENA, t - 1e-9);
        let after = length_at(ANABAENA, t + 1e-9);
        assert!(
            (before - after).abs() < 1e-6,
            "t = {t}: {before} then {after}"
        );
    }
    // Every cell grows by φ per unit of time, so the filament is φ^(t + 1) long.
    for t in [0.0, 0.5, 2.5, 4.25] {
        let length = length_at(ANABAENA, t);
        assert!(
            (length - maths::powf(phi, t + 1.0)).abs() < 1e-9,
            "t = {t}: {length}"
        );
    }
}

#[test]
fn bad_timed_grammars_give_diagnostics_at_their_place() {
    let code = |src: &str| errors(src);
    assert_eq!(
        code("#terminal_age A 2 B\naxiom: A(0)"),
        [("E0211".into(), "A 2 B".into())]
    );
    assert_eq!(
        code("#terminal_age A -1\naxiom: A(0)"),
        [("E0211".into(), "-1".into())]
    );
    assert_eq!(
        code("#terminal_age A 1 A 2\naxiom: A(0)"),
        [("E0211".into(), "A".into())]
    );
    assert_eq!(code("#dt 0\naxiom: A"), [("E0211".into(), "0".into())]);
    assert_eq!(
        code("#dt -0.5\naxiom: A"),
        [("E0211".into(), "-0.5".into())]
    );
    assert_eq!(
        code("#terminal_age A 1\naxiom: A\nA -> A"),
        [
            ("E0212".into(), "A".into()),
            ("E0212".into(), "A".into()),
            ("E0212".into(), "A".into())
        ]
    );
    assert_eq!(
        code("#terminal_age A 1\naxiom: A(0)\nA(t) -> A(1)"),
        [("E0213".into(), "A(1)".into())]
    );
    assert_eq!(
        code("#terminal_age A 1\n#gravity 5\naxiom: A(0)"),
        [("E0214".into(), "#terminal_age A 1".into())]
    );
}

#[test]
fn a_grammar_may_define_dt_itself() {
    // cpfg models write `#define dt 0.02`: their own dt replaces the value.
    assert_eq!(at("#define dt 0.02\naxiom: A(dt)", 0.0), "A(0.02)");
    assert_eq!(at("#dt 0.5\n#define dt 0.02\naxiom: A(dt)", 0.0), "A(0.02)");
}

#[test]
fn too_many_rounds_before_the_time_is_an_error_not_a_hang() {
    let src = "#terminal_age A 0.000001\naxiom: A(0)\nA(t) -> A(0)";
    let started = std::time::Instant::now();
    let b = build(
        src,
        &BuildOptions {
            time: Some(1000.0),
            ..BuildOptions::default()
        },
    );
    let codes: Vec<&str> = b.diagnostics.iter().map(|d| d.code).collect();
    assert_eq!(codes, ["E0407"]);
    assert_eq!(
        &src[b.diagnostics[0].span.clone()],
        "#terminal_age A 0.000001"
    );
    assert!(started.elapsed().as_secs() < 10);
    // Raised, the same grammar reaches a short time.
    let raised = format!("#max_steps 100000\n{src}");
    assert_eq!(at(&raised, 0.05), "A(0)");
}

#[test]
fn a_growth_time_between_steps_of_an_untimed_grammar_shows_its_whole_steps() {
    let src = "axiom: A\nA -> AB";
    let b = build(
        src,
        &BuildOptions {
            time: Some(2.5),
            ..BuildOptions::default()
        },
    );
    let m = b.model.as_ref().expect("model");
    assert_eq!(b.derivation.string.to_text(&m.alphabet), "ABB");
}

#[test]
fn an_lpy_continuous_growth_model_imports_with_its_time_step_and_grows() {
    // L-Py's idiom (its 07-continuous-growth style): a global dt, ages stepped by dt each step.
    let lpy = "dt = 0.1\nmaxage = 3\n\ndef growth(age):\n    return min(age / maxage, 1)\n\n\
               Axiom: A(0)\nderivation length: 40\nproduction:\nA(age) :\n  if age > 1: produce I(0)[+L(0)]A(0)\n  \
               else: produce A(age + dt)\nI(age) --> I(age + dt)\nL(age) --> L(age + dt)\n\
               interpretation:\nI(age) --> F(growth(age))\nL(age) --> ~l(growth(age))\nendlsystem\n";
    let imported = meristem::import::import(lpy, meristem::import::Dialect::Lpy);
    assert!(imported.text.contains("#dt 0.1\n"), "{}", imported.text);
    assert!(imported.notes.is_empty(), "{:?}", imported.notes);
    let grown = |steps: u32| {
        let b = build(
            &imported.text,
            &BuildOptions {
                iterations: Some(steps),
                ..BuildOptions::default()
            },
        );
        assert!(b.ok(), "{:?}", b.diagnostics);
        b.plant.mesh.positions.len()
    };
    // The apex lays down an internode and a leaf each time its age passes 1 in steps of 0.1;
    // they then grow with their own ages: nothing drawn at step 12, one internode at 20, more at 40.
    assert_eq!(grown(12), 0);
    assert!(grown(40) > grown(20) && grown(20) > 0);
    let b = build(&imported.text, &BuildOptions::default());
    let m = b.model.as_ref().expect("model");
    assert_eq!(m.settings.dt, 0.1);
    // Its organs lengthen with their age at every step: on the timeline it is stepwise, derived
    // to each whole step rather than grown in from the whole plant's mesh.
    assert!(m.settings.stepwise() && !m.settings.timed());
}

#[test]
fn a_time_step_without_timed_modules_makes_a_grammar_stepwise() {
    let settings = |text: &str| {
        let b = build(text, &BuildOptions::default());
        b.model.expect("model").settings
    };
    assert!(settings("#dt 0.1\naxiom: A(0)\nA(t) -> A(t+dt)").stepwise());
    assert!(!settings("axiom: F\nF -> FF").stepwise());
    let timed = settings("#dt 0.5\n#terminal_age A 2 B 1\naxiom: A(0)\nA(x) -> A(1) B(0)");
    assert!(timed.timed() && !timed.stepwise());
}

#[test]
fn a_terminal_age_too_small_for_the_clock_is_an_error_not_a_module_never_replaced() {
    // The clock takes moments 1e-9 apart as one: a terminal age of 1e-9 was accepted and never
    // reached (B stayed B(0.00001, 0) at t = 0.00001 instead of being replaced 10,000 times).
    for age in ["0.000000001", "1e-9", "0.0000005"] {
        let src = format!("#terminal_age B {age}\naxiom: B(0, 0)\nB(t, n) -> B(0, n + 1)");
        let codes = errors(&src);
        assert_eq!(codes.len(), 1, "{codes:?}");
        assert_eq!(codes[0].0, "E0211");
        assert_eq!(codes[0].1, age);
    }
    // A millionth is the least, and it is reached: ten rounds by t = 0.00001.
    let src = "#terminal_age B 0.000001\naxiom: B(0, 0)\nB(t, n) -> B(0, n + 1)";
    assert_eq!(at(src, 0.00001), "B(0,10)");
}
