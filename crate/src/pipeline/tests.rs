//! Builds timed, told, sketched and remeshed: the hooks change nothing but what they are told.

use super::build::MAX_COORDINATE_TEXT;
use super::*;
use crate::mesh::MeshOptions;

/// Hooks with `clock` and no progress.
fn timed<'a>(clock: &'a mut dyn FnMut() -> f64) -> Hooks<'a> {
    Hooks {
        clock: Some(clock),
        progress: None,
    }
}

/// A clock that advances by one unit each time it is read.
fn ticking() -> impl FnMut() -> f64 {
    let mut t = 0.0;
    move || {
        t += 1.0;
        t
    }
}

/// `source` built with `options` and a fresh [`ticking`] clock.
fn build_ticking(source: &str, options: &BuildOptions) -> Build {
    let mut clock = ticking();
    build_with(source, options, &mut timed(&mut clock))
}

#[test]
fn without_a_clock_there_are_no_timings() {
    assert_eq!(build("axiom: F", &BuildOptions::default()).timings, None);
}

#[test]
fn a_clock_is_read_once_around_each_stage() {
    let result = build_ticking("axiom: F\nF -> FF", &BuildOptions::default());
    let timings = result.timings.expect("timings");
    assert_eq!(
        timings,
        StageTimings {
            parse_resolve: 1.0,
            derive: 1.0,
            interpret: 1.0,
            mesh: 1.0
        }
    );
    assert_eq!(
        timings.to_json(),
        r#"{"parseResolve":1.0,"derive":1.0,"interpret":1.0,"mesh":1.0}"#
    );
}

#[test]
fn a_timed_remesh_of_a_sketch_adds_its_skeleton_to_interpret_and_its_tubes_to_mesh() {
    let mut clock = ticking();
    let options = BuildOptions {
        sketch: true,
        ..BuildOptions::default()
    };
    let mut result = build_with("axiom: F\nF -> FF", &options, &mut timed(&mut clock));
    result.remesh_with(&options.mesh, &mut timed(&mut clock));
    let timings = result.timings.expect("timings");
    assert_eq!((timings.interpret, timings.mesh), (2.0, 2.0));
    // Without a clock, or on a build made without one, nothing is timed.
    result.remesh(&options.mesh);
    assert_eq!(result.timings, Some(timings));
    let mut untimed = build("axiom: F", &options);
    untimed.remesh_with(&options.mesh, &mut timed(&mut clock));
    assert_eq!(untimed.timings, None);
}

#[test]
fn timings_json_is_what_serde_json_writes() {
    for times in [
        [0.25, 12.5, 0.1 + 0.2, 1234.0],
        [-0.0, 3.0e-3, 99999.875, 1.0 / 3.0],
    ] {
        let timings = StageTimings {
            parse_resolve: times[0],
            derive: times[1],
            interpret: times[2],
            mesh: times[3],
        };
        let by_serde = serde_json::to_string(&timings).unwrap();
        assert_eq!(timings.to_json(), by_serde);
    }
    let broken = StageTimings {
        derive: f64::NAN,
        mesh: f64::INFINITY,
        ..StageTimings::default()
    };
    assert_eq!(
        broken.to_json(),
        r#"{"parseResolve":0.0,"derive":null,"interpret":0.0,"mesh":null}"#
    );
}

#[test]
fn the_clamping_warning_writes_max_coordinate_as_its_exponent_form() {
    assert_eq!(
        MAX_COORDINATE_TEXT,
        format!("{:e}", crate::turtle::MAX_COORDINATE)
    );
}

#[test]
fn stages_after_an_error_take_no_time() {
    let result = build_ticking("axiom: F[", &BuildOptions::default());
    assert!(!result.ok());
    let timings = result.timings.expect("timings");
    assert_eq!(timings.parse_resolve, 1.0);
    assert_eq!(
        (timings.derive, timings.interpret, timings.mesh),
        (0.0, 0.0, 0.0)
    );
}

/// What `progress` is told while `source` builds with `iterations`.
fn progress_of(source: &str, iterations: u32) -> Vec<Progress> {
    let mut told = Vec::new();
    let mut progress = |p| told.push(p);
    let mut hooks = Hooks {
        clock: None,
        progress: Some(&mut progress),
    };
    let options = BuildOptions::with_iterations(iterations);
    build_with(source, &options, &mut hooks);
    told
}

#[test]
fn progress_tells_each_stage_and_each_derivation_step() {
    use Progress::{Derived, Started};
    let derived = |step| Derived { step, steps: 3 };
    assert_eq!(
        progress_of("axiom: F\nF -> F[+F]F", 3),
        [
            Started(Stage::Parse),
            Started(Stage::Derive),
            derived(0),
            derived(1),
            derived(2),
            derived(3),
            Started(Stage::Interpret),
            Started(Stage::Mesh),
        ]
    );
    // With growth attributes the derivation takes the general path: the same steps.
    let growing = progress_of("#lifetime 60 40\naxiom: A\nA -> F[+A]A", 2);
    let steps: Vec<_> = growing
        .iter()
        .filter_map(|p| match p {
            Derived { step, steps } => Some((*step, *steps)),
            _ => None,
        })
        .collect();
    assert_eq!(steps, [(0, 2), (1, 2), (2, 2)]);
    // Errors stop the progress where the build stops.
    assert_eq!(progress_of("axiom: F[", 3), [Started(Stage::Parse)]);
}

#[test]
fn a_clock_changes_nothing_else() {
    let source = "#angle 30\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF";
    let options = BuildOptions::with_iterations(3);
    let plain = build(source, &options);
    let timed = build_ticking(source, &options);
    assert_eq!(plain.plant.stats, timed.plant.stats);
    assert_eq!(plain.plant.mesh.positions, timed.plant.mesh.positions);
}

#[test]
fn a_sketch_draws_lines_and_its_remesh_is_the_plain_build() {
    let source = "#angle 25\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF";
    let options = BuildOptions::with_iterations(4);
    let plain = build(source, &options);
    let mut sketch = build(
        source,
        &BuildOptions {
            sketch: true,
            ..options.clone()
        },
    );
    // Lines only: no skeleton, no triangles; the stats count the segments as lines.
    assert!(sketch.plant.is_sketch());
    assert!(sketch.plant.skeleton.segments.is_empty());
    assert_eq!(sketch.plant.mesh.triangle_count(), 0);
    let segments = plain.plant.skeleton.segments.len();
    assert_eq!(sketch.plant.stats.segments, segments);
    assert_eq!(sketch.plant.stats.lines, segments);
    assert_eq!(sketch.plant.is_flat(), plain.plant.is_flat());
    let lines = plain.plant.segment_lines();
    let sketched = sketch.plant.segment_lines();
    assert_eq!(sketched.modules, lines.modules);
    assert_eq!(sketched.colors, lines.colors);
    for (a, b) in sketched.ends.iter().zip(&lines.ends) {
        assert!((a - b).abs() < 1e-5, "{a} against {b}");
    }
    for k in 0..3 {
        for side in 0..2 {
            let (a, b) = (
                sketch.plant.stats.bounds[side][k],
                crate::mesh::MeshBuffers {
                    lines: sketched.ends.clone(),
                    ..Default::default()
                }
                .bounds()[side][k],
            );
            assert_eq!(a, b, "the sketch's bounds are its lines'");
        }
    }
    // The tubes on demand: the very mesh and stats of the plain build.
    sketch.remesh(&options.mesh);
    assert!(!sketch.plant.is_sketch());
    assert_eq!(sketch.plant.skeleton, plain.plant.skeleton);
    assert_eq!(sketch.plant.mesh, plain.plant.mesh);
    assert_eq!(sketch.plant.stats, plain.plant.stats);
}

#[test]
fn a_sketch_with_growth_draws_its_skeleton_at_once() {
    let source = "#lifetime 60 40\naxiom: A\nA -> F[+A]A";
    let sketch = build(
        source,
        &BuildOptions {
            sketch: true,
            ..BuildOptions::with_iterations(3)
        },
    );
    assert!(!sketch.plant.is_sketch());
    assert!(!sketch.plant.skeleton.segments.is_empty());
}

#[test]
fn without_tubes_the_bounds_are_the_segments() {
    let source = "#angle 25\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF";
    let options = BuildOptions::with_iterations(3);
    let mut result = build(source, &options);
    let with_tubes = result.plant.stats.clone();
    result.remesh(&MeshOptions {
        tubes: false,
        ..options.mesh.clone()
    });
    let stats = &result.plant.stats;
    assert_eq!((stats.vertices, stats.triangles), (0, 0));
    assert_eq!(stats.segments, with_tubes.segments);
    let lines = crate::mesh::MeshBuffers {
        lines: result.plant.segment_lines().ends,
        ..Default::default()
    };
    assert_eq!(stats.bounds, lines.bounds());
    assert_ne!(stats.bounds, [[0.0; 3]; 2]);
}
