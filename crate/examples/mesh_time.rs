//! The mesh stage of ABOP 1.24d at n = 10 (116,050 segments), natively: minimum of repeated
//! remeshes, and the exact-point lookups alone. `cargo run --release --example mesh_time`.
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
    let mut best = f64::MAX;
    for _ in 0..5 {
        let t = Instant::now();
        let j = parts::joint_keys(&built.plant.skeleton);
        let s = parts::start_keys(&built.plant.skeleton);
        best = best.min(t.elapsed().as_secs_f64());
        std::hint::black_box((j, s));
    }
    println!("joint + start keys: {:.2} ms", best * 1e3);
    // What they replaced: both key lists sorted through crate::sort.
    let mut best = f64::MAX;
    for _ in 0..5 {
        let t = Instant::now();
        for points in [0, 1] {
            let mut keys: Vec<[u64; 3]> = built
                .plant
                .skeleton
                .segments
                .iter()
                .map(|s| meristem::mesh::joint_key(if points == 0 { s.end } else { s.start }))
                .collect();
            meristem::sort::sort(&mut keys);
            std::hint::black_box(keys);
        }
        best = best.min(t.elapsed().as_secs_f64());
    }
    println!("(both keys sorted as before: {:.2} ms)", best * 1e3);
    let options = MeshOptions::default();
    let mut best = f64::MAX;
    for _ in 0..10 {
        let t = Instant::now();
        built.remesh(&options);
        best = best.min(t.elapsed().as_secs_f64());
    }
    let v = built.plant.mesh.vertex_count() as f64;
    println!(
        "mesh stage: {:.2} ms, {:.2} ms per million vertices",
        best * 1e3,
        best * 1e3 / (v / 1e6)
    );
}
