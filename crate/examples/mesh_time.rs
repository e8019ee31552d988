//! The mesh stage of ABOP 1.24d at n = 10 (116,050 segments), natively: minimum of repeated
//! remeshes; the chains, their caps and rounded ends, and packing normals and colours for the GPU,
//! alone. `cargo run --release --example mesh_time`.
//! `-- N R`: ABOP 1.24d at n = N; with R, only R remeshes and nothing timed, for counting the
//! instructions of one remesh on a busy machine (valgrind's cachegrind, R = 4 against R = 0).

use meristem::mesh::{parts, MeshOptions};
use meristem::{build, BuildOptions};
use std::time::Instant;

fn main() {
    let path = format!(
        "{}/../public/examples/abop-1.24d.lsys",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(path).expect("public/examples/abop-1.24d.lsys");
    let iterations: u32 = std::env::args()
        .nth(1)
        .map_or(10, |a| a.parse().expect("N: a number of steps"));
    let mut built = build(
        &text,
        &BuildOptions {
            iterations: Some(iterations),
            ..BuildOptions::default()
        },
    );
    if let Some(remeshes) = std::env::args().nth(2) {
        let options = MeshOptions::default();
        for _ in 0..remeshes.parse::<u32>().expect("R: a number of remeshes") {
            built.remesh(&options);
        }
        println!("{} vertices", built.plant.mesh.vertex_count());
        return;
    }
    let skeleton = &built.plant.skeleton;
    println!(
        "{} segments, {} vertices",
        skeleton.segments.len(),
        built.plant.mesh.vertex_count()
    );
    let unit = meristem::mesh::resolve_width_unit(skeleton, MeshOptions::default().width_unit);
    let ms = fastest(5, || {
        std::hint::black_box(parts::chains(skeleton, unit));
    });
    println!("chains: {ms:.2} ms");
    let chains = parts::chains(skeleton, unit);
    let ms = fastest(5, || {
        std::hint::black_box(parts::chain_ends(skeleton, chains.iter()));
    });
    println!(
        "caps and rounded ends of {} chains: {ms:.2} ms",
        chains.len()
    );
    let mesh = &built.plant.mesh;
    let ms = fastest(10, || {
        std::hint::black_box(meristem::mesh::pack_normals(&mesh.normals));
    });
    println!("normals packed for the GPU: {ms:.2} ms");
    let ms = fastest(10, || {
        std::hint::black_box(meristem::mesh::pack_colors(&mesh.colors));
    });
    println!("colours packed for the GPU: {ms:.2} ms");
    let options = MeshOptions::default();
    let ms = fastest(10, || built.remesh(&options));
    let v = built.plant.mesh.vertex_count() as f64;
    println!(
        "mesh stage: {ms:.2} ms, {:.2} ms per million vertices",
        ms / (v / 1e6)
    );
}

/// The shortest of `runs` runs of `f`, in milliseconds.
fn fastest(runs: u32, mut f: impl FnMut()) -> f64 {
    let mut best = f64::MAX;
    for _ in 0..runs {
        let t = Instant::now();
        f();
        best = best.min(t.elapsed().as_secs_f64());
    }
    best * 1e3
}
