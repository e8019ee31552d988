//! The branch tree, edits and partial re-meshing against hand-worked cases.

use super::*;
use crate::maths;
use crate::mesh::{build_mesh, MeshBuffers};
use crate::pipeline::{build, Build, BuildOptions, PlantEditor};

fn built(source: &str) -> PlantEditor {
    editor(build(source, &BuildOptions::default()))
}

/// The plant of `source` after `iterations` steps, ready to edit.
fn built_n(source: &str, iterations: u32) -> PlantEditor {
    editor(build(source, &BuildOptions::with_iterations(iterations)))
}

/// The plant of a build that succeeded, ready to edit.
fn editor(result: Build) -> PlantEditor {
    assert!(result.ok(), "{:?}", result.diagnostics);
    PlantEditor::new(result.plant)
}

fn paths(tree: &BranchTree) -> Vec<(Vec<u32>, Vec<u32>)> {
    (tree.branches.iter().enumerate())
        .map(|(k, b)| (tree.path(k as u32), b.segments.clone()))
        .collect()
}

/// The branch tree of `source`'s plant, checked to hold these branches, in order: each its path
/// and its segments.
fn tree_of(source: &str, branches: &[(&[u32], &[u32])]) -> BranchTree {
    let tree = built(source).tree().clone();
    let expected: Vec<(Vec<u32>, Vec<u32>)> = branches
        .iter()
        .map(|(path, segments)| (path.to_vec(), segments.to_vec()))
        .collect();
    assert_eq!(paths(&tree), expected, "{source}");
    tree
}

#[test]
fn an_axis_is_cut_where_a_branch_leaves_and_the_continuation_is_the_last_child() {
    // s0 s1 [s2 s3 [s4] s5] s6 [s7] s8
    let tree = tree_of(
        "axiom: FF[+FF[-F]F]F[-F]F",
        &[
            (&[0], &[0, 1]),
            (&[0, 0], &[2, 3]),
            (&[0, 0, 0], &[4]),
            (&[0, 0, 1], &[5]),
            (&[0, 1], &[6]),
            (&[0, 1, 0], &[7]),
            (&[0, 1, 1], &[8]),
        ],
    );
    assert_eq!(tree.roots, vec![0]);
    assert_eq!(tree.branches[0].children, vec![1, 4]);
    assert_eq!(tree.branches[3].parent, Some(1));
    assert_eq!(tree.find(&[0, 1, 0]), Ok(5));
    assert_eq!(tree.subtree(1), vec![1, 2, 3]);
    // Every segment is in exactly one branch, at its position.
    for (id, branch) in tree.branches.iter().enumerate() {
        for (k, &s) in branch.segments.iter().enumerate() {
            assert_eq!(tree.segment_branch[s as usize], id as u32);
            assert_eq!(tree.segment_position[s as usize], k as u32);
        }
    }
}

#[test]
fn several_roots_and_moves() {
    // Two bracketed roots; `f` inside a branch still grows from the joint; `@M` starts a root.
    tree_of(
        "axiom: [F][+F[fF]]@M(3,0,0)FF",
        &[(&[0], &[0]), (&[1], &[1]), (&[1, 0], &[2]), (&[2], &[3, 4])],
    );
}

#[test]
fn missing_paths_say_how_far_they_exist() {
    let tree = built("axiom: F[+F]F").tree().clone();
    assert_eq!(tree.find(&[]), Err("the path is empty".into()));
    assert_eq!(tree.find(&[1]), Err("the plant has 1 root branch".into()));
    assert_eq!(
        tree.find(&[0, 2]),
        Err("branch [0] has 2 child branches".into())
    );
    assert_eq!(
        tree.find(&[0, 0, 0]),
        Err("branch [0, 0] has 0 child branches".into())
    );
}

#[test]
fn items_belong_to_the_joint_they_are_drawn_at() {
    // A leaf at the end of s0 (inside a bracket), a sphere at the end of s1, a polygon in the
    // lateral from s1.
    let tree = tree_of(
        "axiom: F[&~l]F@O(0.2)[+F{.f.f.}]F",
        &[(&[0], &[0, 1]), (&[0, 0], &[2]), (&[0, 1], &[3])],
    );
    assert_eq!(
        tree.branches[0].items,
        vec![(Item::Surface(0), 0), (Item::Sphere(0), 1)]
    );
    assert_eq!(tree.branches[1].items, vec![(Item::Polygon(0), 0)]);
}

#[test]
fn paths_are_stable_under_re_derivation() {
    let source = "#angle 25\naxiom: X\nX -> F[+X][-X]FX\nF -> FF";
    let (a, b) = (built_n(source, 3), built_n(source, 4));
    let (ta, tb) = (a.tree().clone(), b.tree().clone());
    assert!(tb.len() > ta.len());
    // Each branch of n = 3 is at the same path at n = 4, starting where the same place grew to.
    for k in 0..ta.len() as u32 {
        let path = ta.path(k);
        let other = tb.find(&path).expect("the path still exists");
        let start = |t: &BranchTree, s: &PlantEditor, b: u32| {
            s.plant().skeleton.segments[t.branches[b as usize].segments[0] as usize].start
        };
        assert_eq!(ta.find(&path), Ok(k));
        // F -> FF doubles every length: the same place is twice as far.
        assert!((start(&ta, &a, k) * 2.0 - start(&tb, &b, other)).length() < 1e-9);
    }
}

#[test]
fn a_straight_branch_has_its_handles_at_its_thirds() {
    let b = built("axiom: F(1)F(2)F(3)");
    let info = b.branches();
    assert_eq!(info.len(), 1);
    let c = info[0].control;
    let expected = [0.0, 2.0, 4.0, 6.0].map(|y| glam::DVec3::new(0.0, y, 0.0));
    for k in 0..4 {
        assert!((c[k] - expected[k]).length() < 1e-12, "{c:?}");
    }
    assert_eq!(info[0].params, vec![0.0, 1.0 / 6.0, 0.5, 1.0]);
}

fn dvec(mesh: &[f32], v: usize) -> glam::DVec3 {
    glam::DVec3::new(
        mesh[3 * v] as f64,
        mesh[3 * v + 1] as f64,
        mesh[3 * v + 2] as f64,
    )
}

/// The mesh equals a full mesh of `build`'s skeleton with the editor's options: positions and
/// normals within `eps`, uvs within `eps` relative to their size, everything else exactly.
fn assert_mesh_is_full_mesh(b: &mut PlantEditor, eps: f32) {
    let options = b.branch_editor().options().clone();
    let mut full = build_mesh(&b.plant().skeleton, &options);
    assert_close(&b.plant().mesh, &mut full, eps);
}

fn assert_close(mesh: &MeshBuffers, full: &mut MeshBuffers, eps: f32) {
    assert_eq!(mesh.indices, full.indices);
    assert_eq!(mesh.ranges, full.ranges);
    assert_eq!(mesh.color_ranges, full.color_ranges);
    assert_eq!(mesh.material_ranges, full.material_ranges);
    assert_eq!(mesh.colors, full.colors);
    assert_eq!(mesh.positions.len(), full.positions.len());
    assert_eq!(mesh.uvs.len(), full.uvs.len());
    // A texture coordinate along a tube grows with its length (in circumferences): compare
    // relatively.
    let uv = mesh
        .uvs
        .iter()
        .zip(&full.uvs)
        .map(|(x, y)| (x - y).abs() / y.abs().max(1.0))
        .fold(0.0f32, f32::max);
    assert!(uv <= eps.max(1e-4), "uvs off by {uv}");
    let worst = |a: &[f32], b: &[f32]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0f32, f32::max)
    };
    let (p, n) = (
        worst(&mesh.positions, &full.positions),
        worst(&mesh.normals, &full.normals),
    );
    assert!(p <= eps && n <= eps, "positions off by {p}, normals by {n}");
    assert_eq!(mesh.check(), Ok(()));
}

const LEAFY: &str = "#angle 22.5\n#width 3\naxiom: A\n\
    A -> !(2)F[&(30)FL@O(0.05)A]/(137)[&(30)F{.+f.-f.-f.}A]F/(90)A\nL -> ~l(0.4)\nF -> F";

#[test]
fn a_drag_rebuilds_the_branch_and_moves_its_descendants_like_a_full_mesh() {
    for smooth in [false, true] {
        // Smooth: every axis a generalized cylinder through Bézier pieces.
        let source = LEAFY.replace("axiom: A", if smooth { "axiom: @Gc A" } else { "axiom: A" });
        let mut b = built_n(&source, 4);
        assert!(b
            .plant()
            .skeleton
            .segments
            .iter()
            .all(|s| s.smooth == smooth));
        let before = b.plant().mesh.clone();
        let info = b.branches();
        assert_eq!(
            b.plant().mesh,
            before,
            "starting to edit does not change the mesh"
        );
        // A branch with descendants, neither root nor leaf of the tree.
        let branch = info
            .iter()
            .position(|i| i.path.len() == 3 && !i.children.is_empty())
            .expect("a mid-level branch") as u32;
        let p3 = info[branch as usize].control[3];
        let p1 = info[branch as usize].control[1];
        let mut partial_frames = 0;
        for frame in 1..=5 {
            let f = frame as f64;
            let change = b
                .drag(
                    branch,
                    3,
                    p3 + glam::DVec3::new(0.01 * f, -0.02 * f, 0.015 * f),
                )
                .unwrap();
            let change2 = b
                .drag(branch, 1, p1 + glam::DVec3::new(0.0, 0.0, 0.01 * f))
                .unwrap();
            partial_frames += (!change.full) as u32 + (!change2.full) as u32;
            assert!(change.vertices() > 0 && change.vertices() < b.plant().mesh.vertex_count());
            assert_mesh_is_full_mesh(&mut b, 2e-5);
            assert_eq!(
                b.plant().stats.bounds,
                b.plant().mesh.bounds(),
                "the stats' bounds follow"
            );
            // The handle is where it was dragged.
            let now = b.branches()[branch as usize].control;
            assert!(
                (now[3] - (p3 + glam::DVec3::new(0.01 * f, -0.02 * f, 0.015 * f))).length() < 1e-9
            );
            assert!((now[1] - (p1 + glam::DVec3::new(0.0, 0.0, 0.01 * f))).length() < 1e-9);
        }
        assert_eq!(partial_frames, 10, "no frame needed a full re-mesh");
        // A drag of its parent, then of the branch again: each drag begins from edited places.
        let parent = info[branch as usize].parent.unwrap();
        let q3 = info[parent as usize].control[3];
        for (who, target) in [
            (parent, q3 + glam::DVec3::new(-0.02, 0.01, 0.03)),
            (branch, p3),
        ] {
            for step in [0.5, 1.0] {
                let at = b.branches()[who as usize].control[3];
                let change = b.drag(who, 3, at + (target - at) * step).unwrap();
                assert!(!change.full, "{change:?}");
                assert_mesh_is_full_mesh(&mut b, 2e-5);
            }
        }
        // Only the vertices of the changed ranges moved.
        let change = b
            .drag(
                branch,
                2,
                info[branch as usize].control[2] + glam::DVec3::X * 0.01,
            )
            .unwrap();
        let before = b.plant().mesh.clone();
        let mut inside = vec![false; before.vertex_count()];
        for r in &change.ranges {
            inside[r[0] as usize..(r[0] + r[1]) as usize].fill(true);
        }
        b.drag(
            branch,
            2,
            info[branch as usize].control[2] + glam::DVec3::X * 0.03,
        )
        .unwrap();
        for (v, &changed) in inside.iter().enumerate() {
            if !changed {
                assert_eq!(
                    dvec(&b.plant().mesh.positions, v),
                    dvec(&before.positions, v),
                    "vertex {v}"
                );
            }
        }
    }
}

/// A drag of a plant that grows in time (`MeshOptions::growth`) stays a partial re-mesh, and
/// leaves the growth arrays those of the whole mesh of the same edits: the times the unedited
/// plant's (an edit moves where a branch grows, not when), each vertex's origin where the edit
/// put its element; so the plant drawn at any growth time is the whole mesh's.
#[cfg(feature = "growth")]
#[test]
fn a_drag_keeps_the_growth_in_time_of_a_whole_mesh_of_its_edits() {
    let mut options = BuildOptions::with_iterations(4);
    options.mesh.growth = true;
    let mut b = editor(build(LEAFY, &options));
    let unedited = b.plant().mesh.clone();
    assert!(!unedited.growth_times.is_empty());
    let info = b.branches();
    let branch = info
        .iter()
        .position(|i| i.path.len() == 3 && !i.children.is_empty())
        .expect("a mid-level branch") as u32;
    let p3 = info[branch as usize].control[3];
    let worst = |a: &[f32], b: &[f32]| {
        assert_eq!(a.len(), b.len());
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0f32, f32::max)
    };
    for frame in 1..=3 {
        let f = frame as f64;
        let target = p3 + glam::DVec3::new(0.05 * f, -0.08 * f, 0.04 * f);
        let change = b.drag(branch, 3, target).unwrap();
        assert!(!change.full, "frame {frame}: {change:?}");
        let mut whole = editor(build(LEAFY, &options));
        whole.apply_edits(&b.edits());
        let (mesh, full) = (&b.plant().mesh, &whole.plant().mesh);
        assert_close(mesh, &mut full.clone(), 2e-5);
        assert_eq!(mesh.growth_times, full.growth_times);
        assert_eq!(mesh.growth_times, unedited.growth_times);
        assert_eq!(mesh.segment_growth_times, full.segment_growth_times);
        let origins = worst(&mesh.growth_origins, &full.growth_origins);
        assert!(origins <= 2e-5, "frame {frame}: origins off by {origins}");
        // The moved vertices grow from their new places, not from where they were.
        let moved = change.ranges.iter().any(|r| {
            let (from, to) = (3 * r[0] as usize, 3 * (r[0] + r[1]) as usize);
            worst(
                &mesh.growth_origins[from..to],
                &unedited.growth_origins[from..to],
            ) > 1e-3
        });
        assert!(moved, "frame {frame}: the dragged branch's origins moved");
        for t in [0.5, 1.7, 2.5, 3.2] {
            let at = worst(
                &crate::mesh::mesh_at(mesh, t),
                &crate::mesh::mesh_at(full, t),
            );
            assert!(at <= 4e-5, "frame {frame}, t = {t}: off by {at}");
        }
    }
}

#[test]
fn descendants_move_rigidly() {
    let mut b = built_n(LEAFY, 4);
    let original = b.plant().skeleton.clone();
    let info = b.branches();
    let branch = info.iter().position(|i| i.path == [0, 0]).unwrap() as u32;
    let p3 = info[branch as usize].control[3];
    b.drag(branch, 3, p3 + glam::DVec3::new(0.3, 0.1, -0.2))
        .unwrap();
    let tree = b.tree().clone();
    let below: Vec<u32> = tree.subtree(branch)[1..]
        .iter()
        .flat_map(|&d| tree.branches[d as usize].segments.clone())
        .collect();
    assert!(below.len() > 5);
    let segment = |s: &crate::turtle::Skeleton, i: u32| s.segments[i as usize].clone();
    let mut moved = false;
    for &i in &below {
        let (o, e) = (segment(&original, i), segment(&b.plant().skeleton, i));
        moved |= (o.end - e.end).length() > 1e-3;
        assert!(((o.end - o.start).length() - (e.end - e.start).length()).abs() < 1e-12);
        assert!((e.left.length() - 1.0).abs() < 1e-12 && e.left.dot(e.up).abs() < 1e-12);
        for &j in &below {
            let (p, q) = (segment(&original, j), segment(&b.plant().skeleton, j));
            // Distances between joints and angles between segments are kept.
            assert!(((o.end - p.end).length() - (e.end - q.end).length()).abs() < 1e-12);
            let angle = |a: &crate::turtle::Segment, b: &crate::turtle::Segment| {
                (a.end - a.start)
                    .normalize()
                    .dot((b.end - b.start).normalize())
            };
            assert!((angle(&o, &p) - angle(&e, &q)).abs() < 1e-12);
        }
    }
    assert!(moved, "the descendants moved");
    // What is not below the branch (nor the branch) did not move at all.
    let mine: Vec<u32> = tree
        .subtree(branch)
        .iter()
        .flat_map(|&d| tree.branches[d as usize].segments.clone())
        .collect();
    for i in 0..original.segments.len() as u32 {
        if !mine.contains(&i) {
            assert_eq!(segment(&original, i), segment(&b.plant().skeleton, i));
        }
    }
}

#[test]
fn an_edited_straight_branch_lies_on_its_edited_curve() {
    let mut b = built("axiom: F(1)F(1)F(1)F(1)[+F]");
    let info = b.branches();
    let target = info[0].control[3] + glam::DVec3::new(1.0, 0.0, 0.5);
    b.drag(0, 3, target).unwrap();
    let now = b.branches();
    let joints = b.tree().clone().joints(&b.plant().skeleton, 0);
    for (j, t) in joints.iter().zip(&now[0].params) {
        assert!((fit::point(&now[0].control, *t) - *j).length() < 1e-12);
    }
    // The child still starts at the branch's end.
    assert_eq!(
        b.plant().skeleton.segments[4].start,
        *joints.last().unwrap()
    );
}

#[test]
fn edits_apply_by_path_undo_exactly_and_report_what_does_not_apply() {
    let mut b = built_n(LEAFY, 3);
    let unedited = (b.plant().skeleton.clone(), b.plant().mesh.clone());
    let edits = vec![
        BranchEdit {
            path: vec![0, 0],
            handles: [
                glam::DVec3::ZERO,
                glam::DVec3::new(0.0, 0.2, 0.0),
                glam::DVec3::new(0.1, 0.3, 0.0),
            ],
        },
        BranchEdit {
            path: vec![0, 7, 1],
            handles: [glam::DVec3::ZERO; 3],
        },
        BranchEdit {
            path: vec![3],
            handles: [glam::DVec3::ZERO; 3],
        },
    ];
    let report = b.apply_edits(&edits);
    assert_eq!(report.applied, vec![vec![0, 0]]);
    assert_eq!(
        report.not_applied,
        vec![
            NotApplied {
                path: vec![0, 7, 1],
                reason: "no branch at this path: branch [0] has 3 child branches".into()
            },
            NotApplied {
                path: vec![3],
                reason: "no branch at this path: the plant has 1 root branch".into()
            },
        ]
    );
    assert_ne!(b.plant().mesh.positions, unedited.1.positions);
    assert_eq!(b.edits(), vec![edits[0].clone()]);
    assert_mesh_is_full_mesh(&mut b, 0.0);
    // A later edit of the same branch wins.
    let report = b.apply_edits(&[
        edits[0].clone(),
        BranchEdit {
            path: vec![0, 0],
            handles: [glam::DVec3::ZERO; 3],
        },
    ]);
    assert_eq!(report.applied, vec![vec![0, 0]]);
    assert_eq!(
        report.not_applied[0].reason,
        "a later edit of the same branch replaces it"
    );
    // No edits: exactly the unedited plant.
    let report = b.apply_edits(&[]);
    assert_eq!(report, EditReport::default());
    assert_eq!(
        (b.plant().skeleton.clone(), b.plant().mesh.clone()),
        unedited
    );
}

#[test]
fn edits_survive_re_derivation_with_another_iteration_count() {
    let source = "#angle 25\naxiom: X\nX -> F[+X][-X]FX\nF -> FF";
    let edit = BranchEdit {
        path: vec![0, 1],
        handles: [
            glam::DVec3::ZERO,
            glam::DVec3::new(0.0, 0.1, 0.0),
            glam::DVec3::new(0.0, 0.4, 0.2),
        ],
    };
    for n in [3, 4, 5] {
        let mut b = built_n(source, n);
        let unedited = b.branches();
        let report = b.apply_edits(std::slice::from_ref(&edit));
        assert_eq!(report.applied, vec![vec![0, 1]], "n = {n}");
        let edited = b.branches();
        let k = b.tree().find(&[0, 1]).unwrap() as usize;
        // The end handle moved by the offset: 0.4 branch lengths along L and 0.2 along U of
        // the branch's start frame.
        let length = b.tree().branches[k].length;
        let moved = edited[k].control[3] - unedited[k].control[3];
        assert!(
            (moved.length() - length * maths::hypot(0.4, 0.2)).abs() < 1e-9,
            "n = {n}"
        );
        assert_eq!(edited[k].control[0], unedited[k].control[0]);
        assert_mesh_is_full_mesh(&mut b, 0.0);
    }
}

#[test]
fn a_joint_folded_sharp_rebuilds_the_whole_mesh() {
    let mut b = built("axiom: F(1)F(1)F(1)F(1)F(1)F(1)[+F]F");
    let info = b.branches();
    // P3 pulled back behind the start: the branch folds and its tube must split.
    let change = b
        .drag(0, 3, info[0].control[0] + glam::DVec3::new(0.3, -2.0, 0.0))
        .unwrap();
    assert!(change.full);
    assert!(
        change.reason.as_deref().unwrap().contains("sharp"),
        "{change:?}"
    );
    assert_mesh_is_full_mesh(&mut b, 0.0);
    // Straightened again, it joins: full again, then partial.
    let change = b.drag(0, 3, info[0].control[3]).unwrap();
    assert!(change.full, "{change:?}");
    let change = b
        .drag(0, 3, info[0].control[3] + glam::DVec3::X * 0.01)
        .unwrap();
    assert!(!change.full, "{change:?}");
    assert_mesh_is_full_mesh(&mut b, 1e-5);
}

#[test]
fn a_start_cap_that_appears_rebuilds_the_whole_mesh() {
    // The second root starts exactly at the first's end (by `@M`), so its tube has no start
    // cap; once that end moves away, it needs one.
    let mut b = built("axiom: F(1)F(1)@M(0,2,0)+F");
    let info = b.branches();
    assert_eq!(info.len(), 2);
    let change = b
        .drag(0, 3, info[0].control[3] + glam::DVec3::X * 0.1)
        .unwrap();
    assert!(change.full);
    assert_eq!(
        change.reason.as_deref(),
        Some("a tube's start cap appeared or vanished")
    );
    assert_mesh_is_full_mesh(&mut b, 0.0);
}

#[test]
fn bad_drags_are_errors_not_panics() {
    let mut b = built("axiom: F[+F]F");
    assert!(b
        .drag(3, 1, glam::DVec3::ZERO)
        .unwrap_err()
        .to_string()
        .contains("no branch 3"));
    assert!(b
        .drag(0, 0, glam::DVec3::ZERO)
        .unwrap_err()
        .to_string()
        .contains("handles are 1, 2 and 3"));
    assert!(b
        .drag(0, 1, glam::DVec3::NAN)
        .unwrap_err()
        .to_string()
        .contains("not finite"));
    // A plant with no segment has no branch.
    let mut empty = built("axiom: +");
    assert!(empty.branches().is_empty());
    assert_eq!(
        empty
            .apply_edits(&[BranchEdit {
                path: vec![0],
                handles: [glam::DVec3::ZERO; 3]
            }])
            .not_applied
            .len(),
        1
    );
}

#[test]
fn branch_ranges_name_the_branch_of_every_triangle() {
    let b = built("axiom: FF[+F~l]F");
    let ranges = b.branch_ranges();
    assert_eq!(ranges.len() % 2, 0);
    assert_eq!(ranges[0], 0);
    // The trunk's tube runs through branch 0 (FF) and its continuation, branch 2 (F); then the
    // lateral's tube and its leaf, both branch 1 (one range).
    let branches: Vec<u32> = ranges.chunks(2).map(|p| p[1]).collect();
    assert_eq!(branches, vec![0, 2, 1]);
    let firsts: Vec<u32> = ranges.chunks(2).map(|p| p[0]).collect();
    assert!(firsts.windows(2).all(|w| w[0] < w[1]));
    assert!((*firsts.last().unwrap() as usize) < b.plant().mesh.triangle_count());
}

#[test]
fn the_lines_fallback_is_rebuilt_whole() {
    let mut b = PlantEditor::new(
        build(
            "axiom: F[+F]F",
            &BuildOptions {
                mesh: crate::mesh::MeshOptions {
                    max_vertices: 0,
                    ..crate::mesh::MeshOptions::default()
                },
                ..BuildOptions::default()
            },
        )
        .plant,
    );
    let p3 = b.branches()[0].control[3];
    let change = b.drag(0, 3, p3 + glam::DVec3::X).unwrap();
    assert!(change.full);
    assert_eq!(
        change.reason.as_deref(),
        Some("the mesh is the lines fallback")
    );
    assert_eq!(b.plant().mesh.triangle_count(), 0);
    // The first line is the dragged segment, now ending at the handle.
    let end = glam::DVec3::new(
        b.plant().mesh.lines[3] as f64,
        b.plant().mesh.lines[4] as f64,
        b.plant().mesh.lines[5] as f64,
    );
    assert!((end - (p3 + glam::DVec3::X)).length() < 1e-6);
}

#[test]
fn provenance_still_names_derived_modules_after_drags_and_edits() {
    // With a homomorphism the turtle reads another string; ranges name the derived string.
    let grown = build(
        "#angle 30\naxiom: A\nA -> B[+A][-A]BA\nhomomorphism:\nB -> FF",
        &BuildOptions::with_iterations(3),
    );
    assert!(!grown.derivation.turtle_origin.is_empty());
    let mut b = PlantEditor::new(grown.plant);
    let unedited = b.plant().mesh.ranges.clone();
    let info = b.branches();
    let k = info.iter().position(|i| i.path == [0, 0]).unwrap() as u32;
    let change = b
        .drag(k, 3, info[k as usize].control[3] + glam::DVec3::Y * 0.2)
        .unwrap();
    assert!(!change.full);
    assert_eq!(b.plant().mesh.ranges, unedited);
    let edits = b.edits();
    b.apply_edits(&edits);
    assert_eq!(b.plant().mesh.ranges, unedited);
}
