//! The branch editor's memory grows with the plant, not with the plant times its depth: a comb
//! (each segment of an axis a fork) has branches as deep as it is long, and the tree kept every
//! branch's whole path, n²/2 numbers for n forks: 7 GB for the 60,000 segments the studio lets
//! a user edit, a trap in the page's core. Measured by counting the bytes allocated (its own test
//! binary: the allocator is the whole process's, so this file holds one test).

use meristem::pipeline::{build, BuildOptions, PlantEditor};
#[path = "shared/counting.rs"]
mod counting;

#[test]
fn editing_a_comb_of_20000_forks_holds_megabytes_not_gigabytes() {
    // 2,500 steps of four forks: 20,000 segments, the deepest branch 10,001 deep.
    let source = "#max_steps 20000\naxiom: A\nA -> F[+F]F[+F]F[+F]F[+F]A\n";
    let options = BuildOptions {
        iterations: Some(2_500),
        ..BuildOptions::default()
    };
    let b = build(source, &options);
    assert!(b.ok(), "{:?}", b.diagnostics);
    assert_eq!(b.plant.skeleton.segments.len(), 20_000);
    let (editor, peak) = counting::peak_of(|| PlantEditor::new(b.plant));
    // Its paths whole: 10,000²/2 × 2 numbers of 4 bytes, 400 MB.
    assert!(peak < 64 << 20, "the editor took {} MB", peak >> 20);
    let tree = editor.tree();
    let deepest = (0..tree.len() as u32)
        .max_by_key(|&k| tree.branches[k as usize].depth)
        .expect("branches");
    let path = tree.path(deepest);
    assert_eq!(path.len(), 10_001);
    assert_eq!(tree.find(&path), Ok(deepest));
}
