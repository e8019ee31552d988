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

#[test]
fn an_lpfg_object_draws_its_surface3_leaves_from_its_s_file_where_lpfg_puts_them() {
    // MonopodialSpiral (lpfg): view.v `surface: leaf.s` is surface 0; lsystem.l's leaf L(t) is
    // interpreted as `… Surface3(0, width, length, length)`.
    let import = import::import_object(&corpus("MonopodialSpiral"));
    let notes: Vec<&str> = import.notes.iter().map(|n| n.message.as_str()).collect();
    assert!(!notes.iter().any(|n| n.contains("urface")), "{notes:?}");
    assert!(
        import
            .text
            .contains("#surface l contact 0.02 -1.66 0 size 1 scale 1 precision 10 10\n"),
        "{}",
        import.text
    );
    let leaf = "~l((leaf_width(t/20)),(leaf_length(t/10)),(leaf_length(t/10)))";
    assert!(import.text.contains(leaf), "{}", import.text);
    let b = built(&import);
    let (counts, vertices) = drawn(&b);
    // One leaf per node: 44 internodes (SOURCES.md), each with its leaf.
    assert_eq!(counts, [44]);
    assert_eq!(per_surface(&b, 0), 2 * 11 * 11);
    assert_eq!(vertices, 44 * per_surface(&b, 0));
    // The patch's corner (s, t) = (0, 0) is its first control point p = (−0.60, 1.21, 0.10).
    // lpfg (surface.cpp, glturtle.cpp): left = up × heading = (0,0,−1) × (0,1,0) = (1,0,0);
    // v = (p − contact) read along (−left, heading, up) = (0.62, 2.87, −0.10), drawn at
    // position + sx·v.x·(−L) + sy·v.y·H + sz·v.z·U. lpfg's turtle starts as Meristem's (heading
    // +Y, left −X, up +Z) and turns alike (Left(a) is +(a)), so the corner is at
    // position − sx·0.62·L + sy·2.87·H − sz·0.10·U.
    let s = &b.plant.skeleton.surfaces[0];
    let expected = s.origin - s.left * (s.scale.x * 0.62) + s.heading * (s.scale.y * 2.87)
        - s.up * (s.scale.z * 0.10);
    let (mesh, parts) = build_mesh_with_parts(&b.plant.skeleton, &b.plant.mesh_options);
    let first = parts.surfaces[0].first_vertex as usize;
    let corner = glam::DVec3::new(
        mesh.positions[3 * first] as f64,
        mesh.positions[3 * first + 1] as f64,
        mesh.positions[3 * first + 2] as f64,
    );
    assert!(
        (corner - expected).length() < 1e-4 * (1.0 + expected.length()),
        "{corner} {expected}"
    );
}

#[test]
fn lpfg_surface_ids_are_read_from_defines_and_an_unknown_id_says_why() {
    let leaf = corpus("MonopodialSpiral")
        .into_iter()
        .find(|f| f.name == "leaf.s")
        .expect("leaf.s");
    let file = |name: &str, text: &str| ObjectFile {
        name: name.into(),
        bytes: text.as_bytes().to_vec(),
    };
    let lsystem = "#include <lpfgall.h>\n#define LEAF_SURFACE 1\nderivation length: 1;\nmodule A(float);\nAxiom: A(1);\nA(k): { produce Surface(LEAF_SURFACE, 2) Surface3(0, 1, 2, 3) Surface(7, 1) Surface(k, 1); }\n";
    let mut files = vec![
        file("plant.l", lsystem),
        file("plant.v", "surface: petal.s 1 4 6\nsurface: leaf.s 2\n"),
        ObjectFile {
            name: "petal.s".into(),
            bytes: leaf.bytes.clone(),
        },
        leaf,
    ];
    let import = import::import_object(&files);
    // lpfg numbers the view file's surfaces from 0: petal.s is 0 (~p), leaf.s 1 (~l).
    assert!(
        import.text.contains("A(k) -> ~l(2)~p(1,2,3)~l(1)\n"),
        "{}",
        import.text
    );
    noted(&import, "none with id 7; lpfg ignores the module");
    noted(&import, "Surface(k, …): the surface id k is not a constant Meristem can work out, so Meristem draws ~l, the view file's leaf.s 2 instead");
    let b = built(&import);
    let declared: Vec<char> = b.plant.skeleton.shapes.iter().map(|s| s.letter).collect();
    assert_eq!(declared, ['p', 'l']);
    // ~l(1), drawn for Surface(k, 1), is leaf.s too (the note says so).
    let (counts, _) = drawn(&b);
    assert_eq!(counts, [1, 2]);
    // Without leaf.s, its id is unknown: Meristem's own leaf, with a note.
    files.retain(|f| f.name != "leaf.s");
    let import = import::import_object(&files);
    // Surface(7, 1) too: with a file missing, no id is known to be wrong.
    assert!(import.text.contains("A(k) -> ~l(2)~p(1,2,3)~l(1)~l(1)\n"));
    noted(&import, "surface file leaf.s was not opened");
    noted(&import, "Surface(LEAF_SURFACE, …) draws the view file's surface 1, which was not read (see the notes on the view file): Meristem draws its own leaf ~l instead");
}

/// Fails unless a note of `import` says `what`.
fn noted(import: &Import, what: &str) {
    let notes: Vec<&str> = import.notes.iter().map(|n| n.message.as_str()).collect();
    assert!(notes.iter().any(|n| n.contains(what)), "{what}: {notes:?}");
}
