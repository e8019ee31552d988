//! Declared surfaces (docs/LANGUAGE.md, "Surfaces"): `#surface X …` and `#patch X …` drawn by
//! `~X`, placed as cpfg places a `.s` surface, meshed two-sided with smooth normals; counts by
//! hand on small grammars.

use meristem::diagnostics::{Diagnostic, Severity};
use meristem::mesh::MeshOptions;
use meristem::pipeline::{build, Build, BuildOptions};
use meristem::turtle::SurfaceKind;

fn built(source: &str) -> Build {
    let options = BuildOptions {
        iterations: Some(0),
        ..BuildOptions::default()
    };
    build(source, &options)
}

fn ok(source: &str) -> Build {
    let b = built(source);
    assert!(b.ok(), "{source}: {:?}", b.diagnostics);
    b
}

fn codes(b: &Build) -> Vec<(&'static str, Severity)> {
    b.diagnostics.iter().map(|d| (d.code, d.severity)).collect()
}

fn with_code<'a>(b: &'a Build, code: &str) -> &'a Diagnostic {
    b.diagnostics
        .iter()
        .find(|d| d.code == code)
        .unwrap_or_else(|| panic!("no {code} in {:?}", b.diagnostics))
}

/// A flat unit patch in the L–H plane: x = column, y = row, each 0 to 1 in thirds.
fn unit_patch(letter: char) -> String {
    let points: Vec<String> = (0..16)
        .map(|k| format!("{} {} 0", (k % 4) as f64 / 3.0, (k / 4) as f64 / 3.0))
        .collect();
    format!("#patch {letter} {}", points.join(", "))
}

#[test]
fn a_library_petal_meshes_both_sides_of_two_patches_at_precision_8() {
    let b = ok("#surface a petal\naxiom: F~a(2)");
    let s = &b.plant.skeleton;
    assert_eq!(s.surfaces.len(), 1);
    assert_eq!(s.surfaces[0].kind, SurfaceKind::Declared(0));
    // 2 patches × 9 × 9 points × 2 sides; the segment's tube comes first.
    let tube_vertices = built("axiom: F").plant.mesh.vertex_count();
    assert_eq!(b.plant.mesh.vertex_count(), tube_vertices + 2 * 81 * 2);
    assert_eq!(b.plant.stats.vertices, b.plant.mesh.vertex_count());
    // The petal starts at the top of the segment (y = 1) and is 2 long up H.
    let top = b.plant.stats.bounds[1][1];
    assert!((top - 3.0).abs() < 1e-6, "{top}");
    for n in b.plant.mesh.normals.chunks_exact(3) {
        let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        assert!((l - 1.0).abs() < 1e-4, "{n:?}");
    }
}

#[test]
fn patches_are_placed_by_the_declared_frame_as_cpfg_places_them() {
    // The same unit patch declared twice: once as it is, once in a frame turned and moved, whose
    // contact, heading, up, size and scale bring it back to the same place.
    let plain = ok(&format!("{}\naxiom: ~a", unit_patch('a')));
    let moved_points: Vec<String> = (0..16)
        .map(|k| {
            // x' = 10 + 4·(row), y' = −4·(column), z' = 5: heading along +x', up along +z'.
            let (row, col) = ((k / 4) as f64 / 3.0, (k % 4) as f64 / 3.0);
            format!("{} {} 5", 10.0 + 4.0 * row, -4.0 * col)
        })
        .collect();
    let source = format!(
        "#surface b contact 10 0 5 heading 1 0 0 up 0 0 2 size 8 scale 2\n#patch b {}\naxiom: ~b",
        moved_points.join(", ")
    );
    let moved = ok(&source);
    // Left = heading × up = −y': a point −4 along y' is 4·(2/8) = 1 along L.
    let (a, b) = (&plain.plant.mesh.positions, &moved.plant.mesh.positions);
    assert_eq!(a.len(), b.len());
    for (p, q) in a.iter().zip(b) {
        assert!((p - q).abs() < 1e-5, "{p} {q}");
    }
    // The turtle starts with L = −X, H = +Y: the patch's far corner is at (−1, 1, 0).
    let bounds = plain.plant.stats.bounds;
    assert_eq!(bounds, [[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
}

#[test]
fn three_parameters_scale_along_l_h_and_u_and_an_end_point_moves_the_turtle() {
    let b = ok(&format!(
        "{}\n#surface a end 0 1 0\naxiom: ~a(2, 3, 1)F",
        unit_patch('a')
    ));
    let bounds = b.plant.stats.bounds;
    assert!((bounds[0][0] + 2.0).abs() < 1e-6, "{bounds:?}");
    // The end point (0, 1, 0) moves the turtle 1 × 2 (the first parameter, as cpfg) up H:
    // F then draws from y = 2 to 3.
    let seg = &b.plant.skeleton.segments[0];
    assert_eq!((seg.start.y, seg.end.y), (2.0, 3.0));
    assert!((bounds[1][1] - 3.0).abs() < 1e-6);
}

#[test]
fn undeclared_l_and_p_keep_meristem_s_outlines_and_a_declared_l_replaces_its_own() {
    let own = ok("axiom: ~l");
    assert_eq!(own.plant.skeleton.surfaces[0].kind, SurfaceKind::Leaf);
    let declared = ok("#surface l leaf\naxiom: ~l");
    assert_eq!(
        declared.plant.skeleton.surfaces[0].kind,
        SurfaceKind::Declared(0)
    );
    assert_eq!(declared.plant.mesh.vertex_count(), 2 * 81 * 2);
}

#[test]
fn mistakes_are_diagnostics_with_spans() {
    // 15 points.
    let text = "#patch a 0 0 0, 1 0 0, 2 0 0, 3 0 0, 0 1 0, 1 1 0, 2 1 0, 3 1 0, 0 2 0, 1 2 0, 2 2 0, 3 2 0, 0 3 0, 1 3 0, 2 3 0\naxiom: ~a";
    let b = built(text);
    let d = with_code(&b, "E0220");
    assert!(d.message.contains("found 45 numbers"), "{}", d.message);
    assert_eq!(d.span.start, 0);
    let b = built("#surface a tulip\naxiom: ~a");
    let d = with_code(&b, "E0221");
    assert!(
        d.message.contains("'tulip'") && d.message.contains("petal"),
        "{}",
        d.message
    );
    assert_eq!(&"#surface a tulip"[d.span.clone()], "tulip");
    let b = built("#surface ab petal\naxiom: F");
    assert!(with_code(&b, "E0221").message.contains("'ab'"));
    let b = built("#surface a petal heading 0 1\naxiom: F");
    assert!(with_code(&b, "E0221").message.contains("3 numbers"));
    let b = built("#surface a petal heading 0 0 1\naxiom: F");
    assert!(with_code(&b, "E0221").message.contains("parallel"));
    let b = built(&format!("#surface a petal\n{}\naxiom: F", unit_patch('a')));
    assert!(with_code(&b, "E0221").message.contains("library's petal"));
    let b = built("#patch a 0 0 zero\naxiom: F");
    assert!(with_code(&b, "E0137").message.contains("x y z"));
}

#[test]
fn an_undeclared_surface_warns_and_names_what_is_declared() {
    let b = built("#surface a disk\naxiom: F~q(2)~l");
    assert_eq!(codes(&b), [("E0222", Severity::Warning)]);
    let d = with_code(&b, "E0222");
    assert!(
        d.message.contains("~q") && d.message.contains("~a"),
        "{}",
        d.message
    );
    assert_eq!(&"#surface a disk\naxiom: F~q(2)~l"[d.span.clone()], "~q(2)");
    // It draws nothing; the plant still builds.
    assert_eq!(b.plant.skeleton.surfaces.len(), 1);
}

#[test]
fn limits_hold_precision_and_patches() {
    let b = built("#surface a petal precision 0 100\naxiom: ~a");
    assert_eq!(
        codes(&b),
        [("E0223", Severity::Warning), ("E0223", Severity::Warning)]
    );
    assert_eq!(b.plant.skeleton.shapes[0].precision, [1, 32]);
    let many: Vec<String> = (0..65).map(|_| unit_patch('a')).collect();
    let b = built(&format!("{}\naxiom: ~a", many.join("\n")));
    assert!(with_code(&b, "E0221")
        .message
        .contains("more than 64 patches"));
    let model = b.model.as_ref().expect("a model");
    assert_eq!(model.settings.surfaces[0].patches.len(), 64);
}

#[test]
fn written_points_keep_their_text_spans_for_an_editor() {
    let text = format!("{}\naxiom: ~a", unit_patch('a'));
    let b = ok(&text);
    let written = &b.plant.skeleton.shapes[0].written;
    assert_eq!(written.len(), 16);
    assert_eq!(
        &text[written[5].span.clone()],
        "0.3333333333333333 0.3333333333333333 0"
    );
    assert_eq!(written[5].index, 5);
}

#[test]
fn a_growing_surface_grows_from_its_contact_point() {
    let options = BuildOptions {
        iterations: Some(1),
        mesh: MeshOptions {
            growth: true,
            ..MeshOptions::default()
        },
        ..BuildOptions::default()
    };
    let b = build("#surface a petal\naxiom: A\nA -> F~a", &options);
    assert!(b.ok());
    let mesh = &b.plant.mesh;
    let n = mesh.vertex_count();
    // The petal's vertices all grow from the top of the segment, (0, 1, 0).
    let origins = &mesh.growth_origins[3 * (n - 2 * 81 * 2)..];
    for o in origins.chunks_exact(3) {
        assert_eq!(o, [0.0, 1.0, 0.0]);
    }
}

/// Two unit patches side by side (the second one over along L), the first in colour 3, the
/// second 5 on top and 7 underneath, and a third with no colour of its own.
fn coloured_patches() -> String {
    let row = |dx: f64| -> String {
        (0..16)
            .map(|k| format!("{} {} 0", dx + (k % 4) as f64 / 3.0, (k / 4) as f64 / 3.0))
            .collect::<Vec<_>>()
            .join(", ")
    };
    format!(
        "#color 1 200 200 200\n#color 3 255 0 0\n#color 5 0 0 255\n#color 7 0 255 0\n#patch a {} color 3\n#patch a {} color 5 7\n#patch a {}\naxiom: ;(1)~a",
        row(0.0),
        row(2.0),
        row(4.0)
    )
}

#[test]
fn patch_colours_win_over_the_turtle_s_as_cpfg_s_do_and_reach_every_export() {
    let b = ok(&coloured_patches());
    let mesh = &b.plant.mesh;
    // Per patch 6 × 6 points a side (precision 5, the default): the fronts of patches 0, 1, 2,
    // then their backs.
    let per = 36;
    assert_eq!(mesh.vertex_count(), 6 * per);
    let colour = |v: usize| {
        let c = &mesh.colors[3 * v..3 * v + 3];
        [c[0], c[1], c[2]].map(|x| (x * 255.0).round() as u8)
    };
    let skeleton = &b.plant.skeleton;
    let srgb = |i: u16| skeleton.color(i).map(|x| (x * 255.0).round() as u8);
    // Front: 3, 5, the turtle's 1; back: 3, 7, 1.
    for (k, index) in [3u16, 5, 1, 3, 7, 1].into_iter().enumerate() {
        assert_eq!(colour(k * per), srgb(index), "part {k}");
        assert_eq!(colour(k * per + per - 1), srgb(index), "part {k}");
    }
    assert_ne!(srgb(3), srgb(1));
    // Each triangle's colour index, as the writers group them.
    let indices: Vec<u32> = mesh.color_ranges.chunks_exact(2).map(|r| r[1]).collect();
    assert_eq!(indices, [3, 5, 1, 3, 7, 1]);
    // OBJ: one material per colour index; the same for glTF, VRML, POV-Ray and Inventor.
    use meristem::export::{export, Format};
    let files = export(Format::Obj, mesh, skeleton, "plant");
    let mtl = String::from_utf8_lossy(&files[1].bytes).into_owned();
    for index in [1, 3, 5, 7] {
        assert!(mtl.contains(&format!("newmtl color_{index}\n")), "{mtl}");
    }
    let glb = &export(Format::Glb, mesh, skeleton, "plant")[0].bytes;
    let json = String::from_utf8_lossy(&glb[20..]).into_owned();
    for index in [1, 3, 5, 7] {
        assert!(json.contains(&format!("\"color_{index}_leaf\"")), "{index}");
    }
    let wrl = String::from_utf8_lossy(&export(Format::Vrml, mesh, skeleton, "plant")[0].bytes)
        .into_owned();
    for index in [1, 3, 5, 7] {
        assert!(
            wrl.contains(&format!("# colour index {index}\n")),
            "{index}"
        );
    }
}

#[test]
fn patch_colours_that_are_not_colour_indices_are_errors_with_spans() {
    for (bad, word) in [
        ("color", "color"),
        ("color 1 2 3", "color 1 2 3"),
        ("color -1", "color -1"),
        ("color 2.5", "color 2.5"),
    ] {
        let source = format!("{} {bad}\naxiom: ~a", unit_patch('a'));
        let b = built(&source);
        let d = with_code(&b, "E0220");
        assert_eq!(&source[d.span.clone()], word, "{bad}");
        assert!(
            d.message.contains("one or two colour indices"),
            "{}",
            d.message
        );
    }
    // A word that is not `color` after the points is still not a number.
    let b = built(&format!("{} colour 3\naxiom: ~a", unit_patch('a')));
    assert!(
        codes(&b).iter().any(|(c, _)| *c == "E0137"),
        "{:?}",
        b.diagnostics
    );
}
