//! Criterion benchmarks of the whole pipeline and of the mesh stage, natively, on the workloads of
//! issue 4 (`npm run bench` runs the same ones in WebAssembly): a tree the size of seed 001's from
//! grammar text to mesh arrays, and a million tube vertices; and issue 8's drag frame: one handle
//! of one branch of that tree moved, the branch and its descendants re-placed and re-meshed.

use criterion::{criterion_group, criterion_main, Criterion};
use meristem::mesh::MeshOptions;
use meristem::pipeline::PlantEditor;
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
    let vertices = build(&tree, &BuildOptions::default())
        .plant
        .mesh
        .vertex_count();
    group.bench_function(
        format!("game-tree.lsys text to mesh ({vertices} vertices)"),
        |b| {
            b.iter(|| {
                black_box(
                    build(black_box(&tree), &BuildOptions::default())
                        .plant
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
    let vertices = big.plant.mesh.vertex_count();
    group.bench_function(
        format!("ABOP 2.8a n=9 mesh stage ({vertices} vertices)"),
        |b| {
            b.iter(|| {
                big.remesh(black_box(&ten_sides));
                black_box(big.plant.mesh.positions.len())
            })
        },
    );
    // Issue 8: one drag frame of a branch with descendants (target ≤ 5 ms in wasm).
    for (path, what) in [
        (vec![0, 0], "a bough, 120 descendants"),
        (vec![0, 2, 0], "a mid-level branch, 39 descendants"),
    ] {
        let mut tree_build = PlantEditor::new(build(&tree, &BuildOptions::default()).plant);
        let branch = tree_build.tree().find(&path).expect("the branch exists");
        let p3 = tree_build.branches()[branch as usize].control[3];
        let mut frame = 0u32;
        group.bench_function(
            format!("game-tree.lsys drag one branch {path:?} ({what})"),
            |b| {
                b.iter(|| {
                    frame += 1;
                    let offset = glam::DVec3::new(0.02 * (frame % 8) as f64, -0.05, 0.03);
                    let change = tree_build
                        .drag(branch, 3, black_box(p3 + offset))
                        .expect("a valid drag");
                    assert!(!change.full);
                    black_box(change.vertices())
                })
            },
        );
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
