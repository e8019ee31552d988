//! The drawing's budget (issue 50, findings 1 and 2; docs/LANGUAGE.md, "Limits"): a plant whose
//! skeleton would pass 512 MB is drawn as lines only, with a warning, and is not exported; one
//! whose lines would pass 512 MB too stops with an error before the turtle runs. Before, `F -> FF`
//! at 24 steps asked for a 2 GB array ("capacity overflow" in WebAssembly, a lost core).

use meristem::diagnostics::Diagnostic;
use meristem::export::Format;
use meristem::pipeline::{
    build, export, Build, BuildOptions, ExportError, ExportOptions, Hooks, MAX_READING_BYTES,
};
use meristem::turtle::{MAX_SKELETON_BYTES, MAX_SKETCH_BYTES};

const DOUBLING: &str = "#max_modules 40000000\naxiom: F\nF -> FF\n";

/// The diagnostic of `code` that `b` must have.
fn diagnostic<'b>(b: &'b Build, code: &str) -> &'b Diagnostic {
    (b.diagnostics.iter().find(|d| d.code == code))
        .unwrap_or_else(|| panic!("{code} expected: {:?}", b.diagnostics))
}

fn options(iterations: u32) -> BuildOptions {
    BuildOptions {
        iterations: Some(iterations),
        ..BuildOptions::default()
    }
}

#[test]
fn sixteen_million_segments_stop_before_the_turtle_runs() {
    let b = build(DOUBLING, &options(24));
    let error = diagnostic(&b, "E0413");
    assert!(
        error.message.contains("16777216 segments"),
        "{}",
        error.message
    );
    assert!(
        error.message.contains("832 MB even as lines"),
        "{}",
        error.message
    );
    assert_eq!(MAX_SKETCH_BYTES, 512 << 20);
    assert_eq!(b.plant.stats.segments, 0);
    assert!(b.plant.mesh.lines.is_empty());
}

#[test]
fn eight_million_segments_are_drawn_as_lines_only_and_not_exported() {
    let mut b = build(DOUBLING, &options(23));
    assert!(b.ok(), "{:?}", b.diagnostics);
    let warning = diagnostic(&b, "E0414");
    assert!(
        warning.message.contains("8388608 segments"),
        "{}",
        warning.message
    );
    assert!(warning.message.contains("1024 MB"), "{}", warning.message);
    assert_eq!(MAX_SKELETON_BYTES, 512 << 20);
    assert!(b.plant.is_lines_only());
    assert_eq!(b.plant.stats.lines, 1 << 23);
    assert_eq!(b.plant.mesh.lines.len(), 6 << 23);
    // Asking for tubes again keeps the lines: the skeleton is never drawn.
    let mesh = b.plant.mesh_options.clone();
    b.remesh(&mesh);
    b.ensure_skeleton();
    assert!(b.plant.skeleton.segments.is_empty());
    assert_eq!(b.plant.mesh.lines.len(), 6 << 23);
    let refused = export(
        DOUBLING,
        &ExportOptions {
            build: options(23),
            format: Format::Glb,
            stem: "plant".into(),
            edits: None,
            look: Default::default(),
            animation: None,
        },
        &mut Hooks::default(),
    );
    match refused {
        Err(ExportError::Refused(message)) => {
            assert!(message.contains("too large to export"), "{message}")
        }
        other => panic!("refused expected, got {:?}", other.map(|e| e.files.len())),
    }
}

#[test]
fn four_million_segments_still_have_their_skeleton() {
    // 2^22 segments of 128 bytes: the skeleton's budget exactly.
    let b = build(DOUBLING, &options(22));
    assert!(b.ok(), "{:?}", b.diagnostics);
    assert!(b.diagnostics.iter().all(|d| d.code != "E0414"));
    assert!(!b.plant.is_lines_only());
    assert_eq!(b.plant.skeleton.segments.len(), 1 << 22);
}

/// A plant the environment reads between steps: `?E` and a program, `F -> FF`.
const READ_DOUBLING: &str = "#environment obstacle sphere center 0 0 100 radius 1\n\
                             #max_modules 40000000\naxiom: ?E(0) F\nF -> FF\n";

#[test]
fn the_environment_does_not_draw_a_plant_of_four_million_segments_between_steps() {
    // After step 22 the plant has 2^22 segments: its skeleton alone would take 513 MB.
    // Before, the environment drew it whatever its size (640 MB at 5 million segments).
    let b = build(READ_DOUBLING, &options(22));
    let error = diagnostic(&b, "E0416");
    assert!(error.message.contains("after step 22"), "{}", error.message);
    assert!(
        error.message.contains("4194304 segments"),
        "{}",
        error.message
    );
    assert!(
        error.message.contains("budget of 512 MB"),
        "{}",
        error.message
    );
    assert_eq!(MAX_READING_BYTES, 512 << 20);
    // The step before is read, and answered.
    assert!(build(READ_DOUBLING, &options(21)).ok());
}

#[test]
fn the_environment_counts_the_parts_of_the_plants_it_has_read() {
    // Two plants of 2^21 segments: each skeleton fits (about 270 MB), but the first one's parts
    // (150 MB) and the second one's skeleton and parts do not.
    let stand = format!("#plant 0 0 0\n#plant 5 0 0\n{READ_DOUBLING}");
    let b = build(&stand, &options(21));
    let error = diagnostic(&b, "E0416");
    assert!(error.message.contains("after step 21"), "{}", error.message);
    assert!(
        error
            .message
            .contains("2097152 segments beside the 2097152 parts"),
        "{}",
        error.message
    );
}

/// 2^n spheres and nothing else.
const SPHERES: &str = "#max_modules 40000000\naxiom: A\nA -> AA\nhomomorphism:\nA -> @O(1)f\n";

#[test]
fn a_plant_too_large_to_mesh_says_that_its_spheres_are_left_out() {
    // 65,536 spheres of 17 × 17 vertices: 18.9 million vertices, above the mesh's 4 million.
    // Before, it was drawn as lines of its segments (none): nothing, without a word.
    let b = build(SPHERES, &options(16));
    assert!(b.ok(), "{:?}", b.diagnostics);
    let warning = diagnostic(&b, "E0417");
    assert!(
        warning
            .message
            .contains("65536 polygons, leaves and spheres are left out"),
        "{}",
        warning.message
    );
    assert!(
        warning.message.contains("limit of 4000000"),
        "{}",
        warning.message
    );
    assert_eq!(b.plant.stats.vertices, 0);
    // Meshed, they say nothing.
    let small = build(SPHERES, &options(4));
    assert!(small.diagnostics.is_empty(), "{:?}", small.diagnostics);
    assert!(small.plant.stats.vertices > 0);
}

#[test]
fn remeshing_past_the_mesh_limit_and_back_adds_and_removes_the_warning() {
    let mut b = build(SPHERES, &options(8));
    assert!(b.diagnostics.is_empty(), "{:?}", b.diagnostics);
    let mut mesh = b.plant.mesh_options.clone();
    mesh.max_vertices = 1000;
    b.remesh(&mesh);
    let codes =
        |b: &Build| -> Vec<String> { b.diagnostics.iter().map(|d| d.code.to_string()).collect() };
    assert_eq!(codes(&b), ["E0417"]);
    b.remesh(&mesh);
    assert_eq!(codes(&b), ["E0417"], "one warning, not one a remesh");
    mesh.max_vertices = 4_000_000;
    b.remesh(&mesh);
    assert!(b.diagnostics.is_empty(), "{:?}", b.diagnostics);
}

#[test]
fn a_plant_of_leaves_over_the_drawing_budget_counts_its_leaves() {
    // 4,194,304 leaves and no segment: before, "the plant has 0 segments, which would take
    // 672 MB as a skeleton".
    let leaves = "#max_modules 40000000\naxiom: A\nA -> AA\nhomomorphism:\nA -> ~l f\n";
    let b = build(leaves, &options(22));
    let warning = diagnostic(&b, "E0414");
    assert!(
        warning.message.contains(
            "0 segments and 4194304 polygons, polygon points, leaves, spheres or queries"
        ),
        "{}",
        warning.message
    );
}
