//! A sketch build of ABOP 1.24d (the shared benchmark's case F: parse, derive with provenance,
//! the sketch turtle), natively: the minimum over repeated builds of each stage and of the whole.
//! `cargo run --release --example sketch_time [n]` (n = 10 by default: 116,050 segments).

use meristem::pipeline::{build_with, Hooks};
use meristem::BuildOptions;
use std::time::Instant;

fn main() {
    let path = format!(
        "{}/../public/examples/abop-1.24d.lsys",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(path).expect("public/examples/abop-1.24d.lsys");
    let iterations: u32 = std::env::args()
        .nth(1)
        .map_or(10, |a| a.parse().expect("n: a number of steps"));
    let options = BuildOptions {
        iterations: Some(iterations),
        sketch: true,
        ..BuildOptions::default()
    };
    let origin = Instant::now();
    let mut clock = || origin.elapsed().as_secs_f64() * 1e3;
    let mut best = [f64::MAX; 5];
    let mut segments = 0;
    for _ in 0..30 {
        let t = Instant::now();
        let built = build_with(
            &text,
            &options,
            &mut Hooks {
                clock: Some(&mut clock),
                progress: None,
            },
        );
        let whole = t.elapsed().as_secs_f64() * 1e3;
        segments = built.plant.stats.segments;
        let s = built.timings.expect("timings: the build had a clock");
        let t = Instant::now();
        drop(built);
        let dropped = t.elapsed().as_secs_f64() * 1e3;
        for (b, v) in best.iter_mut().zip([
            s.parse_resolve,
            s.derive,
            s.interpret + s.mesh,
            dropped,
            whole,
        ]) {
            *b = b.min(v);
        }
    }
    // The sketch turtle alone, on the derived string.
    let built = meristem::build(&text, &options);
    let model = built.model.as_ref().expect("1.24d resolves");
    let string = built.derivation.turtle_string();
    let mut turtle = f64::MAX;
    for _ in 0..30 {
        let t = Instant::now();
        let sketch = meristem::turtle::sketch(model, string);
        turtle = turtle.min(t.elapsed().as_secs_f64() * 1e3);
        std::hint::black_box(sketch);
    }
    println!("turtle::sketch alone {turtle:.3} ms");
    println!("{segments} segments (n = {iterations}), minimum of 30 builds, ms:");
    for (name, v) in ["parse", "derive", "sketch", "drop", "whole"]
        .iter()
        .zip(best)
    {
        println!("  {name:7} {v:.3}");
    }
}
