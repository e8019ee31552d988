//! Property: for random bracketed D0L grammars, the engine derives exactly what a naive
//! string-replacement implementation written here derives, on both of its paths (the flat D0L
//! table and the general matcher, forced by adding a production that never applies).
//! Native only: proptest is not a wasm32 dependency (see tests/wasm_boundary.rs for the wasm32 tests).
#![cfg(not(target_arch = "wasm32"))]

use meristem::derive::{derive, DeriveOptions};
use meristem::model::resolve;
use meristem::syntax::parse;
use proptest::prelude::*;
use std::collections::HashMap;

const LETTERS: [char; 6] = ['A', 'B', 'F', 'X', '+', '-'];

/// A balanced bracketed string from a list of choices (each choice picks a letter, opens or closes).
fn bracketed(choices: &[u8]) -> String {
    let mut out = String::new();
    let mut depth = 0;
    for &c in choices {
        match c % 8 {
            6 => {
                out.push('[');
                depth += 1;
            }
            7 if depth > 0 => {
                out.push(']');
                depth -= 1;
            }
            k => out.push(LETTERS[k as usize % LETTERS.len()]),
        }
    }
    out.extend(std::iter::repeat_n(']', depth));
    out
}

fn naive(axiom: &str, rules: &HashMap<char, String>, steps: u32) -> String {
    let mut s = axiom.to_string();
    for _ in 0..steps {
        s = s
            .chars()
            .map(|c| rules.get(&c).cloned().unwrap_or_else(|| c.to_string()))
            .collect();
    }
    s
}

fn engine(source: &str, steps: u32) -> String {
    let (file, diags) = parse(source);
    assert!(diags.is_empty(), "{source}\n{diags:?}");
    let (model, diags) = resolve(&file);
    assert!(
        diags.iter().all(|d| d.code == "E0301"),
        "{source}\n{diags:?}"
    );
    let model = model.expect("model");
    let d = derive(&model, &DeriveOptions::of_steps(steps)).expect("derives");
    d.string.to_text(&model.alphabet)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn random_bracketed_d0l_grammars_match_a_naive_rewriter(
        axiom in prop::collection::vec(any::<u8>(), 1..8),
        successors in prop::collection::vec((0usize..LETTERS.len(), prop::collection::vec(any::<u8>(), 0..7)), 0..5),
        steps in 0u32..5,
    ) {
        let axiom = bracketed(&axiom);
        let mut rules = HashMap::new();
        let mut source = format!("axiom: {axiom}\n");
        for (letter, choices) in &successors {
            let predecessor = LETTERS[*letter];
            if rules.contains_key(&predecessor) {
                continue; // the engine applies the first production; keep the naive side the same
            }
            let successor = bracketed(choices);
            source.push_str(&format!("{predecessor} -> {successor}\n"));
            rules.insert(predecessor, successor);
        }
        let expected = naive(&axiom, &rules, steps);
        prop_assert_eq!(engine(&source, steps), expected.clone(), "D0L path, grammar:\n{}", source);
        // A conditional production for a module that never occurs forces the general path.
        let general = format!("{source}Z : 0 -> Z\n");
        prop_assert_eq!(engine(&general, steps), expected, "general path, grammar:\n{}", general);
    }
}

/// The derived text of `source` after `steps` steps with `seed`, or the error's code.
fn derived(source: &str, steps: u32, seed: u64) -> String {
    let (file, diags) = parse(source);
    assert!(diags.is_empty(), "{source}\n{diags:?}");
    let (model, _) = resolve(&file);
    let model = model.expect("model");
    match derive(
        &model,
        &DeriveOptions {
            steps,
            seed: Some(seed),
            ..Default::default()
        },
    ) {
        Ok(d) => d.string.to_text(&model.alphabet),
        Err(e) => e.code.to_string(),
    }
}

/// One production: predecessor, left and right context (`None`: none), weight, successor.
type Rule = (usize, Option<usize>, Option<usize>, Option<u8>, Vec<u8>);

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Contexts of one module and constant weights take the per-module classes; the same grammar
    /// with a condition that always holds on every production takes the general matcher. Both
    /// derive the same string with the same seed, brackets, `#ignore` and all.
    #[test]
    fn per_module_classes_match_the_general_matcher(
        axiom in prop::collection::vec(any::<u8>(), 1..40),
        rules in prop::collection::vec((0usize..4, prop::option::of(0usize..6), prop::option::of(0usize..6), prop::option::of(0u8..4), prop::collection::vec(any::<u8>(), 0..5)), 0..7),
        ignore in any::<bool>(),
        flat in any::<bool>(),
        steps in 0u32..5,
        seed in any::<u64>(),
    ) {
        // Flat strings (no brackets) take the bulk copy of modules no production touches.
        let shape = |choices: &[u8]| {
            let text = bracketed(choices);
            if flat { text.replace(['[', ']'], "") } else { text }
        };
        let mut head = format!("#max_modules 5000\naxiom: {}\n", shape(&axiom));
        if ignore {
            head.push_str("#ignore + -\n");
        }
        let (mut plain, mut conditioned) = (head.clone(), head);
        for (predecessor, left, right, weight, successor) in &rules as &[Rule] {
            let left = left.map_or(String::new(), |l| format!("{} < ", LETTERS[l]));
            let right = right.map_or(String::new(), |r| format!(" > {}", LETTERS[r]));
            let weight = weight.map_or(String::new(), |w| format!("({w}) "));
            let lhs = format!("{left}{}{right}", LETTERS[*predecessor]);
            let rhs = format!("-> {weight}{}\n", shape(successor));
            plain.push_str(&format!("{lhs} {rhs}"));
            conditioned.push_str(&format!("{lhs} : 1 {rhs}"));
        }
        prop_assert_eq!(
            derived(&plain, steps, seed),
            derived(&conditioned, steps, seed),
            "grammars:\n{}\n{}", plain, conditioned
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// Long flat strings: runs of modules no production touches are found 16 ids at a time
    /// (against at most four hot ids, or through the table when there are more), and a
    /// Fixed/Choice grammar is written by its own loop. The same grammar with a condition that
    /// always holds takes the general matcher; both derive the same string.
    #[test]
    fn long_flat_runs_match_the_general_matcher(
        runs in prop::collection::vec((0usize..6, 1usize..40), 1..12),
        rules in prop::collection::vec((0usize..6, prop::option::of(0usize..6), prop::option::of(0usize..6), prop::option::of(0u8..4), prop::collection::vec(0usize..6, 0..4)), 0..7),
        steps in 0u32..5,
        seed in any::<u64>(),
    ) {
        let axiom: String = runs.iter().flat_map(|&(l, n)| std::iter::repeat_n(LETTERS[l], n)).collect();
        let head = format!("#max_modules 20000\naxiom: {axiom}\n");
        let (mut plain, mut conditioned) = (head.clone(), head);
        for (predecessor, left, right, weight, successor) in &rules {
            let left = left.map_or(String::new(), |l| format!("{} < ", LETTERS[l]));
            let right = right.map_or(String::new(), |r| format!(" > {}", LETTERS[r]));
            let weight = weight.map_or(String::new(), |w| format!("({w}) "));
            let lhs = format!("{left}{}{right}", LETTERS[*predecessor]);
            let successor: String = successor.iter().map(|&l| LETTERS[l]).collect();
            let rhs = format!("-> {weight}{successor}\n");
            plain.push_str(&format!("{lhs} {rhs}"));
            conditioned.push_str(&format!("{lhs} : 1 {rhs}"));
        }
        prop_assert_eq!(
            derived(&plain, steps, seed),
            derived(&conditioned, steps, seed),
            "grammars:\n{}\n{}", plain, conditioned
        );
    }
}

/// [`derived`], with the error's message after its code.
fn derived_or_error(source: &str, steps: u32, seed: u64) -> String {
    let (file, diags) = parse(source);
    assert!(diags.is_empty(), "{source}\n{diags:?}");
    let (model, diags) = resolve(&file);
    let model = model.unwrap_or_else(|| panic!("{source}\n{diags:?}"));
    let options = DeriveOptions {
        steps,
        seed: Some(seed),
        ..Default::default()
    };
    match derive(&model, &options) {
        Ok(d) => d.string.to_text(&model.alphabet),
        Err(e) => format!("{}: {}", e.code, e.message),
    }
}

/// Predecessors of the parametric property: a letter and the names its parameters bind.
const PREDECESSORS: [(&str, &[&str]); 5] = [
    ("A", &["x"]),
    ("A", &["x", "y"]),
    ("B", &["x", "y"]),
    ("C", &["x"]),
    ("C", &[]),
];

/// An argument written with the parameters `names` bound (constants only when none is).
fn argument(names: &[&str], k: u8) -> String {
    let Some(x) = names.get(k as usize % names.len().max(1)) else {
        return ["2", "0.5", "uniform(0, 1)", "1 / 0"][k as usize % 4].to_string();
    };
    let y = names.last().unwrap();
    match k % 16 {
        0 => x.to_string(),
        1 => format!("{x} * 0.9"),
        2 => format!("2 - {x}"),
        3 => format!("{x} + {y}"),
        4 => format!("1 / {x}"),
        5 => format!("{x} / ({y} - {y})"),
        6 => format!("{x} ^ 2"),
        7 => format!("{x} + uniform(0, 1)"),
        8 => "137.5".to_string(),
        9 => format!("{y} * {x} * 3"),
        // The affine shapes (a parameter times or plus a constant), with signed zeros.
        10 => format!("0.5 * {x}"),
        11 => format!("{x} - 0.25"),
        12 => format!("0 - {x}"),
        13 => format!("{x} * 0"),
        14 => format!("{x} + 0"),
        _ => format!("3 + {y}"),
    }
}

/// A successor module from a choice: a parametric letter, a turtle symbol or a branch.
fn successor_module(names: &[&str], c: u8, a: u8, b: u8) -> String {
    let (p, q) = (argument(names, a), argument(names, b));
    match c % 8 {
        0 => format!("A({p})"),
        1 => format!("A({p},{q})"),
        2 => format!("B({p},{q})"),
        3 => format!("C({p})"),
        4 => "C".to_string(),
        5 => format!("F({p})"),
        6 => format!("[+({q})B({p},{q})]"),
        // A cut: a step's output is not the next step's input, its size not carried.
        7 if a.is_multiple_of(4) => "[%C]".to_string(),
        _ => "!".to_string(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Parametric productions without context, condition or weight take the per-module classes
    /// (templates, simple arguments outside the interpreter, copies); the same grammar with a
    /// condition that always holds takes the general matcher. Both derive the same string (the
    /// same numbers, signed zeros included, the same random draws) or fail with the same error,
    /// arities that do not match, divisions by zero, cuts, `#max_modules` and all.
    #[test]
    fn parametric_classes_match_the_general_matcher(
        rules in prop::collection::vec((0usize..5, prop::collection::vec((any::<u8>(), any::<u8>(), any::<u8>()), 0..6)), 0..6),
        unique in any::<bool>(),
        steps in 0u32..5,
        seed in any::<u64>(),
    ) {
        // One production a letter at most: every class is known, and the step is sized first.
        let mut letters = Vec::new();
        let rules: Vec<_> = rules
            .into_iter()
            .filter(|(p, _)| !unique || { let l = PREDECESSORS[*p].0; let new = !letters.contains(&l); letters.push(l); new })
            .collect();
        let head = "#max_modules 3000\naxiom: A(1) B(0,3) C(0.5) A(1,2) C F(1)\n".to_string();
        let (mut plain, mut conditioned) = (head.clone(), head);
        for (predecessor, successor) in &rules {
            let (letter, names) = PREDECESSORS[*predecessor];
            let lhs = if names.is_empty() { letter.to_string() } else { format!("{letter}({})", names.join(",")) };
            let rhs: String = successor.iter().map(|&(c, a, b)| successor_module(names, c, a, b)).collect();
            plain.push_str(&format!("{lhs} -> {rhs}\n"));
            conditioned.push_str(&format!("{lhs} : 1 -> {rhs}\n"));
        }
        prop_assert_eq!(
            derived_or_error(&plain, steps, seed),
            derived_or_error(&conditioned, steps, seed),
            "grammars:\n{}\n{}", plain, conditioned
        );
    }
}
