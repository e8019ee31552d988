//! Times derivation of the ratio workloads natively (minimum and median of repeated runs):
//! `cargo run --release --example derive_time [A D1 D2 E]`.

use meristem::derive::{derive, DeriveOptions};
use meristem::model::{resolve, Model};
use meristem::syntax::parse;
use std::time::Instant;

fn model(text: &str) -> Model {
    let (syntax, _) = parse(text);
    let (model, diagnostics) = resolve(&syntax);
    assert!(
        !meristem::diagnostics::has_errors(&diagnostics),
        "{diagnostics:?}"
    );
    model.expect("model")
}

fn time(name: &str, text: &str, steps: u32, seed: Option<u64>) {
    let model = model(text);
    let options = DeriveOptions {
        steps,
        seed,
        time: None,
    };
    let len = derive(&model, &options).expect("derives").string.len();
    let mut times = Vec::new();
    let start = Instant::now();
    while times.len() < 5 || (start.elapsed().as_secs_f64() < 1.0 && times.len() < 1000) {
        let t = Instant::now();
        let n = derive(&model, &options).expect("derives").string.len();
        times.push(t.elapsed().as_secs_f64() * 1e3);
        assert_eq!(n, len);
    }
    times.sort_by(f64::total_cmp);
    println!(
        "{name:<12} {len:>9} modules  min {:.3} ms  median {:.3} ms  ({} runs)",
        times[0],
        times[times.len() / 2],
        times.len()
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let on = |w: &str| args.is_empty() || args.iter().any(|a| a == w);
    if on("A") {
        time("A n=10", "axiom: X\nX -> F[+X]F[-X]+X\nF -> FF\n", 10, None);
    }
    if on("D1") {
        for len in [10_000usize, 1_000_000] {
            let text = format!("axiom: b{}\nb < a -> b\nb -> a\n", "a".repeat(len - 1));
            time(&format!("D1 {len}"), &text, 10, None);
        }
    }
    if on("D2") {
        let d2 = "#ignore + - F\naxiom: F1F1F1\n0 < 0 > 0 -> 0\n0 < 0 > 1 -> 1[+F1F1]\n\
                  0 < 1 > 0 -> 1\n0 < 1 > 1 -> 1\n1 < 0 > 0 -> 0\n1 < 0 > 1 -> 1F1\n\
                  1 < 1 > 0 -> 0\n1 < 1 > 1 -> 0\n* < + > * -> -\n* < - > * -> +\n";
        time("D2 n=30", d2, 30, None);
        time("D2 n=50", d2, 50, None);
    }
    if on("DR") {
        let x = "X".repeat(100_000);
        time(
            "DR",
            &format!("axiom: {x}\nX -> (0.5) X\nX -> (0.5) X\n"),
            10,
            Some(7),
        );
        time(
            "NODR",
            &format!("axiom: {x}\nX -> X\nZ -> (1) Z\n"),
            10,
            Some(7),
        );
    }
    if on("E") {
        let e = "axiom: X\nX -> (0.5) F[+X]F[-X]+X\nX -> (0.5) F[-X]F[+X]-X\nF -> FF\n";
        time("E n=11", e, 11, Some(7));
    }
}
