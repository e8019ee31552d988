//! ABOP chapter 2, the trees: each gallery figure (`public/examples/abop-2.*.lsys`) checked
//! against what its grammar implies and the book states: internode counts by hand count, the
//! branching angles of its table measured on the skeleton, width ratios, and the trunk's width
//! ÷ the tree's height in the mesh (what the view, the Stages strip, every print figure and every
//! export draw) within 25 % of the ratio computed by hand from the grammar's own numbers: the
//! first internode's width, and the height along the main axis.

mod shared;

use glam::DVec3;
use meristem::export::Format;
use meristem::maths;
use meristem::pipeline::{build, export, Build, BuildOptions, ExportOptions, Hooks, PlantEditor};
use meristem::turtle::Skeleton;
use shared::examples;

/// The text of the gallery example whose file name starts with `prefix`.
fn example(prefix: &str) -> String {
    examples()
        .into_iter()
        .find(|(p, _)| {
            p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with(prefix))
        })
        .map(|(_, text)| text)
        .unwrap_or_else(|| panic!("no example {prefix}"))
}

/// A `#define` constant of an example.
fn constant(text: &str, name: &str) -> f64 {
    let line = text
        .lines()
        .find(|l| l.split_whitespace().take(2).eq(["#define", name]))
        .unwrap_or_else(|| panic!("no #define {name}"));
    line.split_whitespace()
        .nth(2)
        .and_then(|v| v.parse().ok())
        .expect("a number")
}

/// The example built at `n` steps (its own `#iterations` when `None`), without a diagnostic.
fn built(text: &str, n: Option<u32>) -> Build {
    let options = BuildOptions {
        iterations: n,
        ..BuildOptions::default()
    };
    let b = build(text, &options);
    assert!(b.diagnostics.is_empty(), "{:?}", b.diagnostics);
    b
}

/// The trunk's drawn diameter (twice the farthest vertex from the Y axis on the mesh's lowest
/// plane: the trunk's base ring) and the plant's drawn height (the mesh's extent along Y).
fn trunk_and_height(positions: &[f32]) -> (f64, f64) {
    let (mut low, mut high) = (f64::MAX, f64::MIN);
    for p in positions.chunks(3) {
        low = low.min(p[1] as f64);
        high = high.max(p[1] as f64);
    }
    let height = high - low;
    let radius = positions
        .chunks(3)
        .filter(|p| (p[1] as f64 - low).abs() < 1e-5 * height)
        .map(|p| maths::hypot(p[0] as f64, p[2] as f64))
        .fold(0.0, f64::max);
    (2.0 * radius, height)
}

/// The book's drawing unit of a Fig 2.6 or 2.7 tree: its widths are cpfg line widths in pixels, so
/// a pixel is the picture's frame ÷ its pixels. As Meristem's default unit does, the frame is the
/// finished tree's bounding-box diagonal (from the skeleton: no width in it) and 300 pixels across.
fn book_pixel(s: &Skeleton) -> f64 {
    let (mut low, mut high) = (DVec3::splat(f64::MAX), DVec3::splat(f64::MIN));
    for seg in &s.segments {
        low = low.min(seg.start).min(seg.end);
        high = high.max(seg.start).max(seg.end);
    }
    low.distance(high) / 300.0
}

/// The grammar's `#width_unit`.
fn width_unit(text: &str) -> f64 {
    text.lines()
        .find_map(|l| l.strip_prefix("#width_unit "))
        .and_then(|v| v.trim().parse().ok())
        .expect("a #width_unit")
}

/// Every stage of a Fig 2.6 or 2.7 tree is drawn with the grammar's unit: the trunk 10 units wide.
fn assert_trunk_at_every_stage(name: &str, text: &str) {
    let unit = width_unit(text);
    for stage in [1, 4, 7] {
        let b = built(text, Some(stage));
        assert_eq!(b.plant.mesh.width_unit, unit, "{name} at n = {stage}");
        let (trunk, _) = trunk_and_height(&b.plant.mesh.positions);
        assert!(
            (trunk - 10.0 * unit).abs() < 1e-3 * trunk,
            "{name} at n = {stage}: {trunk}"
        );
    }
}

/// `measured` is within 25 % of `expected`.
fn within_quarter(what: &str, measured: f64, expected: f64) {
    let off = (measured / expected - 1.0).abs();
    assert!(
        off <= 0.25,
        "{what}: {measured:.5} is {:.0} % off {expected:.5}",
        off * 100.0
    );
}

/// The angle between two segments' directions, in degrees.
fn angle(s: &Skeleton, a: usize, b: usize) -> f64 {
    let dir = |i: usize| (s.segments[i].end - s.segments[i].start).normalize();
    dir(a).angle_between(dir(b)).to_degrees()
}

/// The segments that leave the end of segment `i` as branches (not its axis's continuation).
fn branches_of(s: &Skeleton, i: usize) -> Vec<usize> {
    (0..s.segments.len())
        .filter(|&k| s.segments[k].anchor == Some(i as u32) && s.segments[k].previous.is_none())
        .collect()
}

/// The segment continuing segment `i`'s axis.
fn next_on_axis(s: &Skeleton, i: usize) -> Option<usize> {
    (0..s.segments.len()).find(|&k| s.segments[k].previous == Some(i as u32))
}

/// Honda's trees, Fig 2.6 a–d: r2, a0 of the book's table.
const HONDA: [(&str, f64, f64); 4] = [
    ("abop-2.06a", 0.6, 45.0),
    ("abop-2.06b", 0.9, 45.0),
    ("abop-2.06c", 0.8, 45.0),
    ("abop-2.06d", 0.7, 30.0),
];

#[test]
fn honda_trees_have_their_tables_angles_counts_and_proportions() {
    for (name, r2, a0) in HONDA {
        let text = example(name);
        assert_eq!(constant(&text, "r2"), r2, "{name}: the table's r2");
        let b = built(&text, None);
        let s = &b.plant.skeleton;
        // Every apex (A, B or C) draws one internode and makes two apices, so n = 10 steps
        // draw 2^10 − 1 internodes.
        assert_eq!(s.segments.len(), 1023, "{name}");
        // The trunk: the first internode and its continuations, n of them, straight up.
        let mut trunk = vec![0];
        while let Some(k) = next_on_axis(s, *trunk.last().expect("a segment")) {
            trunk.push(k);
        }
        assert_eq!(trunk.len(), 10, "{name}: one trunk internode a step");
        // The first lateral branch leaves the trunk at a0, with width 10 · wr.
        let lateral = branches_of(s, 0)[0];
        let measured = angle(s, 0, lateral);
        assert!(
            (measured - a0).abs() < 1e-6,
            "{name}: branching angle {measured}"
        );
        let ratio = s.segments[lateral].width / s.segments[0].width;
        assert!((ratio - 0.707).abs() < 1e-9, "{name}: wr");
        // By hand: the trunk is 10 of the book's pixels wide, the tree as high as its trunk's
        // internodes 1, r1, r1², … r1⁹ laid end to end (the trunk grows straight up; no branch
        // reaches higher): (1 − r1¹⁰)/(1 − r1).
        let r1: f64 = constant(&text, "r1");
        let expected = 10.0 * book_pixel(s) / ((1.0 - r1.powi(10)) / (1.0 - r1));
        let (trunk_width, height) = trunk_and_height(&b.plant.mesh.positions);
        within_quarter(name, trunk_width / height, expected);
        assert_trunk_at_every_stage(name, &text);
    }
}

/// Aono and Kunii's sympodial trees, Fig 2.7 a–d: r1, r2, a1, a2 of the book's table.
const SYMPODIAL: [(&str, f64, f64, f64, f64); 4] = [
    ("abop-2.07a", 0.9, 0.7, 5.0, 65.0),
    ("abop-2.07b", 0.9, 0.7, 10.0, 60.0),
    ("abop-2.07c", 0.9, 0.8, 20.0, 50.0),
    ("abop-2.07d", 0.9, 0.8, 35.0, 35.0),
];

#[test]
fn sympodial_trees_fork_at_their_tables_angles_with_their_proportions() {
    for (name, r1, r2, a1, a2) in SYMPODIAL {
        let text = example(name);
        assert_eq!(constant(&text, "r2"), r2, "{name}: the table's r2");
        let b = built(&text, None);
        let s = &b.plant.skeleton;
        // Every apex draws one internode and forks in two: 2^10 − 1 internodes.
        assert_eq!(s.segments.len(), 1023, "{name}");
        // No leading axis: the trunk ends in a fork of two branches at a1 and a2.
        assert_eq!(next_on_axis(s, 0), None, "{name}: sympodial");
        let fork = branches_of(s, 0);
        assert_eq!(fork.len(), 2, "{name}");
        let angles = [angle(s, 0, fork[0]), angle(s, 0, fork[1])];
        assert!((angles[0] - a1).abs() < 1e-6, "{name}: a1 {angles:?}");
        assert!((angles[1] - a2).abs() < 1e-6, "{name}: a2 {angles:?}");
        let lengths: Vec<f64> = fork
            .iter()
            .map(|&k| s.segments[k].start.distance(s.segments[k].end))
            .collect();
        assert!((lengths[0] - r1).abs() < 1e-9 && (lengths[1] - r2).abs() < 1e-9);
        // By hand: after the trunk (length 1), the highest path takes the r1 branch of every fork:
        // at fork k its internode is r1^k long, and since $ makes L horizontal before each turn
        // by a1 about U, the heading's upward part is multiplied by cos a1 at each fork:
        // height = 1 + Σ_{k=1..9} (r1 cos a1)^k. The trunk is 10 of the book's pixels wide.
        let q = r1 * maths::cos(a1.to_radians());
        let height = 1.0 + (1..10).map(|k| q.powi(k)).sum::<f64>();
        let expected = 10.0 * book_pixel(s) / height;
        let (trunk_width, drawn_height) = trunk_and_height(&b.plant.mesh.positions);
        within_quarter(name, trunk_width / drawn_height, expected);
        assert_trunk_at_every_stage(name, &text);
    }
}

/// The ternary trees, Fig 2.8 a–d: n, a, lr of the book's table.
const TERNARY: [(&str, u32, f64, f64); 4] = [
    ("abop-2.08a", 6, 18.95, 1.109),
    ("abop-2.08b", 8, 18.95, 1.109),
    ("abop-2.08c", 8, 22.5, 1.790),
    ("abop-2.08d", 6, 36.0, 1.070),
];

/// The ternary tree's trunk width ÷ height after n steps, by hand. The trunk `!(1)F(200)` is
/// multiplied by vr in width and lr in length at every step: vr^n wide. Along the main axis, the
/// trunk (200 lr^n) is followed, for each step k = 1 … n, by the internode A made at step k and
/// one of its branches' internodes, both 50 lr^(n−k) long (their tilt and tropism ignored):
/// 200 lr^n + 100 (lr^n − 1)/(lr − 1).
fn ternary_ratio(n: u32, lr: f64, vr: f64) -> f64 {
    let n = n as i32;
    let height = 200.0 * lr.powi(n) + 100.0 * (lr.powi(n) - 1.0) / (lr - 1.0);
    vr.powi(n) / height
}

#[test]
fn ternary_trees_have_their_tables_counts_angles_and_the_books_trunks_at_every_stage() {
    for (name, n, a, lr) in TERNARY {
        let text = example(name);
        assert_eq!(constant(&text, "lr"), lr, "{name}: the table's lr");
        let vr = constant(&text, "vr");
        for stage in 0..=n {
            let b = built(&text, Some(stage));
            let s = &b.plant.skeleton;
            // The axiom draws one internode; step k turns 3^(k−1) apices into 4 internodes each:
            // 1 + 4 (3^n − 1)/2.
            assert_eq!(
                s.segments.len(),
                1 + 2 * (3usize.pow(stage) - 1),
                "{name} n = {stage}"
            );
            assert!((s.segments[0].width - vr.powi(stage as i32)).abs() < 1e-9);
            // Widths are the model's units: what the Stages strip draws at each step.
            assert_eq!(b.plant.mesh.width_unit, 1.0);
            let (trunk, height) = trunk_and_height(&b.plant.mesh.positions);
            assert!(
                (trunk - vr.powi(stage as i32)).abs() < 1e-3 * trunk,
                "{name}: {trunk}"
            );
            within_quarter(
                &format!("{name} at n = {stage}"),
                trunk / height,
                ternary_ratio(stage, lr, vr),
            );
        }
        // The first apex's internode is vertical (tropism pulls along it, so it does not bend
        // it); its three branches leave it at a before tropism bends them: the first branch's
        // internode is within tropism's turn of a (e · sin a radians at most).
        let b = built(&text, Some(2));
        let s = &b.plant.skeleton;
        let stem = next_on_axis(s, 0).expect("the first apex's internode");
        let e = text
            .lines()
            .find_map(|l| l.strip_prefix("#tropism "))
            .and_then(|t| t.split_whitespace().nth(3)?.parse::<f64>().ok())
            .expect("tropism");
        let fork = branches_of(s, stem);
        assert_eq!(fork.len(), 3, "{name}");
        for k in fork {
            let measured = angle(s, stem, k);
            let slack = (e * maths::sin(a.to_radians())).to_degrees() + 1e-6;
            assert!((measured - a).abs() <= slack, "{name}: {measured} vs {a}");
        }
    }
}

/// The trunk's width ÷ height in a file's vertices `v x y z` (OBJ).
fn obj_trunk_and_height(obj: &str) -> (f64, f64) {
    let positions: Vec<f32> = obj
        .lines()
        .filter_map(|l| l.strip_prefix("v "))
        .flat_map(|l| {
            l.split_whitespace()
                .map(|v| v.parse::<f32>().expect("number"))
        })
        .collect();
    trunk_and_height(&positions)
}

/// The Stages strip's pictures are each stage's mesh (tested above); its PNG draws that mesh, and
/// its SVG and the Download menu's SVG are the core's SVG export: the trunk's stroke there is as
/// wide as in the mesh. Every other export writes the mesh: OBJ's vertices give the same trunk.
#[test]
fn print_figures_and_exports_draw_the_trunk_the_mesh_draws() {
    let text = example("abop-2.08a");
    let exported = |format: Format| {
        let options = ExportOptions {
            build: BuildOptions::default(),
            format,
            stem: "tree".into(),
            edits: None,
            look: Default::default(),
            animation: None,
        };
        let files = export(&text, &options, &mut Hooks::default())
            .expect("exported")
            .files;
        String::from_utf8(files[0].bytes.clone()).expect("text")
    };
    let trunk = 1.732f64.powi(6);
    let svg = exported(Format::Svg);
    let widths: Vec<f64> = svg
        .split("stroke-width=\"")
        .skip(1)
        .filter_map(|w| w.split('"').next()?.parse().ok())
        .collect();
    let widest = widths.iter().copied().fold(0.0, f64::max);
    assert!(
        (widest - trunk).abs() < 0.01 * trunk,
        "svg trunk {widest} vs {trunk}"
    );
    let (obj_trunk, obj_height) = obj_trunk_and_height(&exported(Format::Obj));
    let b = built(&text, None);
    let (mesh_trunk, mesh_height) = trunk_and_height(&b.plant.mesh.positions);
    assert!(
        (obj_trunk - mesh_trunk).abs() < 1e-3 * mesh_trunk,
        "{obj_trunk}"
    );
    assert!((obj_height - mesh_height).abs() < 1e-3 * mesh_height);
}

/// `#width_unit u`: a width w is a tube w·u across whatever the plant's size; without it the
/// width unit follows the plant (1/300 of its diagonal), as before.
#[test]
fn width_unit_makes_widths_diameters_in_model_units_at_any_size() {
    for length in [1.0, 100.0, 10_000.0] {
        let own = built(&format!("#width_unit 1\naxiom: !(4)F({length})"), None);
        let (trunk, _) = trunk_and_height(&own.plant.mesh.positions);
        assert!((trunk - 4.0).abs() < 1e-3, "{length}: {trunk}");
        let half = built(&format!("#width_unit 0.5\naxiom: !(4)F({length})"), None);
        assert!((trunk_and_height(&half.plant.mesh.positions).0 - 2.0).abs() < 1e-3);
        let relative = built(&format!("axiom: !(4)F({length})"), None);
        let (trunk, _) = trunk_and_height(&relative.plant.mesh.positions);
        let expected = 4.0 * length / 300.0;
        assert!(
            (trunk - expected).abs() < 1e-3 * expected,
            "{length}: {trunk}"
        );
    }
    // A sphere without a radius is as wide as the width, in the same unit.
    let ball = built("#width_unit 2\naxiom: !(3)F(50)@O", None);
    assert_eq!(ball.plant.mesh.width_unit, 2.0);
    let top = ball
        .plant
        .mesh
        .positions
        .chunks(3)
        .map(|p| p[1] as f64)
        .fold(f64::MIN, f64::max);
    assert!(
        (top - (50.0 + 3.0)).abs() < 0.05,
        "sphere of radius 3 on top: {top}"
    );
}

/// Dragging a branch of 2.8a (the studio's branch editing) keeps the grammar's unit: the trunk,
/// which the drag does not move, stays vr⁶ wide, the mesh's unit one model unit.
#[test]
fn a_dragged_tree_keeps_its_widths_in_model_units() {
    let mut editor = PlantEditor::new(built(&example("abop-2.08a"), None).plant);
    let branches = editor.branches();
    let (k, branch) = branches
        .iter()
        .enumerate()
        .find(|(_, b)| b.parent.is_some() && !b.children.is_empty())
        .expect("a limb");
    let tip = branch.control[3] + DVec3::new(40.0, 10.0, 0.0);
    editor.drag(k as u32, 3, tip).expect("dragged");
    assert_eq!(editor.plant().mesh.width_unit, 1.0);
    let (trunk, _) = trunk_and_height(&editor.plant().mesh.positions);
    assert!((trunk - 1.732f64.powi(6)).abs() < 1e-3 * trunk, "{trunk}");
}
