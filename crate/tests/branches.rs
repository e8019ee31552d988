//! Editing branches by their Bézier handles (issue 8), from the outside: the tree the size of
//! seed 001's, every gallery example, edits travelling in every export and on the command line.

use glam::DVec3;
use meristem::branches::{parse_edits, write_edits, BranchEdit};
use meristem::export::{self, Format};
use meristem::maths;
use meristem::mesh::MeshBuffers;
use meristem::pipeline::{build, BuildOptions, Plant, PlantEditor};
use std::path::PathBuf;
use std::process::Command;

fn example_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../public/examples")
        .join(name)
}

fn example(name: &str) -> String {
    std::fs::read_to_string(example_path(name)).expect("example exists")
}

/// Starts editing a plant.
fn edit(plant: Plant) -> PlantEditor {
    PlantEditor::new(plant)
}

/// The size of the plant (its bounding box's diagonal), at least 1.
fn size(mesh: &MeshBuffers) -> f32 {
    let [min, max] = mesh.bounds();
    let d = (0..3)
        .map(|k| (max[k] - min[k]).powi(2))
        .sum::<f64>()
        .sqrt();
    d.max(1.0) as f32
}

/// The build's mesh against a full re-mesh of its (edited) skeleton: positions and normals within
/// `tolerance` times the plant's size, everything else exactly.
fn assert_equals_full_remesh(b: &PlantEditor, tolerance: f32, what: &str) {
    let mut full = b.clone();
    full.remesh(&b.plant().mesh_options.clone());
    let (m, f) = (&b.plant().mesh, &full.plant().mesh);
    assert_eq!(m.indices, f.indices, "{what}: indices");
    assert_eq!(m.ranges, f.ranges, "{what}: provenance");
    assert_eq!(m.color_ranges, f.color_ranges, "{what}: colour ranges");
    assert_eq!(m.colors, f.colors, "{what}: colours");
    let eps = tolerance * size(f);
    let worst = |a: &[f32], b: &[f32]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0f32, f32::max)
    };
    assert_eq!(m.positions.len(), f.positions.len(), "{what}");
    let (p, n) = (
        worst(&m.positions, &f.positions),
        worst(&m.normals, &f.normals),
    );
    assert!(
        p <= eps && n <= tolerance,
        "{what}: positions off by {p}, normals by {n}"
    );
    assert_eq!(m.check(), Ok(()), "{what}");
}

#[test]
fn the_game_tree_has_a_branch_per_drawn_apex_and_a_drag_rebuilds_a_third_of_it() {
    let mut b = edit(build(&example("game-tree.lsys"), &BuildOptions::default()).plant);
    let info = b.branches();
    // Every A that drew (1 + 3 + 9 + 27 + 81 + 243) is one branch of 9 segments.
    assert_eq!(info.len(), 364);
    assert!(info.iter().all(|i| i.segments.len() == 9));
    assert_eq!(info[0].path, vec![0]);
    assert_eq!(info[0].children.len(), 3);
    let bough = b.tree().find(&[0, 0]).unwrap();
    let below = b.tree().subtree(bough).len();
    assert_eq!(below, 1 + 3 + 9 + 27 + 81);
    let p3 = info[bough as usize].control[3];
    let vertices = b.plant().mesh.vertex_count();
    for frame in 0..4 {
        let change = b
            .drag(bough, 3, p3 + DVec3::new(0.05 * frame as f64, -0.1, 0.08))
            .unwrap();
        assert!(!change.full, "{change:?}");
        // About a third of the tree is re-meshed, never all of it.
        assert!(change.vertices() > vertices / 5 && change.vertices() < vertices / 2);
        assert_equals_full_remesh(&b, 1e-6, "game tree");
    }
}

/// The path of a branch with descendants in the middle of the tree, if any.
fn middle_branch(b: &PlantEditor) -> Option<u32> {
    let info = b.branches();
    let deepest = info.iter().map(|i| i.path.len()).max()?;
    let with_children: Vec<usize> = (0..info.len())
        .filter(|&k| !info[k].children.is_empty())
        .collect();
    with_children
        .iter()
        .copied()
        .find(|&k| info[k].path.len() == deepest.div_ceil(2).max(2))
        .or_else(|| with_children.first().copied())
        .or(Some(0))
        .map(|k| k as u32)
}

#[test]
fn every_gallery_example_has_a_tree_of_its_segments_and_drags_like_a_full_remesh() {
    let dir = example_path("");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.ends_with(".lsys"))
        .collect();
    names.sort();
    let mut dragged = 0;
    for name in &names {
        let built = build(&example(name), &BuildOptions::default());
        if built.plant.skeleton.segments.len() > 30_000 || !built.plant.mesh.lines.is_empty() {
            continue; // big plants: the test would take minutes in a debug build
        }
        let mut b = edit(built.plant);
        let tree = b.tree().clone();
        // Every segment is in exactly one branch; children attach at their parent's end.
        let mut seen = vec![0; b.plant().skeleton.segments.len()];
        for branch in &tree.branches {
            for &s in &branch.segments {
                seen[s as usize] += 1;
            }
            if let Some(parent) = branch.parent {
                let last = *tree.branches[parent as usize].segments.last().unwrap();
                assert_eq!(
                    b.plant().skeleton.segments[branch.segments[0] as usize].anchor,
                    Some(last),
                    "{name}"
                );
            }
        }
        assert!(seen.iter().all(|&n| n == 1), "{name}");
        let Some(branch) = middle_branch(&b) else {
            continue;
        };
        let p3 = b.branches()[branch as usize].control[3];
        let length = tree.branches[branch as usize].length;
        let full = b
            .drag(branch, 3, p3 + DVec3::new(0.03, 0.02, 0.05) * length)
            .unwrap()
            .full;
        assert_equals_full_remesh(&b, 1e-5, name);
        dragged += !full as u32;
    }
    assert!(dragged > 20, "only {dragged} examples took a partial drag");
}

/// Every file of every format: (name, bytes).
fn exports(plant: &Plant) -> Vec<(String, Vec<u8>)> {
    Format::ALL
        .into_iter()
        .flat_map(|f| export::export(f, &plant.mesh, &plant.skeleton, "plant"))
        .map(|f| (f.name, f.bytes))
        .collect()
}

const LEAFY: &str = "#angle 22.5\n#width 3\naxiom: A\n\
    A -> !(2)F[&(30)FL@O(0.05)A]/(137)[&(30)F{.+f.-f.-f.}A]F/(90)A\nL -> ~l(0.4)";

#[test]
fn edits_travel_in_every_export() {
    let options = BuildOptions {
        iterations: Some(3),
        ..BuildOptions::default()
    };
    let unedited = build(LEAFY, &options);
    let edits = vec![BranchEdit {
        path: vec![0, 1],
        handles: [
            DVec3::ZERO,
            DVec3::new(0.0, 0.3, 0.1),
            DVec3::new(0.1, 0.5, -0.2),
        ],
    }];
    let mut edited = edit(build(LEAFY, &options).plant);
    assert_eq!(edited.apply_edits(&edits).applied, vec![vec![0, 1]]);
    let (before, after) = (exports(&unedited.plant), exports(edited.plant()));
    // Seven files, and POV-Ray's two texture images.
    assert_eq!(before.len(), 9);
    for ((name, a), (_, b)) in before.iter().zip(&after) {
        // The material library of the OBJ holds colours only; the textures are fixed images.
        if name != "plant.mtl" && !name.ends_with(".png") {
            assert_ne!(a, b, "{name} shows the edit");
        }
    }
    // The files are those of a full mesh of the edited skeleton, byte for byte.
    let mut full = edited.clone();
    full.remesh(&edited.plant().mesh_options.clone());
    assert_eq!(exports(full.plant()), after);
    // After drags (partial re-meshes), applying the edits in force writes the same files as a
    // fresh build with them: what the studio's download and the command line do.
    let bough = edited.tree().find(&[0, 0]).unwrap();
    let at = edited.branches()[bough as usize].control[2];
    for k in 1..4 {
        edited
            .drag(bough, 2, at + DVec3::new(0.0, 0.0, 0.02 * k as f64))
            .unwrap();
    }
    let now = edited.edits();
    assert_eq!(now.len(), 2);
    let document = write_edits(&now);
    let mut fresh = edit(build(LEAFY, &options).plant);
    fresh.apply_edits(&parse_edits(&document).unwrap());
    edited.apply_edits(&now);
    assert_eq!(exports(fresh.plant()), exports(edited.plant()));
}

fn meristem(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_meristem"))
        .args(args)
        .output()
        .expect("run meristem");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn the_command_line_applies_an_edits_file() {
    let dir = std::env::temp_dir().join(format!("meristem-branches-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let grammar = dir.join("leafy.lsys");
    std::fs::write(&grammar, LEAFY).unwrap();
    let grammar = grammar.to_str().unwrap();
    let edits = vec![
        BranchEdit {
            path: vec![0, 0],
            handles: [DVec3::ZERO, DVec3::ZERO, DVec3::new(0.0, 0.4, 0.0)],
        },
        BranchEdit {
            path: vec![0, 9],
            handles: [DVec3::ZERO; 3],
        },
    ];
    let file = dir.join("edits.json");
    std::fs::write(&file, write_edits(&edits)).unwrap();
    let file = file.to_str().unwrap();
    let out = dir.join("plant.glb");
    let out = out.to_str().unwrap();
    let (code, _, err) = meristem(&["export", grammar, "-o", out, "-n", "3", "--edits", file]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        err,
        format!(
            "{file}: warning: the edit of branch [0, 9] does not apply: no branch at this path: branch [0] has 3 child branches\n"
        )
    );
    let built = build(
        LEAFY,
        &BuildOptions {
            iterations: Some(3),
            ..BuildOptions::default()
        },
    );
    let unedited = export::export(
        Format::Glb,
        &built.plant.mesh,
        &built.plant.skeleton,
        "plant",
    );
    let mut b = edit(built.plant);
    b.apply_edits(&edits);
    let plant = b.plant();
    let expected = export::export(Format::Glb, &plant.mesh, &plant.skeleton, "plant");
    let written = std::fs::read(out).unwrap();
    assert_eq!(written, expected[0].bytes);
    assert_ne!(written, unedited[0].bytes);
    // Stats see the edited plant; a malformed document fails before building.
    let (code, stats, _) = meristem(&["derive", grammar, "-n", "3", "--stats", "--edits", file]);
    assert_eq!(code, 0);
    assert_eq!(stats.trim(), b.plant().stats.to_json());
    let bad = dir.join("bad.json");
    std::fs::write(&bad, "{\"version\": 7, \"edits\": []}").unwrap();
    let bad = bad.to_str().unwrap();
    let (code, _, err) = meristem(&["derive", grammar, "--stats", "--edits", bad]);
    assert_eq!(code, 2);
    assert!(err.contains("newer Meristem"), "{err}");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn an_edits_file_with_a_byte_order_mark_applies_and_a_wrong_one_says_what_is_wrong() {
    let dir = std::env::temp_dir().join(format!("meristem-edits-bom-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let grammar = dir.join("leafy.lsys");
    std::fs::write(&grammar, LEAFY).unwrap();
    let grammar = grammar.to_str().unwrap();
    let edits = vec![BranchEdit {
        path: vec![0, 0],
        handles: [DVec3::ZERO, DVec3::ZERO, DVec3::new(0.0, 0.4, 0.0)],
    }];
    let stats_with = |name: &str, bytes: Vec<u8>| {
        let file = dir.join(name);
        std::fs::write(&file, bytes).unwrap();
        meristem(&[
            "derive",
            grammar,
            "-n",
            "3",
            "--stats",
            "--edits",
            file.to_str().unwrap(),
        ])
    };
    let plain = stats_with("plain.json", write_edits(&edits).into_bytes());
    assert_eq!(plain.0, 0, "{}", plain.2);
    // As Notepad writes UTF-8: a byte order mark first, CRLF at the end.
    let with_bom = stats_with(
        "bom.json",
        [
            &b"\xef\xbb\xbf"[..],
            write_edits(&edits).as_bytes(),
            b"\r\n",
        ]
        .concat(),
    );
    assert_eq!(with_bom, plain, "the same plant, no message");
    let unedited = meristem(&["derive", grammar, "-n", "3", "--stats"]);
    assert_ne!(plain.1, unedited.1, "the edit did apply");
    // Four handles: said in words, naming the edit.
    let (code, _, err) = stats_with(
        "four.json",
        br#"{"version": 1, "edits": [{"path": [0, 0], "handles": [[0,0,0],[0,0,0],[0,0,0],[0,0,0]]}]}"#.to_vec(),
    );
    assert_eq!(code, 2);
    assert!(
        err.ends_with("four.json: edit 0: \"handles\" must hold 3 points (P1, P2, P3), not 4\n"),
        "{err}"
    );
    let (code, _, err) = stats_with(
        "short.json",
        br#"{"version": 1, "edits": [{"path": [0, 0], "handles": [[0,0,0],[0,0,0],[1,2]]}]}"#
            .to_vec(),
    );
    assert_eq!(code, 2);
    assert!(
        err.contains("edit 0: handle P3 must be 3 numbers (heading, left, up), not 2 numbers"),
        "{err}"
    );
    std::fs::remove_dir_all(dir).ok();
}

/// A small deterministic generator (xorshift64*), so the property test needs no crate and
/// repeats exactly.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    /// Uniform in [-1, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

#[test]
fn whatever_a_drag_accepts_the_edits_document_holds_and_the_core_reads_back() {
    // Plants with branches of ordinary, tiny and huge lengths: the same world distance is a
    // different number of branch lengths on each.
    let grammars = [
        LEAFY,
        "#angle 30\naxiom: F(1e-9)[+F(1e-9)]F(1e-9)[-F(5)]F(1e-300)",
        "#angle 25\naxiom: F(1e6)[+F(1e-6)[-F(1)]F(1e6)]F(3)",
    ];
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let (mut accepted, mut refused) = (0, 0);
    for grammar in grammars {
        let built = build(
            grammar,
            &BuildOptions {
                iterations: Some(2),
                ..BuildOptions::default()
            },
        );
        let mut b = edit(built.plant.clone());
        let info = b.branches();
        assert!(!info.is_empty(), "{grammar}");
        for _ in 0..300 {
            let branch = (rng.next() % info.len() as u64) as u32;
            let handle = 1 + (rng.next() % 3) as usize;
            let at = b.control_points(branch)[handle];
            // Targets from a hair to 1e12 away, in random directions.
            let scale = maths::powf(10.0, -8.0 + 20.0 * (rng.unit() + 1.0) / 2.0);
            let target = at + DVec3::new(rng.unit(), rng.unit(), rng.unit()) * scale;
            let before = b.edits();
            match b.drag(branch, handle, target) {
                Ok(_) => accepted += 1,
                Err(e) => {
                    refused += 1;
                    assert!(
                        matches!(e, meristem::branches::DragError::OutOfReach(_)),
                        "{e}"
                    );
                    assert_eq!(b.edits(), before, "a refused drag changes nothing");
                }
            }
            // Every document the editor writes is one the same core reads back, unchanged, and
            // applies whole to a fresh editor of the same plant.
            let document = write_edits(&b.edits());
            let read = parse_edits(&document)
                .unwrap_or_else(|e| panic!("{grammar}: a drag made an unreadable document: {e}"));
            assert_eq!(read, b.edits());
            let mut fresh = edit(built.plant.clone());
            let report = fresh.apply_edits(&read);
            assert!(report.not_applied.is_empty(), "{report:?}");
            assert_eq!(fresh.edits(), read);
        }
    }
    assert!(
        accepted > 300 && refused > 100,
        "both kinds of target were tried: {accepted} accepted, {refused} refused"
    );
}
