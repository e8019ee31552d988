//! Criterion benchmarks of the whole pipeline and of the mesh stage, natively, on the workloads of
//! issue 4 (`npm run bench` runs the same ones in WebAssembly): a tree the size of seed 001's from
//! grammar text to mesh arrays, and a million tube vertices.

use criterion::{criterion_group, criterion_main, Criterion};
use meristem::mesh::MeshOptions;
use meristem::{build, BuildOptions};
use std::hint::black_box;

fn example(file: &str) -> String {
    let path = format!("{}/../public/examples/{file}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("pipeline");
    group.sample_size(20);
    let tree = example("game-tree.lsys");
    let vertices = build(&tree, &BuildOptions::default()).mesh.vertex_count();
    group.bench_function(
        format!("game-tree.lsys text to mesh ({vertices} vertices)"),
        |b| {
            b.iter(|| {
                black_box(
                    build(black_box(&tree), &BuildOptions::default())
                        .mesh
                        .positions
                        .len(),
                )
            })
        },
    );
    let ten_sides = MeshOptions {
        sides: 10,
        ..MeshOptions::default()
    };
    let mut big = build(
        &example("abop-2.08a-ternary-tree.lsys"),
        &BuildOptions {
            iterations: Some(9),
            mesh: ten_sides.clone(),
            ..BuildOptions::default()
        },
    );
    let vertices = big.mesh.vertex_count();
    group.bench_function(
        format!("ABOP 2.8a n=9 mesh stage ({vertices} vertices)"),
        |b| {
            b.iter(|| {
                big.remesh(black_box(&ten_sides));
                black_box(big.mesh.positions.len())
            })
        },
    );
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
