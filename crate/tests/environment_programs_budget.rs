//! The environment's programs within their budget from the start (docs/LANGUAGE.md, "Limits",
//! `E0408`): what each program starts with (a million attraction points, 24 MB) counts as it is
//! made, so a hundred such lines stop at the third, not after 2.4 GB. Measured by counting the
//! bytes the build allocates (its own test binary: the allocator is the whole process's, so this
//! file holds one test).

use meristem::environment::MAX_ENVIRONMENT_BYTES;
use meristem::pipeline::{build, BuildOptions};
#[path = "shared/counting.rs"]
mod counting;

#[test]
fn a_hundred_programs_of_a_million_points_stop_at_the_one_past_the_budget() {
    let line = "#environment attractors box min -1 -1 -1 max 1 1 1 count 1000000\n";
    let source = format!("{}axiom: F A ?E(0,0,0,0)\nA -> F A\n", line.repeat(100));
    let (b, peak) = counting::peak_of(|| build(&source, &BuildOptions::default()));
    let error = (b.diagnostics.iter().find(|d| d.code == "E0408"))
        .unwrap_or_else(|| panic!("E0408 expected: {:?}", b.diagnostics));
    // The third line: 3 × 24 MB pass the 64 MB.
    assert_eq!(error.span.start, 2 * line.len(), "{}", error.message);
    assert!(
        error.message.contains("beside the 46 MB"),
        "{}",
        error.message
    );
    assert!(
        peak < MAX_ENVIRONMENT_BYTES + (32 << 20),
        "the build held {} MB at once",
        peak >> 20
    );
}
