//! The growth attributes' states within a budget (docs/LANGUAGE.md, "Limits", `E0401`): they
//! follow every module (64 bytes each, for the string before a step and after it), 16 times what
//! the string itself takes, so a raised `#max_modules` let them grow past 2 GB before the module
//! limit stopped the derivation. Measured by counting the bytes the build allocates (its own test
//! binary: the allocator is the whole process's, so this file holds one test).

use meristem::pipeline::{build, BuildOptions};
#[path = "shared/counting.rs"]
mod counting;

#[test]
fn growth_states_stop_at_their_budget_before_they_are_allocated() {
    let source = "#lifetime 1000000 0\n#speed 1 0\n#gravity 5\n#max_modules 40000000\n\
                  axiom: A\nA -> F[+A][-A]\n";
    let options = BuildOptions {
        iterations: Some(12),
        ..BuildOptions::default()
    };
    let (b, peak) = counting::peak_of(|| build(source, &options));
    let error = (b.diagnostics.iter().find(|d| d.code == "E0401"))
        .unwrap_or_else(|| panic!("E0401 expected: {:?}", b.diagnostics));
    assert!(error.message.contains("growth states"), "{}", error.message);
    assert!(
        error.message.contains("budget of 1024 MB"),
        "{}",
        error.message
    );
    // The strings (up to 15 million modules, 4 bytes each, twice), the states of the step
    // before (4.8 million, 64 bytes each), never those of the step refused.
    assert!(peak < 700 << 20, "the build held {} MB at once", peak >> 20);
}
