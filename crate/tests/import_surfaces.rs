//! vlab objects with cpfg surfaces (`.s` files named by the view file's `surface:` lines): their
//! patches become `#surface` / `#patch` lines and the plant draws them; a malformed `.s` gives a
//! note with its file and line, and the plant draws Meristem's own leaf or petal instead.
//! Native only: it reads the corpus from disk.
#![cfg(not(target_arch = "wasm32"))]

mod shared;

use meristem::import::{self, Import, ObjectFile};
use meristem::mesh::build_mesh_with_parts;
use meristem::pipeline::{build, Build, BuildOptions};
use meristem::turtle::SurfaceKind;
use shared::object;
use std::path::PathBuf;

fn corpus(name: &str) -> Vec<ObjectFile> {
    object(
        &PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("tests/import-corpus/vlab")
            .join(name),
    )
}

fn built(import: &Import) -> Build {
    let b = build(&import.text, &BuildOptions::default());
    assert!(b.ok(), "{:?}", b.diagnostics);
    b
}

/// The surfaces drawn of each declared shape, and the vertices their parts of the mesh hold.
fn drawn(b: &Build) -> (Vec<usize>, usize) {
    let s = &b.plant.skeleton;
    let mut counts = vec![0; s.shapes.len()];
    for surface in &s.surfaces {
        if let SurfaceKind::Declared(k) = surface.kind {
            counts[k as usize] += 1;
        }
    }
    let (_, parts) = build_mesh_with_parts(s, &b.plant.mesh_options);
    let vertices = parts.surfaces.iter().map(|p| p.vertices as usize).sum();
    (counts, vertices)
}

/// Vertices of one drawn surface: both sides of each patch's grid.
fn per_surface(b: &Build, k: usize) -> usize {
    let shape = &b.plant.skeleton.shapes[k];
    let [s, t] = shape.precision.map(|n| n as usize + 1);
    2 * shape.patches.len() * s * t
}

/// Imports the corpus object `name`, checks that no note is about a surface and that it declares
/// `shapes` (letter, patches), builds it and checks that the mesh holds every drawn surface's
/// vertices. Returns the text and the surfaces drawn of each shape.
fn imported(name: &str, shapes: [(char, usize); 2]) -> (String, Build, Vec<usize>) {
    let import = import::import_object(&corpus(name));
    let notes: Vec<&str> = import.notes.iter().map(|n| n.message.as_str()).collect();
    assert!(!notes.iter().any(|n| n.contains("surface")), "{notes:?}");
    let b = built(&import);
    let declared: Vec<(char, usize)> = b
        .plant
        .skeleton
        .shapes
        .iter()
        .map(|s| (s.letter, s.patches.len()))
        .collect();
    assert_eq!(declared, shapes);
    let (counts, vertices) = drawn(&b);
    let expected = counts[0] * per_surface(&b, 0) + counts[1] * per_surface(&b, 1);
    assert_eq!(vertices, expected);
    (import.text, b, counts)
}

#[test]
fn lychnis_draws_its_petals_and_leaves_from_its_s_files() {
    let (text, b, counts) = imported("01-Lychnis", [('p', 1), ('l', 1)]);
    // plant.v: `surface: p petal.s 2 6 6`, `surface: l leaf.s 6 6 10`; petal.s's header.
    let petal = "#surface p contact 23.44 4.08 -9.23 end 23.63 5.46 -8.91 heading 0.01 1 0.03 up 0.02 -0.03 1 size 39.46 scale 2 precision 6 6\n";
    assert!(text.contains(petal), "{text}");
    assert!(text.contains("#patch p 21.18 5.46 -9.72, 12.57 15 4.03, -5.96 55.04 -10.39,"));
    assert!(text.contains(" scale 6 precision 6 10\n#patch l "));
    // Every flower has 5 petals (K(t) → five R(t), each with its ~p).
    assert_eq!(counts[0] % 5, 0);
    assert_eq!(per_surface(&b, 0), 2 * 7 * 7);
    assert_eq!(per_surface(&b, 1), 2 * 7 * 11);
    // Regression values of this translation (cpfg cannot run here).
    assert_eq!(counts, [LYCHNIS_PETALS, LYCHNIS_LEAVES]);
}

const LYCHNIS_PETALS: usize = 240;
const LYCHNIS_LEAVES: usize = 130;

#[test]
fn lilac_draws_its_four_patch_calyx_and_its_petals() {
    let (text, _, counts) = imported("Lilac", [('p', 1), ('c', 4)]);
    let calyx = "#surface c contact 0 0 370 end 0 0 -0.46 heading 0.01 0.01 -1 up 0.01 -1 -0.01 size 370 scale 2 precision 5 5\n";
    assert!(text.contains(calyx), "{text}");
    // plant.l's flower K: one calyx ~c(4) and four petals ~p(P_SIZE).
    assert_eq!(counts[0], 4 * counts[1]);
    // Regression values of this translation (cpfg cannot run here).
    assert_eq!(counts, [LILAC_PETALS, LILAC_CALYCES]);
}

const LILAC_PETALS: usize = 2472;
const LILAC_CALYCES: usize = 618;

#[test]
fn a_malformed_s_file_is_a_note_with_its_line_and_the_plant_still_builds() {
    let mut files = corpus("01-Lychnis");
    let petal = files
        .iter_mut()
        .find(|f| f.name == "petal.s")
        .expect("petal.s");
    let text = String::from_utf8_lossy(&petal.bytes).replace("Y: 1.00 Z: 0.03", "Y: x Z: 0.03");
    petal.bytes = text.into_bytes();
    let import = import::import_object(&files);
    let note = import
        .notes
        .iter()
        .find(|n| n.message.contains("surface p"))
        .expect("a note on the petal");
    assert_eq!(
        note.message,
        "the view file's surface p is read from petal.s, which cannot be read (petal.s, line 4: 'Y: x' is not a number): ~p draws Meristem's own petal"
    );
    let b = built(&import);
    assert_eq!(b.plant.skeleton.shapes.len(), 1);
    assert!(b
        .plant
        .skeleton
        .surfaces
        .iter()
        .any(|s| s.kind == SurfaceKind::Petal));
}

#[test]
fn any_bytes_as_s_files_never_crash_the_import_or_the_build() {
    let base = corpus("01-Lychnis");
    let good = base
        .iter()
        .find(|f| f.name == "leaf.s")
        .expect("leaf.s")
        .bytes
        .clone();
    let mut cases: Vec<Vec<u8>> = vec![Vec::new(), vec![0xff; 40], b"1 2 3 4 5 6\n".to_vec()];
    for cut in (0..good.len()).step_by(37) {
        cases.push(good[..cut].to_vec());
    }
    // A patch repeated past the limit of 64.
    let text = String::from_utf8_lossy(&good).into_owned();
    let patch_at = text.find("patch").unwrap_or(0);
    cases.push(format!("{}{}", text, text[patch_at..].repeat(70)).into_bytes());
    for bytes in cases {
        let mut files = base.clone();
        files
            .iter_mut()
            .find(|f| f.name == "leaf.s")
            .expect("leaf.s")
            .bytes = bytes;
        let import = import::import_object(&files);
        let b = build(&import.text, &BuildOptions::default());
        assert!(b.ok(), "{:?}", b.diagnostics);
    }
}
