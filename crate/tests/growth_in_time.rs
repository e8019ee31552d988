//! Growth in time (docs/LANGUAGE.md, "Growth in time"): the growth arrays of the mesh, counted by
//! hand on small grammars, and the invariants every plant's growth keeps.

use meristem::export::animation::Animation;
use meristem::export::Format;
use meristem::mesh::{growth_schedule, mesh_at, MeshBuffers, MeshOptions};
use meristem::pipeline::{build, export, Build, BuildOptions, ExportError, ExportOptions, Hooks};

/// The build of `source` with `n` iterations and the growth arrays; `lines`: the lines fallback
/// (one growth entry per line end, two per segment).
fn grown(source: &str, n: u32, lines: bool) -> Build {
    let mut mesh = MeshOptions {
        growth: true,
        ..MeshOptions::default()
    };
    if lines {
        mesh.max_vertices = 0;
    }
    let b = build(
        source,
        &BuildOptions {
            iterations: Some(n),
            mesh,
            ..BuildOptions::default()
        },
    );
    assert!(b.ok(), "{source}: {:?}", b.diagnostics);
    b
}

/// (t0, t1) of each segment, from the lines fallback's growth times.
fn segment_times(mesh: &MeshBuffers) -> Vec<(f32, f32)> {
    assert_eq!(mesh.growth_times.len(), 2 * mesh.lines.len() / 3);
    mesh.growth_times
        .chunks_exact(4)
        .map(|t| {
            assert_eq!(
                (t[0], t[1]),
                (t[2], t[3]),
                "both ends of a line grow together"
            );
            (t[0], t[1])
        })
        .collect()
}

#[test]
fn a_line_that_doubles_is_drawn_from_its_base() {
    // F -> FF, n = 3: 1, 2, 4, 8 segments; the plant at step n is the first 2^n of them.
    let b = grown("axiom: F\nF -> FF", 3, true);
    assert_eq!(b.step_counts, vec![1.0, 2.0, 4.0, 8.0]);
    let times = segment_times(&b.plant.mesh);
    let expected = [
        (-1.0, 0.0),
        (0.0, 1.0),
        (1.0, 1.5),
        (1.5, 2.0),
        (2.0, 2.25),
        (2.25, 2.5),
        (2.5, 2.75),
        (2.75, 3.0),
    ];
    assert_eq!(times.len(), expected.len());
    for (got, want) in times.iter().zip(expected) {
        assert!(
            (got.0 - want.0).abs() < 1e-5 && (got.1 - want.1).abs() < 1e-5,
            "{times:?}"
        );
    }
    // Each line grows from its own start.
    let mesh = &b.plant.mesh;
    for (k, line) in mesh.lines.chunks_exact(6).enumerate() {
        assert_eq!(&mesh.growth_origins[6 * k..6 * k + 3], &line[..3]);
        assert_eq!(&mesh.growth_origins[6 * k + 3..6 * k + 6], &line[..3]);
    }
}

#[test]
fn each_segment_has_its_growth_times_whatever_the_mesh() {
    // The Lines mode's mesh (no tubes, a leaf): the leaf's vertices carry growth arrays, and every
    // segment its times, those of its line in the lines fallback (F -> FF's, counted above).
    let source = "axiom: F~l\nF -> FF";
    let fallback = grown(source, 3, true);
    let by_lines: Vec<f32> = segment_times(&fallback.plant.mesh)
        .into_iter()
        .flat_map(|(t0, t1)| [t0, t1])
        .collect();
    assert_eq!(fallback.plant.mesh.segment_growth_times, by_lines);
    let b = build(
        source,
        &BuildOptions {
            iterations: Some(3),
            mesh: MeshOptions {
                growth: true,
                tubes: false,
                ..MeshOptions::default()
            },
            ..BuildOptions::default()
        },
    );
    let mesh = &b.plant.mesh;
    mesh.check().unwrap();
    assert_eq!(mesh.segment_growth_times, by_lines);
    assert_eq!(mesh.segment_growth_times.len(), 2 * 8);
    assert_eq!(&mesh.segment_growth_times[..2], [-1.0, 0.0]);
    assert!(mesh.segment_growth_times.iter().all(|&t| t <= 3.0));
    assert!(mesh.vertex_count() > 0 && mesh.growth_times.len() == 2 * mesh.vertex_count());
    // Without the option: none.
    let plain = build(
        source,
        &BuildOptions {
            iterations: Some(3),
            ..BuildOptions::default()
        },
    );
    assert!(plain.plant.mesh.segment_growth_times.is_empty());
}

#[test]
fn a_branching_plant_has_each_steps_number_of_elements_at_that_step() {
    // F -> F[+F]F, n = 2: 1, 3, 9 segments.
    let b = grown("#angle 30\naxiom: F\nF -> F[+F]F", 2, true);
    assert_eq!(b.step_counts, vec![1.0, 3.0, 9.0]);
    let times = segment_times(&b.plant.mesh);
    assert_eq!(times.len(), 9);
    let done_by = |t: f32| times.iter().filter(|s| s.1 <= t + 1e-6).count();
    assert_eq!(done_by(0.0), 1);
    assert_eq!(done_by(1.0), 3);
    assert_eq!(done_by(2.0), 9);
    // The trunk's first segment is the axiom's; the plant grows from it.
    assert_eq!(times[0], (-1.0, 0.0));
}

#[test]
fn leaves_and_polygons_grow_after_the_branch_they_stand_on() {
    let source = "#angle 45\naxiom: A\nA -> F[+A{.-f.+f.+f.}]F[-A~l]A";
    let b = grown(source, 3, false);
    let skeleton = &b.plant.skeleton;
    assert!(!skeleton.polygons.is_empty() && !skeleton.surfaces.is_empty());
    let schedule = growth_schedule(skeleton);
    let segments = skeleton.segments.len();
    let anchor_end = |a: Option<u32>| a.map_or(-1.0, |a| schedule.elements[a as usize].t1);
    for (i, p) in skeleton.polygons.iter().enumerate() {
        let g = schedule.elements[segments + i];
        assert!(g.t0 >= anchor_end(p.anchor), "polygon {i}: {g:?}");
        assert_eq!(g.origin, p.points[0]);
    }
    let surfaces = segments + skeleton.polygons.len();
    for (i, s) in skeleton.surfaces.iter().enumerate() {
        let g = schedule.elements[surfaces + i];
        assert!(g.t0 >= anchor_end(s.anchor), "leaf {i}: {g:?}");
        assert_eq!(g.origin, s.origin);
    }
    b.plant.mesh.check().unwrap();
}

/// The invariants of one build's growth.
fn check_growth(name: &str, b: &Build, n: u32) {
    let mesh = &b.plant.mesh;
    mesh.check().unwrap_or_else(|e| panic!("{name}: {e}"));
    let points = if mesh.positions.is_empty() {
        &mesh.lines
    } else {
        &mesh.positions
    };
    assert_eq!(mesh.growth_times.len(), points.len() / 3 * 2, "{name}");
    for t in mesh.growth_times.chunks_exact(2) {
        assert!(
            -1.0 <= t[0] && t[0] < t[1] && t[1] <= n as f32,
            "{name}: {t:?}"
        );
    }
    // Whole at N, and every vertex on its origin before it starts.
    assert_eq!(&mesh_at(mesh, n as f32), points, "{name}");
    let early = mesh_at(mesh, -1.0);
    let differ = early
        .iter()
        .zip(&mesh.growth_origins)
        .position(|(a, b)| a != b);
    assert_eq!(
        differ,
        None,
        "{name}: {:?}",
        differ.map(|i| (
            early[i],
            mesh.growth_origins[i],
            &mesh.growth_times[i / 3 * 2..i / 3 * 2 + 2]
        ))
    );
    // Just after it starts, an element is tiny.
    let extent = mesh
        .bounds()
        .iter()
        .fold(0.0f64, |m, c| c.iter().fold(m, |m, x| m.max(x.abs())))
        .max(1.0);
    for (v, t) in mesh.growth_times.chunks_exact(2).enumerate() {
        let at = t[0] + (t[1] - t[0]) * 1e-3;
        let moved = mesh_at_vertex(mesh, v, at);
        assert!(
            moved < 1e-3 * extent as f32,
            "{name}: vertex {v} moved {moved}"
        );
    }
    // No element starts before the one it stands on has finished; every element of step k's
    // plant (by count) has finished at k.
    let skeleton = &b.plant.skeleton;
    let schedule = growth_schedule(skeleton);
    for (i, s) in skeleton.segments.iter().enumerate() {
        if let Some(a) = s.anchor {
            let (g, before) = (schedule.elements[i], schedule.elements[a as usize]);
            // (Step 0's plant is whole at 0: its elements all have (−1, 0).)
            let axiom = (g.t0, g.t1) == (-1.0, 0.0);
            assert!(
                axiom || g.t0 >= before.t1,
                "{name}: segment {i} {g:?} on {before:?}"
            );
        }
    }
    let counts = &b.step_counts;
    assert_eq!(counts.len(), n as usize + 1, "{name}");
    let total = schedule.elements.len() as f64;
    for (k, c) in counts.iter().enumerate() {
        let target = (c / counts[n as usize] * total).round() as usize;
        let done = schedule
            .elements
            .iter()
            .filter(|g| g.t1 <= k as f32)
            .count();
        assert!(
            done >= target.min(schedule.elements.len()),
            "{name}: step {k}: {done} < {target}"
        );
    }
}

/// How far vertex `v` is from its origin at time `t`.
fn mesh_at_vertex(mesh: &MeshBuffers, v: usize, t: f32) -> f32 {
    let points = if mesh.positions.is_empty() {
        &mesh.lines
    } else {
        &mesh.positions
    };
    let p = [0, 1, 2].map(|k| points[3 * v + k]);
    let o = [0, 1, 2].map(|k| mesh.growth_origins[3 * v + k]);
    let q = meristem::mesh::grown_position(
        p,
        o,
        [mesh.growth_times[2 * v], mesh.growth_times[2 * v + 1]],
        t,
    );
    (0..3).map(|k| (q[k] - o[k]).powi(2)).sum::<f32>().sqrt()
}

#[test]
fn every_plant_grows_within_its_steps_and_is_whole_at_the_end() {
    let grammars = [
        ("doubling", "axiom: F\nF -> FF", 4),
        ("abop 1.24b", "#angle 20\naxiom: F\nF -> F[+F]F[-F][F]", 3),
        (
            "abop 1.24d",
            "#angle 20\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF",
            4,
        ),
        (
            "leaves",
            "#angle 45\naxiom: A\nA -> F[+A{.-f.+f.+f.}]F[-A~l]A",
            3,
        ),
        ("spheres", "#angle 30\naxiom: A\nA -> F[&A@O(0.2)]/(90)A", 3),
        (
            "homomorphism",
            "#angle 30\naxiom: A\nA -> A[+A]A\nhomomorphism:\nA -> FF",
            2,
        ),
        (
            "decomposition",
            "#angle 30\naxiom: A\nA -> A[+A]B\ndecomposition:\nB -> FF",
            2,
        ),
        (
            "nothing drawn at first",
            "#angle 30\naxiom: X\nX -> F[+X][-X]",
            3,
        ),
        ("zero steps", "axiom: F[+F]F", 0),
        ("smooth", "#angle 30\naxiom: @Gc X @Ge\nX -> F[+X]F-X", 3),
    ];
    for (name, source, n) in grammars {
        check_growth(name, &grown(source, n, false), n);
        check_growth(name, &grown(source, n, true), n);
    }
}

#[test]
fn a_joint_is_not_drawn_ahead_of_the_segment_growing_into_it() {
    // Two segments in a chain: while the first grows, the second (not started) is all on its
    // origin, the first's end: no tube reaches ahead of the growing tip.
    let b = grown("axiom: F\nF -> FF", 1, false);
    let mesh = &b.plant.mesh;
    let at = mesh_at(mesh, 0.5);
    for (v, t) in mesh.growth_times.chunks_exact(2).enumerate() {
        if t[0] >= 0.5 {
            let o = &mesh.growth_origins[3 * v..3 * v + 3];
            assert_eq!(&at[3 * v..3 * v + 3], o, "vertex {v}");
        }
    }
    // The tip of the growing segment is below its end at 0.5.
    let highest = at.chunks_exact(3).map(|p| p[1]).fold(f32::MIN, f32::max);
    let full = mesh
        .positions
        .chunks_exact(3)
        .map(|p| p[1])
        .fold(f32::MIN, f32::max);
    assert!(highest < 0.9 * full, "{highest} {full}");
}

#[test]
fn without_the_option_the_mesh_has_no_growth_and_the_same_vertices() {
    let source = "#angle 20\n#iterations 3\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF";
    let plain = build(source, &BuildOptions::default());
    assert!(plain.plant.mesh.growth_times.is_empty() && plain.step_counts.is_empty());
    let b = grown(source, plain.derived_with.steps, false);
    // The same surface: the same bounds, each segment's own start ring added.
    assert_eq!(plain.plant.mesh.bounds(), b.plant.mesh.bounds());
    assert!(b.plant.mesh.vertex_count() > plain.plant.mesh.vertex_count());
    assert_eq!(
        plain.plant.mesh.triangle_count(),
        b.plant.mesh.triangle_count()
    );
}

#[test]
fn the_vertex_budget_counts_the_growth_arrays() {
    let source = "#angle 20\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF";
    let four = BuildOptions {
        iterations: Some(4),
        ..BuildOptions::default()
    };
    let plain = build(source, &four);
    let vertices = plain.plant.mesh.vertex_count();
    // A budget the plain mesh fits in, but not the mesh with 20 bytes more per vertex.
    let mesh = MeshOptions {
        growth: true,
        max_vertices: vertices + vertices / 10,
        ..MeshOptions::default()
    };
    let b = build(
        source,
        &BuildOptions {
            iterations: Some(4),
            mesh,
            ..BuildOptions::default()
        },
    );
    assert!(b.plant.mesh.positions.is_empty() && !b.plant.mesh.lines.is_empty());
    assert_eq!(
        b.plant.mesh.growth_times.len(),
        2 * b.plant.mesh.lines.len() / 3
    );
}

/// The JSON chunk of a GLB.
fn glb_json(glb: &[u8]) -> serde_json::Value {
    let length = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    serde_json::from_slice(&glb[20..20 + length]).unwrap()
}

/// The GLB of `source` after `n` steps, with `animation`.
fn export_glb(source: &str, n: u32, animation: Option<Animation>) -> Result<Vec<u8>, ExportError> {
    let options = ExportOptions {
        build: BuildOptions {
            iterations: Some(n),
            ..BuildOptions::default()
        },
        format: Format::Glb,
        stem: "plant".into(),
        edits: None,
        look: Default::default(),
        animation,
    };
    export(source, &options, &mut Hooks::default()).map(|e| e.files[0].bytes.clone())
}

#[test]
fn the_gltf_animation_has_a_morph_target_per_keyframe_and_ends_whole() {
    let source = "#angle 20\naxiom: FX\nX -> F[+X]F[-X]+X\nF -> FF";
    let animation = Animation {
        seconds_per_step: 2.0,
        targets_per_step: 3,
    };
    let glb = export_glb(source, 3, Some(animation)).unwrap_or_else(|_| panic!("exported"));
    let json = glb_json(&glb);
    // 3 steps × 3 targets, and a last keyframe that is the whole plant.
    for p in json["meshes"][0]["primitives"].as_array().unwrap() {
        assert_eq!(p["targets"].as_array().unwrap().len(), 9);
    }
    assert_eq!(json["meshes"][0]["weights"].as_array().unwrap().len(), 9);
    let sampler = &json["animations"][0]["samplers"][0];
    assert_eq!(sampler["interpolation"], "LINEAR");
    let input = &json["accessors"][sampler["input"].as_u64().unwrap() as usize];
    assert_eq!(input["count"], 10);
    assert_eq!(input["max"][0], 6.0);
    let output = &json["accessors"][sampler["output"].as_u64().unwrap() as usize];
    assert_eq!(output["count"], 10 * 9);
    let channel = &json["animations"][0]["channels"][0]["target"];
    assert_eq!(
        (channel["node"].as_u64(), channel["path"].as_str()),
        (Some(0), Some("weights"))
    );
    // Without the option, the same plant's file has no animation.
    let plain = export_glb(source, 3, None).unwrap_or_else(|_| panic!("exported"));
    assert!(glb_json(&plain).get("animations").is_none());
}

#[test]
fn a_gltf_animation_past_its_limit_is_refused_with_a_message() {
    let source = "#angle 20\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF";
    let animation = Animation {
        seconds_per_step: 1.0,
        targets_per_step: 16,
    };
    match export_glb(source, 8, Some(animation)) {
        Err(ExportError::Refused(message)) => {
            assert!(message.contains("fewer targets per step"), "{message}")
        }
        _ => panic!("exported past the limit"),
    }
}

#[test]
fn the_cli_writes_frames_of_the_growth() {
    let dir = std::env::temp_dir().join(format!("meristem-growth-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let grammar = dir.join("plant.lsys");
    std::fs::write(&grammar, "#angle 20\n#iterations 3\naxiom: F\nF -> F[+F]F").unwrap();
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_meristem"))
            .arg("export")
            .arg(&grammar)
            .args(args)
            .output()
            .unwrap()
    };
    let frames = dir.join("frames");
    let out = run(&["--frames", "4", "-o", frames.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let names: Vec<String> = (0..4).map(|k| format!("frame_{k:03}.svg")).collect();
    let texts: Vec<String> = names
        .iter()
        .map(|n| std::fs::read_to_string(frames.join(n)).unwrap())
        .collect();
    // The same frame (viewBox) on every picture; the plant grows: more drawn at each frame.
    let view_box = |t: &str| {
        t.split("viewBox=\"")
            .nth(1)
            .unwrap()
            .split('"')
            .next()
            .unwrap()
            .to_string()
    };
    assert!(texts.iter().all(|t| view_box(t) == view_box(&texts[0])));
    assert_ne!(texts[0], texts[1]);
    assert_ne!(texts[1], texts[2]);
    // The last frame is the plant's own SVG.
    let whole = dir.join("whole.svg");
    assert!(run(&["-o", whole.to_str().unwrap()]).status.success());
    assert_eq!(texts[3], std::fs::read_to_string(&whole).unwrap());
    // One frame at a time, and limits.
    let at = dir.join("at.svg");
    assert!(run(&["--at", "1.5", "-o", at.to_str().unwrap()])
        .status
        .success());
    assert!(std::fs::read_to_string(&at).unwrap().contains("<svg"));
    let refused = run(&["--frames", "0", "-o", frames.to_str().unwrap()]);
    assert!(!refused.status.success());
    assert!(String::from_utf8_lossy(&refused.stderr).contains("1 to 10000"));
    let refused = run(&[
        "--frames",
        "3",
        "--format",
        "obj",
        "-o",
        frames.to_str().unwrap(),
    ]);
    assert!(String::from_utf8_lossy(&refused.stderr).contains("SVG or PNG pictures"));
    let _ = std::fs::remove_dir_all(&dir);
}
