//! The environment's work limit (docs/LANGUAGE.md, "Limits", `E0418`): a program whose passes
//! test every `?E` against every part, point or other `?E` (all crowded in one cell of its grid)
//! stops the build with a diagnostic at its `#environment` line once it has done 200 tests a
//! module of `#max_modules`, instead of running for minutes. The grammars are the hostile
//! corpus's, with a small `#max_modules` so that the limit comes at once.

use meristem::diagnostics::Severity;
use meristem::pipeline::{build, Build, BuildOptions};

fn at(iterations: u32) -> BuildOptions {
    BuildOptions {
        iterations: Some(iterations),
        ..BuildOptions::default()
    }
}

fn grows(b: &Build) -> bool {
    b.diagnostics.iter().all(|d| d.severity != Severity::Error)
        && !b.plant.skeleton.segments.is_empty()
}

const SPACE: &str = include_str!("hostile/environment_space_crowded_in_one_cell.lsys");
const ATTRACTORS: &str = include_str!("hostile/environment_attractors_in_one_cell.lsys");
const COLLISION: &str = include_str!("hostile/environment_collision_two_crowds.lsys");
const LIGHT: &str = include_str!("hostile/environment_light_long_segments.lsys");

/// The E0418 of `source`'s build: its message, after checking that it points at the program's
/// `#environment` line and that the build made no plant.
fn work_limit(source: &str, options: &BuildOptions) -> String {
    let b = build(source, options);
    let e = (b.diagnostics.iter().find(|d| d.code == "E0418"))
        .unwrap_or_else(|| panic!("E0418 expected, got {:?}", b.diagnostics));
    assert!(
        source[e.span.clone()].starts_with("#environment"),
        "{:?}",
        e.span
    );
    assert!(
        b.plant.skeleton.segments.is_empty(),
        "no plant after an error"
    );
    e.message.clone()
}

#[test]
fn buds_crowded_among_parts_stop_the_space_program_at_its_work_limit() {
    let m = work_limit(SPACE, &BuildOptions::default());
    assert!(m.contains("space program"), "{m}");
    assert!(m.contains("limit of 1000000 tests"), "{m}");
    assert!(
        m.contains("by step 10, answering 1023 `?E` among 1023 parts"),
        "{m}"
    );
    assert!(m.contains("a smaller `radius`"), "{m}");
    // Below the limit the same grammar grows.
    let b = build(SPACE, &at(8));
    assert!(grows(&b), "{:?}", b.diagnostics);
}

#[test]
fn attraction_points_crowded_round_buds_stop_at_the_work_limit() {
    let m = work_limit(ATTRACTORS, &BuildOptions::default());
    assert!(m.contains("attractors program"), "{m}");
    assert!(m.contains("a smaller `influence`"), "{m}");
}

#[test]
fn two_crowds_of_buds_stop_the_collision_program_at_its_work_limit() {
    let m = work_limit(COLLISION, &BuildOptions::default());
    assert!(m.contains("collision program"), "{m}");
    assert!(m.contains("by step 11, answering 4094 `?E`"), "{m}");
    let b = build(COLLISION.replace("A A", "F A A").as_str(), &at(9));
    assert!(grows(&b), "{:?}", b.diagnostics);
}

#[test]
fn long_segments_in_a_fine_light_grid_stop_at_the_work_limit() {
    let m = work_limit(LIGHT, &BuildOptions::default());
    assert!(m.contains("light program"), "{m}");
    assert!(m.contains("a larger `cell`"), "{m}");
    // A coarser cell: each segment over 200 voxels, and the plant grows.
    let coarse = LIGHT.replace("cell 0.05", "cell 5");
    let b = build(&coarse, &BuildOptions::default());
    assert!(grows(&b), "{:?}", b.diagnostics);
}

#[test]
fn raising_max_modules_raises_the_work_limit() {
    let raised = COLLISION.replace("#max_modules 10000", "#max_modules 100000");
    let m = work_limit(&raised, &at(20));
    assert!(m.contains("limit of 20000000 tests"), "{m}");
    assert!(m.contains("by step 13"), "{m}");
}

#[test]
fn a_plant_read_at_every_step_without_growing_stops_at_the_reading_limit() {
    let src = include_str!("hostile/environment_timed_plant_read_every_step.lsys");
    let m = work_limit(src, &BuildOptions::default());
    assert!(m.contains("the environment has read"), "{m}");
    assert!(
        m.contains("work limit of 40000 (20 times the module limit)"),
        "{m}"
    );
    // To t = 30 it reads less, and grows.
    let b = build(src, &at(30));
    assert!(
        b.diagnostics.iter().all(|d| d.severity != Severity::Error),
        "{:?}",
        b.diagnostics
    );
}
