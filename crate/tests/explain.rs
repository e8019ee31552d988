//! The explanation of a production (the studio's context-sensitivity view): which modules it
//! rewrote in the last step, which modules served as its contexts, and the counts, checked by hand.

use meristem::{build, BuildOptions};

/// Explains production `p` of `source` after `n` steps: (produced, left, right, rewritten, left
/// and right in the previous string, context matched, condition failed).
fn explain(source: &str, n: u32, p: u32) -> meristem::pipeline::Explained {
    built(source, n)
        .inspector()
        .expect("model")
        .explain(p)
        .expect("a step was taken")
        .expect("no runtime error")
}

#[test]
fn the_signal_of_section_1_8_is_rewritten_by_its_left_context() {
    let source = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../public/examples/abop-sec-1.8-signal.lsys"
    ))
    .unwrap();
    // Step 3 is aaabaaaaa; step 4 is aaaabaaaa. `b < a -> b` rewrote the a at 4, seeing the b at 3.
    let e = explain(&source, 4, 0);
    assert_eq!(e.explanation.rewritten, [4]);
    assert_eq!(e.explanation.left, [3]);
    assert!(e.explanation.right.is_empty());
    assert_eq!(e.explanation.context_matched, 1);
    assert_eq!(e.explanation.condition_failed, 0);
    assert_eq!(e.produced, [4]);
    // The b at 3 became an a, still at 3.
    assert_eq!(e.left, [3]);
    // `b -> a` rewrote the b at 3 (no context).
    let e = explain(&source, 4, 1);
    assert_eq!(e.explanation.rewritten, [3]);
    assert_eq!(e.explanation.context_matched, 1);
    assert!(e.explanation.left.is_empty() && e.left.is_empty());
}

#[test]
fn conditions_are_counted_apart_from_contexts() {
    let e = explain("axiom: A(1)A(2)A(3)\nA(x) < A(y) : y > 2 -> B(x+y)", 1, 0);
    // A(2) and A(3) have a left A; only A(3) passes the condition.
    assert_eq!(e.explanation.context_matched, 2);
    assert_eq!(e.explanation.condition_failed, 1);
    assert_eq!(e.explanation.rewritten, [2]);
    assert_eq!(e.explanation.left, [1]);
    assert_eq!(e.produced, [2]);
}

#[test]
fn contexts_skip_branches_as_in_abop_and_are_found_inside_them() {
    // H's left neighbour on the path to the root is F: the branch [G] is skipped.
    let e = explain("axiom: F[G]H\nF < H -> X", 1, 0);
    assert_eq!(e.explanation.rewritten, [4]);
    assert_eq!(e.explanation.left, [0]);
    // A right context that names a branch is matched inside it: A > [B]C sees B at 2 and C at 4.
    let e = explain("axiom: A[B]C\nA > [B]C -> X", 1, 0);
    assert_eq!(e.explanation.rewritten, [0]);
    assert_eq!(e.explanation.right, [2, 4]);
    // In the new string X[B]C the right context's descendants are B and C.
    assert_eq!(e.right, [2, 4]);
}

#[test]
fn a_production_that_erases_is_explained_from_matching() {
    // `A > B -> ε` erases the A before B; the first A has no B on its right.
    let e = explain("axiom: AAB\nA > B ->", 1, 0);
    assert_eq!(e.explanation.rewritten, [1]);
    assert_eq!(e.explanation.right, [2]);
    assert!(e.produced.is_empty());
    assert_eq!(e.right, [1]); // B is now at 1
}

#[test]
fn stochastic_choices_are_the_ones_the_derivation_made() {
    let source = "#seed 7\naxiom: FFFFFFFFFFFFFFFFFFFF\nF -> (1) A\nF -> (1) B";
    let b = build(
        source,
        &BuildOptions {
            iterations: Some(1),
            ..BuildOptions::default()
        },
    );
    let text = b.derived_text();
    let a = b.inspector().expect("model").explain(0).unwrap().unwrap();
    let expected: Vec<u32> = text
        .char_indices()
        .filter(|(_, c)| *c == 'A')
        .map(|(i, _)| i as u32)
        .collect();
    assert!(!expected.is_empty() && expected.len() < 20, "{text}");
    assert_eq!(a.explanation.rewritten, expected);
    assert_eq!(a.produced, expected);
    assert_eq!(a.explanation.context_matched, 20);
}

#[test]
fn nothing_to_explain_before_the_first_step() {
    let b = build("axiom: A\nA -> B", &BuildOptions::default());
    assert!(b.inspector().expect("model").explain(0).is_none());
}

#[test]
fn a_module_is_explained_by_the_one_rewriting_that_made_it() {
    // Two signals: b at 0 and b at 3 of "babbaa"... keep it plain: A(x) < B -> C(x) twice.
    let source = "axiom: A(1)BA(2)B\nA(x) < B -> C(x)D";
    let b = build(
        source,
        &BuildOptions {
            iterations: Some(1),
            ..BuildOptions::default()
        },
    );
    assert_eq!(b.derived_text(), "A(1)C(1)DA(2)C(2)D");
    // C(2) at 4 came from the B at 3, whose left context is A(2) at 2 (now at 3).
    let e = b
        .inspector()
        .expect("model")
        .explain_module(4)
        .unwrap()
        .unwrap();
    assert_eq!(e.explanation.production, 0);
    assert_eq!(e.explanation.rewritten, [3]);
    assert_eq!(e.explanation.left, [2]);
    assert_eq!(e.produced, [4, 5]);
    assert_eq!(e.left, [3]);
    // The counts still cover the whole string.
    assert_eq!(e.explanation.context_matched, 2);
    // A copied module has nothing to explain.
    assert!(b.inspector().expect("model").explain_module(0).is_none());
}

#[test]
fn the_fingerprint_tells_derivations_apart_and_repeats_for_equal_ones() {
    let run = |source: &str, seed: u64| {
        let b = build(
            source,
            &BuildOptions {
                seed: Some(seed),
                ..BuildOptions::default()
            },
        );
        b.derivation
            .string
            .fingerprint(&b.model.as_ref().unwrap().alphabet)
    };
    let stochastic = "#iterations 4\naxiom: F\nF -> (1) F[+F]F\nF -> (1) F[-F]F";
    assert_eq!(run(stochastic, 5), run(stochastic, 5));
    assert_ne!(run(stochastic, 5), run(stochastic, 6));
    // Parameters count, to the bit.
    assert_ne!(run("axiom: A(1)", 1), run("axiom: A(1.0000001)", 1));
    // Interning order does not: the same string from differently ordered grammars.
    assert_eq!(run("axiom: AB", 1), run("#module B\naxiom: AB", 1));
}

/// `source` built after `n` steps, without errors.
fn built(source: &str, n: u32) -> meristem::Build {
    let b = build(
        source,
        &BuildOptions {
            iterations: Some(n),
            ..BuildOptions::default()
        },
    );
    assert!(b.ok(), "{:?}", b.diagnostics);
    b
}

/// The text of a gallery example.
fn example(file: &str) -> String {
    let path = format!("{}/../public/examples/{file}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(path).unwrap()
}

/// The build's derivation traced ([`meristem::pipeline::Inspector::sequence`]) and each step's
/// string as text.
fn traced(b: &meristem::Build) -> (Vec<meristem::derive::TracedStep>, Vec<String>) {
    let inspector = b.inspector().expect("model");
    let steps = inspector.sequence(1_000).expect("short").expect("derives");
    let texts = steps
        .iter()
        .map(|s| inspector.texts_of(&s.string).concat())
        .collect();
    (steps, texts)
}

#[test]
fn the_derivation_of_eq_1_7_is_the_sequence_of_fig_1_34() {
    let b = built(&example("abop-eq-1.7.lsys"), 4);
    let inspector = b.inspector().expect("model");
    let (steps, texts) = traced(&b);
    assert_eq!(
        texts,
        [
            "B(2)A(4,4)",
            "B(1)B(4)A(1,0)",
            "B(0)B(3)A(2,1)",
            "CB(2)A(4,3)",
            "CB(1)A(8,7)"
        ]
    );
    // Step 1: B(2) became B(1) by its fourth production; A(4,4) became B(4)A(1,0) by the second.
    assert_eq!(steps[1].parent, [0, 1, 1]);
    assert_eq!(steps[1].origin, [3, 1, 1]);
    // Step 3: B(0) became C (the third production); the axiom has no parents.
    assert_eq!(steps[3].origin[0], 2);
    assert!(steps[0].parent.is_empty());
    // The last step is the build's.
    assert_eq!(steps[4].string, b.derivation.string);
    // Too long for the limit: no sequence.
    assert!(inspector.sequence(10).is_none());
}

#[test]
fn a_match_report_says_which_part_of_a_production_failed() {
    // Step 1 reads `b a a c a`: the signal b passes to the a after it, not to the others.
    let source = "axiom: baaca\nb < a > a -> b\na -> a\n";
    let b = built(source, 1);
    let inspector = b.inspector().expect("model");
    // Module 1 of the derived string came from module 1 (the first a): both contexts match.
    let fired = inspector
        .match_report(0, 1)
        .expect("a step")
        .expect("no error");
    assert!(fired.predecessor && fired.left.matched && fired.right.matched);
    assert_eq!(
        (fired.left.modules.clone(), fired.right.modules.clone()),
        (vec![0], vec![2])
    );
    assert_eq!(fired.rewritten_by, Some(0));
    // Module 2 (the second a): its left neighbour is an a, not the b the production wants.
    let left = inspector
        .match_report(0, 2)
        .expect("a step")
        .expect("no error");
    assert!(!left.left.matched);
    assert_eq!(left.left.expected.as_deref(), Some("b"));
    assert_eq!(
        (left.left.found, left.left.found_text.as_deref()),
        (Some(1), Some("a"))
    );
    assert_eq!(left.rewritten_by, Some(1));
    // Module 4 (the last a): no right neighbour at all.
    let right = inspector
        .match_report(0, 4)
        .expect("a step")
        .expect("no error");
    assert!(!right.left.matched || !right.right.matched);
    // Module 3 (c) is not the predecessor.
    let other = inspector
        .match_report(0, 3)
        .expect("a step")
        .expect("no error");
    assert!(!other.predecessor);
    assert_eq!(other.module_text, "c");
}

#[test]
fn a_module_explanation_counts_every_rewriting_of_its_production() {
    // Clicking one F of 1.24d reports how often F -> FF fired, not 1 (issue 17, problem 4).
    let source = "axiom: X\nX -> F[+X]F[-X]+X\nF -> FF\n";
    let b = built(source, 3);
    let inspector = b.inspector().expect("model");
    let whole = inspector.explain(1).expect("a step").expect("no error");
    let f = b
        .derivation
        .origin()
        .iter()
        .position(|&o| o == 1)
        .expect("an F written by F -> FF");
    let one = inspector
        .explain_module(f)
        .expect("a step")
        .expect("no error");
    assert_eq!(one.explanation.fired, whole.explanation.fired);
    assert!(whole.explanation.fired > 1);
    assert_eq!(one.explanation.rewritten.len(), 1);
}

#[test]
fn a_d0l_derivation_writes_its_provenance_when_asked_as_the_traced_derivation_records_it() {
    // The D0L path leaves the last step's provenance to be written when first read (origin and
    // parent); the traced derivation records it as the step runs. They agree module for module,
    // with modules no production rewrites (the brackets, `+`), erased ones and an empty
    // successor among them, after 0, 1 and several steps.
    let sources = [
        "axiom: X\nX -> F[+X]F[-X]+X\nF -> FF\n",
        "axiom: ABA\nA -> AB\nB -> \n",
        "axiom: F-F-F-F\nF -> FF-F-F-F-FF\n",
    ];
    for source in sources {
        let b = built(source, 1);
        let model = b.model.as_ref().expect("model");
        for steps in [0, 1, 4] {
            let options = meristem::derive::DeriveOptions::of_steps(steps);
            let mut none = meristem::derive::Unobserved;
            let lazy = meristem::derive::derive_tracked(model, &options, &mut none).unwrap();
            let (traced, trace) =
                meristem::derive::derive_traced(model, &options, &mut none).unwrap();
            let last = trace.last().expect("the axiom at least");
            assert_eq!(lazy.origin(), last.origin, "{source} after {steps}");
            assert_eq!(lazy.parent(), last.parent, "{source} after {steps}");
            assert_eq!(lazy, traced, "{source} after {steps}");
            assert_eq!(lazy.origin().len(), lazy.string.len());
        }
    }
}

#[test]
fn a_timed_derivation_is_traced_round_by_round_and_ends_with_the_string_at_its_time() {
    // ABOP 6.1's timed Anabaena at t = 2.5: rounds at t = 1 and 2 (every cell has terminal age 1),
    // then every cell half a unit older: b_l(0.5) a_r(0.5) a_r(0.5), the build's string.
    let source = example("abop-6.1-timed-anabaena.lsys");
    let at = |time: f64| {
        let options = BuildOptions {
            time: Some(time),
            ..BuildOptions::default()
        };
        build(&source, &options)
    };
    let b = at(2.5);
    assert!(b.ok(), "{:?}", b.diagnostics);
    let (steps, texts) = traced(&b);
    // Each round's string at its moment: a replaced cell at age 0, the others aged to it.
    assert_eq!(
        texts,
        [
            "a_r(0)",
            "a_l(0)b_r(0)",
            "b_l(0)a_r(0)a_r(0)",
            "b_l(0.5)a_r(0.5)a_r(0.5)"
        ]
    );
    let times: Vec<Option<f64>> = steps.iter().map(|s| s.time).collect();
    assert_eq!(times, [Some(0.0), Some(1.0), Some(2.0), Some(2.5)]);
    // The ageing step rewrites nothing: each module is its own parent.
    assert_eq!(steps[3].parent, [0, 1, 2]);
    assert!(steps[3]
        .origin
        .iter()
        .all(|&o| o == meristem::derive::NOT_REWRITTEN));
    assert_eq!(steps[3].string, b.derivation.string);

    // At a round's own time, no ageing step: the last round is the string at t.
    let (steps, _) = traced(&at(2.0));
    assert_eq!(
        steps.iter().map(|s| s.time).collect::<Vec<_>>(),
        [Some(0.0), Some(1.0), Some(2.0)]
    );
    // Other grammars' steps have no time.
    let (steps, _) = traced(&built("axiom: A\nA -> AB\n", 2));
    assert!(steps.iter().all(|s| s.time.is_none()));
}
