//! The environment (issue 47; docs/LANGUAGE.md, "Environment"): `#environment`, `#stand` and
//! `#plant` read with their diagnostics, `?E` answered between steps, pruning against an
//! obstacle, stands of plants with their seeds, and a stand exported.

use meristem::export::Format;
use meristem::model::{resolve, EnvironmentSpec, PlantPlace, ProgramSpec, SettingValue};
use meristem::pipeline::{build, export, BuildOptions, ExportOptions, Hooks};
use meristem::vocabulary::{EnvironmentProgram, EnvironmentShape};

/// The diagnostics of resolving `source`: (code, the text its span covers).
fn diagnostics(source: &str) -> Vec<(String, String)> {
    let (file, mut found) = meristem::syntax::parse(source);
    let (_, more) = resolve(&file);
    found.extend(more);
    found
        .iter()
        .map(|d| (d.code.to_string(), source[d.span.clone()].to_string()))
        .collect()
}

fn spec(source: &str) -> EnvironmentSpec {
    let (file, _) = meristem::syntax::parse(source);
    resolve(&file).0.expect("a model").environment
}

fn built(source: &str, iterations: u32) -> meristem::pipeline::Build {
    let options = BuildOptions {
        iterations: Some(iterations),
        ..BuildOptions::default()
    };
    let b = build(source, &options);
    let errors: Vec<_> = b
        .diagnostics
        .iter()
        .filter(|d| d.severity == meristem::diagnostics::Severity::Error)
        .collect();
    assert!(errors.is_empty(), "{errors:?}");
    b
}

#[test]
fn each_wrong_word_has_its_diagnostic_at_the_word() {
    let cases: &[(&str, &str, &str)] = &[
        ("#environment sunlight", "E0230", "sunlight"),
        (
            "#environment obstacle cube min 0 0 0 max 1 1 1",
            "E0230",
            "obstacle",
        ),
        ("#environment light box", "E0230", "box"),
        (
            "#environment attractors plane point 0 0 0 normal 0 1 0",
            "E0230",
            "plane",
        ),
        (
            "#environment obstacle sphere centre 0 0 0 radius 1",
            "E0231",
            "centre",
        ),
        (
            "#environment obstacle sphere center 0 0 radius 1",
            "E0231",
            "center 0 0",
        ),
        (
            "#environment obstacle box min 0 0 0",
            "E0232",
            "#environment obstacle box min 0 0 0",
        ),
        (
            "#environment obstacle sphere center 0 0 0 radius 0",
            "E0231",
            "radius 0",
        ),
        (
            "#environment obstacle box min 0 0 0 max 1 -1 1",
            "E0231",
            "max 1 -1 1",
        ),
        (
            "#environment obstacle plane point 0 0 0 normal 0 0 0",
            "E0231",
            "normal 0 0 0",
        ),
        ("#environment light sky x", "E0203", "x"),
        ("#stand circle 4", "E0233", "circle"),
        ("#stand row 3", "E0233", "row 3"),
        ("#stand row 0 spacing 1", "E0233", "0"),
        (
            "#stand grid 30 30 spacing 1",
            "E0235",
            "grid 30 30 spacing 1",
        ),
        // Past the limit by one count alone: the same error, not "a whole number from 0 to 401".
        ("#stand row 402 spacing 1", "E0235", "row 402 spacing 1"),
        (
            "#stand grid 1e9 1e9 spacing 1",
            "E0235",
            "grid 1e9 1e9 spacing 1",
        ),
        (
            "#stand random 50 size 1 1 spacing 1",
            "E0235",
            "random 50 size 1 1 spacing 1",
        ),
        ("#plant 1 2", "E0234", "1 2"),
    ];
    for (line, code, at) in cases {
        let found = diagnostics(&format!("{line}\naxiom: F ?E(1)"));
        assert_eq!(
            found,
            vec![(code.to_string(), at.to_string())],
            "{line}: {found:?}"
        );
    }
    // 400 plants at most, #stand and #plant together.
    let many = "#stand grid 20 20 spacing 1\n#plant 0 0 0\naxiom: F";
    assert_eq!(diagnostics(many)[0].0, "E0235");
}

#[test]
fn a_full_environment_reads_as_written() {
    let source = "#environment light sun 0.5 sun_direction 0 1 1 cell 0.25\n\
                  #environment obstacle box min -1 0 -1 max 1 2 1\n\
                  #stand row 3 spacing 2\n\
                  #plant 0 0 5\n\
                  axiom: F ?E(0, 0, 0, 0, 0, 0)";
    let s = spec(source);
    let setting = |name: &'static str, values: Vec<f64>, text: &str| SettingValue {
        name,
        values,
        span: source.find(text).map(|a| a..a + text.len()).unwrap(),
    };
    let line = |text: &str| source.find(text).map(|a| a..a + text.len()).unwrap();
    let expected = EnvironmentSpec {
        programs: vec![
            ProgramSpec {
                program: EnvironmentProgram::Light,
                shape: None,
                settings: vec![
                    setting("sun", vec![0.5], "sun 0.5"),
                    setting("sun_direction", vec![0.0, 1.0, 1.0], "sun_direction 0 1 1"),
                    setting("cell", vec![0.25], "cell 0.25"),
                ],
                span: line("#environment light sun 0.5 sun_direction 0 1 1 cell 0.25"),
            },
            ProgramSpec {
                program: EnvironmentProgram::Obstacle,
                shape: Some(EnvironmentShape::Box),
                settings: vec![
                    setting("min", vec![-1.0, 0.0, -1.0], "min -1 0 -1"),
                    setting("max", vec![1.0, 2.0, 1.0], "max 1 2 1"),
                ],
                span: line("#environment obstacle box min -1 0 -1 max 1 2 1"),
            },
        ],
        plants: [
            [-2.0, 0.0, 0.0],
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [0.0, 0.0, 5.0],
        ]
        .iter()
        .enumerate()
        .map(|(i, &position)| PlantPlace {
            position,
            index: i as u32,
        })
        .collect(),
    };
    assert_eq!(s, expected);
    assert_eq!(s.reply_len(), 6);
}

/// A shoot growing up (one unit a step) into a box whose floor is at y = 2.5, asking with `?E`
/// behind its apex. Its reply, hand-checked: after step n the `?E` stands at the apex, at y = n;
/// the distance to the box is 2.5 − n outside, and inside (n = 3, the box 1 wide on each side
/// of x and z) the nearest face is the floor, 0.5 below.
const SHOOT: &str = "#environment obstacle box min -1 2.5 -1 max 1 10 1\n\
                     axiom: A ?E(1, 0)\n\
                     A > ?E(f, d) : f == 1 -> F A\n\
                     A > ?E(f, d) : f == 0 -> B\n";

#[test]
fn a_communication_module_reads_the_obstacle_where_it_stands_after_each_step() {
    assert_eq!(built(SHOOT, 1).derived_text(), "FA?E(1,1.5)");
    assert_eq!(built(SHOOT, 2).derived_text(), "FFA?E(1,0.5)");
    assert_eq!(built(SHOOT, 3).derived_text(), "FFFA?E(0,-0.5)");
    // Step 4's production reads step 3's reply: the apex stops.
    assert_eq!(built(SHOOT, 4).derived_text(), "FFFB?E(0,-0.5)");
    // Without the program the module stays as written (and a warning says what is missing).
    let inert = built(
        SHOOT
            .lines()
            .skip(1)
            .collect::<Vec<_>>()
            .join("\n")
            .as_str(),
        4,
    );
    assert_eq!(inert.derived_text(), "FFFFA?E(1,0)");
    assert!(inert.diagnostics.iter().any(|d| d.code == "E0409"));
}

#[test]
fn a_communication_module_keeps_what_the_reply_does_not_fill() {
    let source = "#environment obstacle sphere center 0 0 0 radius 1\naxiom: F ?E(7) F ?E(7, 7, 7)";
    assert_eq!(built(source, 0).derived_text(), "F?E(1)F?E(1,1,7)");
}

/// A bush that probes one step ahead of each apex (`g` moves there without drawing) and prunes
/// the apex with `%` when that point is inside the box above it; it keeps growing otherwise.
const HEDGE: &str = "#angle 30\n\
                     #seed 5\n\
                     #environment obstacle box min -50 3.5 -50 max 50 60 50\n\
                     axiom: A g ?E(1, 0)\n\
                     A > g ?E(f, d) : f == 1 -> F [ + / A g ?E(1, 0) ] [ - \\ A g ?E(1, 0) ] & A g ?E(1, 0)\n\
                     A > g ?E(f, d) : f == 0 -> %\n";

#[test]
fn pruning_against_a_box_leaves_no_segment_inside_it() {
    let pruned = built(HEDGE, 7);
    let segments = &pruned.plant.skeleton.segments;
    assert!(segments.len() > 20);
    let inside = |p: glam::DVec3| p.x.abs() < 50.0 && p.z.abs() < 50.0 && p.y > 3.5 && p.y < 60.0;
    for s in segments {
        for k in 0..=10 {
            let p = s.start.lerp(s.end, k as f64 / 10.0);
            assert!(!inside(p), "a segment reaches {p} inside the box");
        }
    }
    // The same bush without the box grows into it: the box did the pruning.
    let free = built(&HEDGE.replace("#environment", "// #environment"), 7);
    assert!(free.plant.skeleton.segments.len() > segments.len());
    let top = free
        .plant
        .skeleton
        .segments
        .iter()
        .map(|s| s.end.y)
        .fold(0.0, f64::max);
    assert!(top > 3.5);
}

/// A stochastic grammar, the same in every test below.
const STOCHASTIC: &str = "#angle 25\n\
                          axiom: A ?E(1, 0)\n\
                          A -> (1) F [ + A ] A\n\
                          A -> (1) F [ - A ] A\n\
                          A -> (1) F A\n";

#[test]
fn the_same_seed_gives_the_same_plant() {
    let source = format!("#environment obstacle plane point 0 3 0 normal 0 -1 0\n{STOCHASTIC}");
    let a = built(&source, 6).derived_text();
    assert_eq!(a, built(&source, 6).derived_text());
    let other = build(
        &source,
        &BuildOptions {
            iterations: Some(6),
            seed: Some(2),
            ..BuildOptions::default()
        },
    );
    assert_ne!(a, other.derived_text());
}

/// Plant i of a stand of the grammar derives with the seed `seed + i`: alone with that seed (the
/// obstacle's replies depend on no other plant) it is the same plant.
#[test]
fn a_stand_s_plants_differ_and_each_is_reproducible() {
    let stand = format!("#stand grid 3 3 spacing 4\n#environment obstacle sphere center 0 2 0 radius 1\n{STOCHASTIC}");
    let b = built(&stand, 5);
    assert_eq!(b.plant_offsets.len(), 9);
    assert_eq!(b.plant_offsets[0], [-4.0, 0.0, -4.0]);
    let text = b.derived_text();
    assert_eq!(text, built(&stand, 5).derived_text());
    // `[@M(x,y,z)…]` a plant: its own string is between `)` and the `]` before the next.
    let plants: Vec<&str> = text
        .split("[@M(")
        .skip(1)
        .map(|p| p.split_once(')').unwrap().1)
        .map(|p| p.strip_suffix(']').unwrap_or(p))
        .collect();
    assert_eq!(plants.len(), 9);
    let distinct: std::collections::HashSet<&str> = plants.iter().copied().collect();
    assert!(distinct.len() >= 5, "{plants:?}");
    let single = "#environment obstacle sphere center 0 2 0 radius 1\n".to_string() + STOCHASTIC;
    for (i, plant) in plants.iter().enumerate().step_by(4) {
        let alone = build(
            &single,
            &BuildOptions {
                iterations: Some(5),
                seed: Some(1 + i as u64),
                ..BuildOptions::default()
            },
        );
        // The sphere sits at the origin: plant 4 (the middle one) stands in it.
        if i != 4 {
            let alone_text = alone.derived_text();
            // The same plant; only its reply differs, the obstacle being elsewhere from it.
            let unanswered = |s: &str| s.split("?E(").next().unwrap_or("").to_string();
            assert_eq!(unanswered(plant), unanswered(&alone_text), "plant {i}");
        }
    }
    // Every plant is drawn at its place.
    let skeleton = &b.plant.skeleton;
    for offset in &b.plant_offsets {
        let base = glam::DVec3::from_array(*offset);
        assert!(skeleton
            .segments
            .iter()
            .any(|s| s.start.distance(base) < 1e-9));
    }
}

#[test]
fn a_stand_of_nine_builds_and_exports_gltf() {
    let source = format!("#stand grid 3 3 spacing 3\n{STOCHASTIC}");
    let options = ExportOptions {
        build: BuildOptions {
            iterations: Some(4),
            ..BuildOptions::default()
        },
        format: Format::Glb,
        stem: "stand".into(),
        edits: None,
        look: Default::default(),
        animation: None,
    };
    let exported = export(&source, &options, &mut Hooks::default()).expect("exported");
    let glb = &exported.files[0].bytes;
    assert_eq!(&glb[..4], b"glTF");
    assert_eq!(
        u32::from_le_bytes(glb[8..12].try_into().unwrap()) as usize,
        glb.len()
    );
    let single = export(STOCHASTIC, &options, &mut Hooks::default()).expect("exported");
    let one = single.files[0].bytes.len();
    // (The mesh spends fewer sides on each tube of a larger model: not 9 times the bytes.)
    assert!(
        glb.len() > one,
        "{} bytes for 9 plants, {one} for one",
        glb.len()
    );
    let json_len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let json = std::str::from_utf8(&glb[20..20 + json_len]).expect("a JSON chunk");
    assert!(json.contains("\"meshes\""));
}

#[test]
fn progress_tells_each_step_and_each_answer_pass_in_order() {
    use meristem::pipeline::{build_with, Progress};
    let mut told = Vec::new();
    let mut progress = |p: Progress| match p {
        Progress::Derived { step, steps } => told.push(format!("step {step} of {steps}")),
        Progress::Environment { step, steps } => {
            told.push(format!("{}, step {step} of {steps}", p.label()))
        }
        Progress::Started(_) => {}
    };
    let mut hooks = Hooks {
        clock: None,
        progress: Some(&mut progress),
    };
    let options = BuildOptions {
        iterations: Some(3),
        ..BuildOptions::default()
    };
    let b = build_with(SHOOT, &options, &mut hooks);
    assert!(b.ok());
    let expected = [
        "step 0 of 3",
        "environment, step 0 of 3",
        "step 1 of 3",
        "environment, step 1 of 3",
        "step 2 of 3",
        "environment, step 2 of 3",
        "step 3 of 3",
        "environment, step 3 of 3",
    ];
    assert_eq!(told, expected);
    // No ?E in the string after step 1 (the apex stopped, its ?E gone): no pass, none told.
    let mut told = Vec::new();
    let mut progress = |p: Progress| told.push(p);
    let mut hooks = Hooks {
        clock: None,
        progress: Some(&mut progress),
    };
    let source = "#environment obstacle box min -1 -1 -1 max 1 1 1\n\
                  axiom: A ?E(1, 0)\n\
                  ?E(f, d) -> F\n";
    assert!(build_with(source, &options, &mut hooks).ok());
    let passes: Vec<_> = (told.iter())
        .filter_map(|p| match p {
            Progress::Environment { step, .. } => Some(*step),
            _ => None,
        })
        .collect();
    assert_eq!(passes, [0]);
}

#[test]
fn the_derivation_view_shows_each_step_s_replies() {
    let b = built(SHOOT, 4);
    let model = b.model.as_ref().unwrap();
    let steps = b.inspector().unwrap().sequence(10_000).unwrap().unwrap();
    let texts: Vec<String> = steps
        .iter()
        .map(|s| s.string.to_text(&model.alphabet))
        .collect();
    // The axiom is answered too: its ?E stands at the origin, 2.5 below the box.
    assert_eq!(
        texts,
        [
            "A?E(1,2.5)",
            "FA?E(1,1.5)",
            "FFA?E(1,0.5)",
            "FFFA?E(0,-0.5)",
            "FFFB?E(0,-0.5)"
        ]
    );
}

/// A stand's provenance is each plant's, moved to where the plant sits: every module copied in
/// the last step (written by no production) is the module its parent was, in the placed string
/// before the step; the derivation view's steps place every plant too.
#[test]
fn a_stand_s_provenance_points_into_its_own_plant() {
    let source = format!("#stand row 4 spacing 3\n{STOCHASTIC}\nhomomorphism:\nA -> F(0.5)");
    let b = built(&source, 4);
    let d = &b.derivation;
    let (origin, parent) = (d.origin(), d.parent());
    assert_eq!(origin.len(), d.string.len());
    assert_eq!(parent.len(), d.string.len());
    for i in 0..d.string.len() {
        let p = parent[i] as usize;
        assert!(p < d.previous.len());
        if origin[i] == meristem::derive::NOT_REWRITTEN {
            assert_eq!(d.previous.ids[p], d.string.ids[i], "module {i}");
        }
    }
    // The homomorphism's string maps back into the placed string.
    let shown = d.turtle_string();
    assert_eq!(d.turtle_origin.len(), shown.len());
    let model = b.model.as_ref().unwrap();
    let a = model.alphabet.get("A").unwrap();
    for (k, &i) in d.turtle_origin.iter().enumerate() {
        let from = d.string.ids[i as usize];
        assert!(from == shown.ids[k] || from == a, "module {k}");
    }
    let steps = b.inspector().unwrap().sequence(100_000).unwrap().unwrap();
    assert_eq!(steps.len(), 5);
    for step in &steps {
        assert_eq!(
            step.string.to_text(&model.alphabet).matches("[@M(").count(),
            4
        );
    }
    assert_eq!(steps[4].string, d.string);
}

#[test]
fn a_stand_counts_its_plants_together_against_the_module_limit() {
    // Each plant has 2^6 = 64 modules after 6 steps; the 9 together pass 500.
    let source = "#max_modules 500\n#stand grid 3 3 spacing 1\naxiom: A\nA -> AA";
    let options = BuildOptions {
        iterations: Some(6),
        ..BuildOptions::default()
    };
    let b = build(source, &options);
    let error = b
        .diagnostics
        .iter()
        .find(|d| d.code == "E0400")
        .expect("E0400");
    assert!(
        error.message.contains("9 plants 576 modules"),
        "{}",
        error.message
    );
    assert!(build(
        source,
        &BuildOptions {
            iterations: Some(5),
            ..options
        }
    )
    .ok());
}

#[test]
fn an_answer_pass_counts_what_it_holds_so_a_stand_of_786432_questions_is_answered() {
    // 3 plants of 2^18 = 262,144 ?E after step 19, each answered with the obstacle's two values:
    // their probes, askers and replies (120 bytes each) and one plant's turtle records at a time
    // (80 bytes each) are 111 MB, within the pass's 128 MB. Counted as a turtle record per ?E of
    // every plant at once (200 bytes each, 157 MB) they were refused; twice the plants still are.
    let source = |plants: u32| {
        format!(
            "#environment obstacle sphere center 0 0 0 radius 1\n\
             #stand row {plants} spacing 1\n\
             axiom: B(0)\n\
             B(n) : n < 18 -> B(n + 1) B(n + 1)\n\
             B(n) : n >= 18 -> ?E(5, 5)\n"
        )
    };
    let b = built(&source(3), 19);
    assert!(b.diagnostics.iter().all(|d| d.code != "E0408"));
    let six = build(
        &source(6),
        &BuildOptions {
            iterations: Some(19),
            ..BuildOptions::default()
        },
    );
    let error = six
        .diagnostics
        .iter()
        .find(|d| d.code == "E0408")
        .expect("E0408 for six plants");
    assert!(error.message.contains("1572864 ?E"), "{}", error.message);
    assert!(
        error.message.contains("128 MB for one answer pass"),
        "{}",
        error.message
    );
}

/// A timed grammar (ABOP 6.1) whose stem grows by a growth function of its age, drawn by the
/// homomorphism: the bud on its tip waits while it is free and stops once its stem has carried
/// it into the box.
const TIMED_STEM: &str = "#environment obstacle box min -1 2 -1 max 1 10 1\n\
                          #terminal_age I 1000 A 1\n\
                          axiom: I(0) A(0) ?E(1, 0)\n\
                          A(t) > ?E(f, d) : f == 1 -> A(0)\n\
                          A(t) > ?E(f, d) : f == 0 -> B\n\
                          homomorphism:\n\
                          I(t) -> F(linear(t / 4, 0.5, 4))\n";

#[test]
fn a_timed_plant_is_answered_as_drawn_at_each_step_its_organs_grown() {
    let at = |source: &str, time: f64| {
        let b = build(
            source,
            &BuildOptions {
                time: Some(time),
                ..BuildOptions::default()
            },
        );
        assert!(b.ok(), "{:?}", b.diagnostics);
        assert!(b.diagnostics.is_empty(), "{:?}", b.diagnostics);
        b.derived_text()
    };
    // The stem is 0.5 + 3.5 t / 4 long at t: 1.375 at t = 1 (the bud 0.625 below the box),
    // 2.25 at t = 2 (0.25 inside); the bud reads that at its terminal age, t = 3, and stops.
    assert_eq!(at(TIMED_STEM, 1.0), "I(1)A(0)?E(1,0.625)");
    assert_eq!(at(TIMED_STEM, 2.0), "I(2)A(0)?E(0,-0.25)");
    assert_eq!(at(TIMED_STEM, 3.0), "I(3)B?E(0,-1)");
    // A fraction of a step: answered at the time asked, as drawn then (2.6875 long).
    assert_eq!(at(TIMED_STEM, 2.5), "I(2.5)A(0.5)?E(0,-0.6875)");
    // The derivation view: a row a round and a row at each whole step, as answered then.
    let b = build(
        TIMED_STEM,
        &BuildOptions {
            time: Some(3.0),
            ..BuildOptions::default()
        },
    );
    let model = b.model.as_ref().unwrap();
    let rows: Vec<(Option<f64>, String)> = (b.inspector().unwrap().sequence(100).unwrap())
        .unwrap()
        .iter()
        .map(|s| (s.time, s.string.to_text(&model.alphabet)))
        .collect();
    let expected = [
        (Some(0.0), "I(0)A(0)?E(1,1.5)"),
        (Some(1.0), "I(1)A(0)?E(1,0.625)"),
        (Some(2.0), "I(2)A(0)?E(0,-0.25)"),
        (Some(3.0), "I(3)B?E(0,-1)"),
    ];
    let expected: Vec<(Option<f64>, String)> =
        expected.iter().map(|(t, s)| (*t, s.to_string())).collect();
    assert_eq!(rows, expected);
    // The string itself, without its drawing, leaves the bud at the ground: free for ever.
    let undrawn = TIMED_STEM.replace("I(t) -> F(", "I(t) -> X(");
    assert_eq!(at(&undrawn, 3.0), "I(3)A(0)?E(1,2)");
}

#[test]
fn a_stand_s_plants_grow_with_the_growth_attributes_as_each_alone() {
    // Far from every plant: the obstacle changes no reply, so each plant of the stand is the
    // plant derived alone with its seed, its segments lengthened by #shape and bent by #gravity.
    let plant = "#environment obstacle sphere center 0 100 0 radius 1\n\
                 #lifetime 6 2\n#shape 1.4 3\n#gravity 4 2\n\
                 axiom: A ?E(1, 0)\n\
                 A -> F [+ A ?E(1, 0)] [- A ?E(1, 0)] A\n\
                 ?E(f, d) -> ε\n";
    let stand = format!("#plant 0 0 0\n#plant 10 0 0\n{plant}");
    let lengths = |b: &meristem::pipeline::Build| -> Vec<f64> {
        let mut l: Vec<f64> = (b.plant.skeleton.segments.iter())
            .map(|s| (s.end - s.start).length())
            .collect();
        l.sort_by(f64::total_cmp);
        l
    };
    let options = |seed| BuildOptions {
        iterations: Some(4),
        seed: Some(seed),
        ..BuildOptions::default()
    };
    let both = build(&stand, &options(5));
    assert!(both.ok(), "{:?}", both.diagnostics);
    assert!(
        !both.diagnostics.iter().any(|d| d.code == "E0409"),
        "{:?}",
        both.diagnostics
    );
    let mut alone: Vec<f64> = [5, 6]
        .iter()
        .flat_map(|&seed| lengths(&build(plant, &options(seed))))
        .collect();
    alone.sort_by(f64::total_cmp);
    let together = lengths(&both);
    assert_eq!(together.len(), alone.len());
    assert!(
        together.iter().any(|&l| l > 1.5),
        "#shape lengthens: {together:?}"
    );
    for (a, b) in together.iter().zip(&alone) {
        assert!((a - b).abs() < 1e-9, "{together:?} vs {alone:?}");
    }
}
