use meristem::BuildOptions;
fn main() {
    let text = "#angle 20\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF\n";
    let n: u32 = std::env::args().nth(1).map_or(7, |a| a.parse().unwrap());
    let reps: u32 = std::env::args()
        .nth(2)
        .map_or(20000, |a| a.parse().unwrap());
    let options = BuildOptions {
        iterations: Some(n),
        sketch: true,
        ..BuildOptions::default()
    };
    let t = std::time::Instant::now();
    let mut s = 0;
    for _ in 0..reps {
        let b = meristem::build(text, &options);
        s += b.plant.stats.segments;
    }
    println!(
        "{s} {:.1} us/build",
        t.elapsed().as_secs_f64() * 1e6 / reps as f64
    );
}
