//! The shared bench's workload C (the parametric Honda tree, n = 17, 917,498 modules) derived
//! natively: the minimum of repeated derivations. `cargo run --release --example param_time [n]`.
//! Each derivation allocates its strings afresh; to time the derivation rather than the kernel's
//! page faults (WebAssembly keeps its memory), let glibc keep what is freed:
//! `GLIBC_TUNABLES=glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=4000000000`.

use meristem::derive::{derive, DeriveOptions};
use meristem::model::resolve;
use meristem::syntax::parse;
use std::time::Instant;

const C: &str = "#define r1 0.9
#define r2 0.6
#define a0 45
#define a2 45
#define d 137.5
#define wr 0.707
axiom: A(1,10)
A(l,w) -> !(w)F(l)[&(a0)B(l*r2,w*wr)]/(d)A(l*r1,w*wr)
B(l,w) -> !(w)F(l)[-(a2)$C(l*r2,w*wr)]C(l*r1,w*wr)
C(l,w) -> !(w)F(l)[+(a2)$B(l*r2,w*wr)]B(l*r1,w*wr)
";

fn main() {
    let steps: u32 = std::env::args()
        .nth(1)
        .map_or(17, |a| a.parse().expect("a number of steps"));
    let rounds: usize = std::env::args()
        .nth(2)
        .map_or(30, |a| a.parse().expect("a number of rounds"));
    let (syntax, _) = parse(C);
    let (model, _) = resolve(&syntax);
    let model = model.expect("model");
    let options = DeriveOptions::of_steps(steps);
    let mut best = f64::MAX;
    let mut len = 0;
    let mut sum = 0.0;
    for _ in 0..rounds {
        let t = Instant::now();
        let d = derive(&model, &options).expect("derives");
        best = best.min(t.elapsed().as_secs_f64() * 1e3);
        len = d.string.len();
        sum = (0..len)
            .filter(|&i| model.alphabet.name(d.string.ids[i]) == "F")
            .map(|i| d.string.params_of(i)[0])
            .sum::<f64>();
    }
    println!("C n={steps}: {len} modules, sum of F {sum}, best {best:.3} ms");
}
