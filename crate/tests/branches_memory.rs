//! The branch editor's memory grows with the plant, not with the plant times its depth: a comb
//! (each segment of an axis a fork) has branches as deep as it is long, and the tree kept every
//! branch's whole path, n²/2 numbers for n forks: 7 GB for the 60,000 segments the studio lets
//! a user edit, a trap in the page's core. Measured by counting the bytes allocated (its own test
//! binary: the allocator is the whole process's, so this file holds one test).

use meristem::pipeline::{build, BuildOptions, PlantEditor};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};

/// The system allocator, counting the bytes held now and the most held at once.
struct Counting;

static HELD: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let held = HELD.fetch_add(layout.size(), Relaxed) + layout.size();
        PEAK.fetch_max(held, Relaxed);
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        HELD.fetch_sub(layout.size(), Relaxed);
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

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
    let before = HELD.load(Relaxed);
    PEAK.store(before, Relaxed);
    let editor = PlantEditor::new(b.plant);
    let peak = PEAK.load(Relaxed) - before;
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
