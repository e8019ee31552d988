//! The gallery is the regression corpus: every `public/examples/*.lsys` must have a header, parse
//! without any diagnostic, build within the limits and give a mesh that keeps every invariant.

mod shared;

use meristem::pipeline::{build, BuildOptions};
use shared::{example, examples};

#[test]
fn every_example_has_a_title_source_and_description_header() {
    for (path, text) in examples() {
        let header: Vec<_> = text.lines().take_while(|l| l.starts_with("//")).collect();
        assert!(
            header.len() >= 3,
            "{}: needs a header of title, source and description",
            path.display()
        );
        assert!(
            header.iter().any(|l| l.contains("Source:")),
            "{}: header names no source",
            path.display()
        );
    }
}

#[test]
fn every_example_builds_cleanly_with_a_valid_mesh() {
    for (path, text) in examples() {
        let result = build(&text, &BuildOptions::default());
        assert!(
            result.diagnostics.is_empty(),
            "{}: {:?}",
            path.display(),
            result.diagnostics
        );
        assert!(
            result.plant.stats.segments > 0,
            "{}: draws nothing",
            path.display()
        );
        assert!(
            result.plant.stats.triangles > 0,
            "{}: no triangles",
            path.display()
        );
        if let Err(e) = result.plant.mesh.check() {
            panic!("{}: {e}", path.display());
        }
    }
}

#[test]
fn abop_1_24d_has_the_known_size() {
    let (_, text) = examples()
        .into_iter()
        .find(|(p, _)| p.ends_with("abop-1.24d.lsys"))
        .expect("1.24d");
    let result = build(&text, &BuildOptions::default());
    // Each X makes three X per step, so n = 7 leaves 3^7 of them.
    let derived = result.derived_text();
    assert_eq!(derived.matches('X').count(), 3usize.pow(7));
    assert_eq!(result.plant.stats.modules, derived.chars().count());
    assert_eq!(result.plant.stats.segments, derived.matches('F').count());
    let ten = build(
        &text,
        &BuildOptions {
            iterations: Some(10),
            ..BuildOptions::default()
        },
    );
    assert_eq!(
        ten.plant.stats.modules, 381_767,
        "the issue's reference size of 1.24d at n = 10"
    );
}

#[test]
fn pruning_keeps_every_segment_end_inside_its_volume() {
    let ellipsoid = build(
        &example("green-prune-ellipsoid.lsys"),
        &BuildOptions::default(),
    );
    assert!(
        ellipsoid.plant.skeleton.segments.len() > 100,
        "the tree grows"
    );
    let inside = |p: glam::DVec3| {
        p.x * p.x / 16.0 + (p.y - 5.5).powi(2) / 30.25 + p.z * p.z / 16.0 <= 1.0 + 1e-9
    };
    for s in &ellipsoid.plant.skeleton.segments {
        assert!(inside(s.end), "segment end {} outside the ellipsoid", s.end);
    }
    let unpruned = build(
        &example("green-prune-ellipsoid.lsys")
            .lines()
            .filter(|l| !l.ends_with("-> %"))
            .collect::<Vec<_>>()
            .join("\n"),
        &BuildOptions::default(),
    );
    assert!(
        unpruned
            .plant
            .skeleton
            .segments
            .iter()
            .any(|s| !inside(s.end)),
        "without the cut the tree grows out"
    );

    let boxed = build(&example("green-prune-box.lsys"), &BuildOptions::default());
    assert!(boxed.plant.skeleton.segments.len() > 100);
    for s in &boxed.plant.skeleton.segments {
        let p = s.end;
        assert!(
            p.x.abs() <= 3.0 + 1e-9
                && p.z.abs() <= 3.0 + 1e-9
                && (-1e-9..=8.0 + 1e-9).contains(&p.y),
            "{p} outside the box"
        );
    }
}

#[test]
fn the_bush_of_fig_1_25_shows_its_leaves() {
    let bush = build(&example("abop-1.25-bush.lsys"), &BuildOptions::default());
    assert!(
        bush.plant.skeleton.polygons.len() > 100,
        "{} leaves",
        bush.plant.skeleton.polygons.len()
    );
    // Each leaf is two-sided: its triangles come twice, and they are coloured as leaves.
    let leaf_triangles = bush.plant.mesh.ranges.chunks_exact(2).count();
    assert!(leaf_triangles > bush.plant.skeleton.polygons.len());
    assert_eq!(bush.plant.mesh.check(), Ok(()));
}

#[test]
fn smooth_branches_make_more_rings_than_joints() {
    let smooth = build(&example("smooth-tree.lsys"), &BuildOptions::default());
    let sharp = build(
        &example("smooth-tree.lsys").replace("@Gc", ""),
        &BuildOptions::default(),
    );
    assert_eq!(
        smooth.plant.skeleton.segments.len(),
        sharp.plant.skeleton.segments.len()
    );
    assert!(smooth.plant.stats.vertices > 2 * sharp.plant.stats.vertices);
    assert_eq!(smooth.plant.mesh.check(), Ok(()));
}

/// Green's gallery: each Random L-system grows a different individual of the same species per seed.
#[test]
fn greens_random_l_systems_grow_individuals_of_one_species() {
    let build = |name: &str, seed: u64| {
        let b = meristem::build(
            &example(name),
            &meristem::BuildOptions {
                seed: Some(seed),
                ..meristem::BuildOptions::default()
            },
        );
        assert!(b.ok(), "{name}: {:?}", b.diagnostics);
        b
    };
    // The ternary tree: the same architecture (segments, leaves) for every seed, other angles.
    let (a, b) = (
        build("green-ternary-tree.lsys", 1),
        build("green-ternary-tree.lsys", 2),
    );
    assert_eq!(a.plant.skeleton.segments.len(), 365);
    assert_eq!(
        a.plant.skeleton.segments.len(),
        b.plant.skeleton.segments.len()
    );
    assert_eq!(a.plant.skeleton.surfaces.len(), 3 * 729);
    assert_ne!(a.derived_text(), b.derived_text());
    // The palm: @Repeat draws the trunk's pace once per palm, so heights differ between seeds; the
    // crown always has its eight fronds.
    let heights: Vec<f64> = (1..=6)
        .map(|seed| build("green-palm-tree.lsys", seed).plant.stats.bounds[1][1])
        .collect();
    assert!(
        heights.iter().any(|&h| (h - heights[0]).abs() > 1.0),
        "{heights:?}"
    );
    let palm = build("green-palm-tree.lsys", 1);
    assert_eq!(palm.derived_text().matches("R(").count(), 8);
    // The coral: a rounded tip on every branch, and its four stems (in a Switch) of unequal ages.
    let coral = build("green-coral.lsys", 1);
    assert_eq!(
        coral.plant.skeleton.spheres.len() + 1,
        coral.plant.skeleton.segments.len()
    );
    let tips = |stem: &str| stem.matches("A(").count();
    let text = coral.derived_text();
    let stems: Vec<usize> = text.split("@|").map(tips).collect();
    assert_eq!(stems.len(), 4, "{text}");
    assert!(stems.iter().any(|&n| n != stems[0]), "{stems:?}");
}

#[test]
fn sierpinski_and_the_row_of_trees_lie_as_in_the_book() {
    // ABOP 1.10b stands on a horizontal base and 1.37a's row runs left to right with the trees
    // above it: both are wider than tall, start at the origin and grow up (+Y) from their base.
    for name in ["abop-1.10b-sierpinski.lsys", "abop-1.37a-row-of-trees.lsys"] {
        let result = build(&example(name), &BuildOptions::default());
        let [min, max] = result.plant.stats.bounds;
        let (width, height) = (max[0] - min[0], max[1] - min[1]);
        assert!(width > 1.1 * height, "{name}: {width} wide, {height} tall");
        let thickness = max[2] - min[2];
        assert!(
            min[0].abs() < thickness && min[1].abs() < thickness,
            "{name}: starts at {min:?}"
        );
        assert!(
            max[1] > 0.4 * width,
            "{name}: grows below its base ({min:?}..{max:?})"
        );
    }
}

#[test]
fn internodes_of_a_grammar_without_widths_are_a_tenth_as_wide_as_long() {
    // ABOP 1.24a sets no width: its internodes (length 1) were as thick as long (beads) when the
    // width followed the plant's size alone; now at most a tenth of the median internode.
    let depth = |text: &str| {
        let [min, max] = build(text, &BuildOptions::default()).plant.stats.bounds;
        max[2] - min[2] // a flat plant's depth is its tubes' width (times cos 30° for 6 sides)
    };
    let a = depth(&example("abop-1.24a.lsys"));
    assert!(a <= 0.1 + 1e-6 && a > 0.05, "1.24a's tubes are {a} across");
    // A grammar that sets widths keeps the width unit of the plant's size (1/300 of its diagonal).
    let set = depth(&format!("#width 1\n{}", example("abop-1.24a.lsys")));
    assert!(set > 3.0 * a, "with #width 1: {set}");
    let bang = depth(&example("abop-1.24a.lsys").replace("axiom: F", "axiom: !(1)F"));
    assert!((bang - set).abs() < 1e-9, "with !(1): {bang}");
}
