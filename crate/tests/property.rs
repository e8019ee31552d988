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
    let d = derive(&model, &DeriveOptions { steps, seed: None }).expect("derives");
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
