//! Criterion benchmarks of derivation, natively, on the workloads of `npm run bench` (which runs the
//! same grammars in WebAssembly). Grammars come from the gallery so there is one copy of each.

use criterion::{criterion_group, criterion_main, Criterion};
use meristem::derive::{derive, DeriveOptions};
use meristem::model::{resolve, Model};
use meristem::syntax::parse;
use std::hint::black_box;

/// (gallery file, iterations) — the same list as scripts/bench.mjs.
const WORKLOADS: &[(&str, u32)] = &[
    ("abop-1.24d.lsys", 10),
    ("abop-1.31a-hogeweg.lsys", 30),
    ("abop-1.31a-hogeweg.lsys", 50),
    ("abop-2.08a-ternary-tree.lsys", 8),
    ("abop-1.27-stochastic.lsys", 8),
    ("abop-eq-1.9-proportions.lsys", 16),
];

fn model(file: &str) -> Model {
    let path = format!("{}/../public/examples/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let (syntax, _) = parse(&text);
    let (model, diagnostics) = resolve(&syntax);
    assert!(
        !meristem::diagnostics::has_errors(&diagnostics),
        "{file}: {diagnostics:?}"
    );
    model.expect("model")
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("derive");
    group.sample_size(20);
    for &(file, steps) in WORKLOADS {
        let model = model(file);
        let options = DeriveOptions::of_steps(steps);
        let modules = derive(&model, &options).expect("derives").string.len();
        group.bench_function(format!("{file} n={steps} ({modules} modules)"), |b| {
            b.iter(|| {
                black_box(
                    derive(black_box(&model), &options)
                        .expect("derives")
                        .string
                        .len(),
                )
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
