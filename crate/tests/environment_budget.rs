//! The environment's answer pass within its budget (docs/LANGUAGE.md, "Environment", Limits): a
//! string of a million `?E` stops with `E0408` before the pass allocates its probes and replies,
//! measured by counting the bytes the build allocates (its own test binary: the allocator is
//! the whole process's, so this file holds one test).

use meristem::environment::MAX_ENVIRONMENT_BYTES;
use meristem::pipeline::{build, BuildOptions};
#[path = "shared/counting.rs"]
mod counting;

#[test]
fn a_million_communication_modules_stop_before_their_answers_are_allocated() {
    // 2^20 = 1,048,576 ?E after step 21, none before: the first pass that runs has them all.
    // Their strings take 16 bytes a module; their answers about 200 each (over 200 MB, above the
    // pass's 128 MB).
    let source = "#environment obstacle sphere center 0 0 0 radius 1\n\
                  axiom: B(0)\n\
                  B(n) : n < 20 -> B(n + 1) B(n + 1)\n\
                  B(n) : n >= 20 -> ?E(0, 0)\n";
    let options = BuildOptions {
        iterations: Some(21),
        ..BuildOptions::default()
    };
    let (b, peak) = counting::peak_of(|| build(source, &options));
    let error = b
        .diagnostics
        .iter()
        .find(|d| d.code == "E0408")
        .unwrap_or_else(|| panic!("E0408 expected: {:?}", b.diagnostics));
    assert!(error.message.contains("1048576 ?E"), "{}", error.message);
    assert!(error.message.contains("after step 21"), "{}", error.message);
    assert!(error.message.contains("128 MB"), "{}", error.message);
    assert_eq!(&source[error.span.clone()], "?E(0, 0)");
    // The strings (about 3 × 16 MB) and nothing of the pass's 200 MB.
    assert!(
        peak < MAX_ENVIRONMENT_BYTES,
        "the build held {peak} bytes at once, above the budget of {MAX_ENVIRONMENT_BYTES}"
    );
}
