//! The environmental programs of real vlab objects (`tests/import-environment/SOURCES.md`):
//! those whose meaning matches one of Meristem's programs become `#environment` lines with a note
//! saying what differs, the others leave `?E` inert with a note naming the missing program
//! (docs/LANGUAGE.md, "Importing other dialects").
#![cfg(not(target_arch = "wasm32"))]

mod shared;

use meristem::import::{self, Import};
use meristem::pipeline::{build, BuildOptions};
use shared::object;
use std::path::PathBuf;

fn tests() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests")
}

/// The object `name`: its files here, with those the import corpus already holds (`12-two-trees`
/// is there without its environment files).
fn imported(name: &str) -> Import {
    let mut files = object(&tests().join("import-environment").join(name));
    if name == "cpfg-12-two-trees" {
        files.extend(object(&tests().join("import-corpus/vlab/12-two-trees")));
    }
    import::import_object(&files)
}

/// The notes whose message contains `piece`.
fn notes_with<'a>(import: &'a Import, piece: &str) -> Vec<&'a str> {
    import
        .notes
        .iter()
        .filter(|n| n.message.contains(piece))
        .map(|n| n.message.as_str())
        .collect()
}

#[test]
fn one_chiba_light_source_becomes_the_sun() {
    let i = imported("cpfg-10-light-three-spheres");
    // light.spec: `source direction: 50 100 0 4` (the only one), `transmittance: 0.0`.
    assert!(
        i.text
            .contains("#environment light sky 0 sun 1 sun_direction 50 100 0 absorb 1\n"),
        "{}",
        i.text
    );
    let mapped = notes_with(&i, "chiba (light through leaf balls");
    assert_eq!(mapped.len(), 1);
    assert!(mapped[0].contains("the light (0 to 1) into the ?E's first parameter"));
    assert!(mapped[0].contains("the parts the turtle draws shade"));
    // At the first ?E (line 8 of balls.l: the axiom).
    let at_e: Vec<_> = i
        .notes
        .iter()
        .filter(|n| n.message.starts_with("?E(…) is answered"))
        .collect();
    assert_eq!(at_e.len(), 1);
    assert_eq!(at_e[0].line, 8);
    assert!(at_e[0].message.contains("chiba"));
}

#[test]
fn nine_chiba_sources_are_a_sun_and_a_sky() {
    let i = imported("cpfg-12-two-trees");
    // Intensities 4 (overhead), 3 × 4 and 2 × 4: 24 in all; the overhead one is 4/24 = 1/6.
    assert!(
        i.text.contains(
            "#environment light sky 0.833333333333 sun 0.166666666667 sun_direction 0 100 0 absorb 0.75\n"
        ),
        "{}",
        i.text
    );
    let sources = notes_with(&i, "chiba's 9 light sources");
    assert_eq!(sources.len(), 1);
    assert!(sources[0].contains("towards 0 100 0, 17 %"));
    assert_eq!(notes_with(&i, "?E(…) is answered between steps").len(), 1);
    assert!(notes_with(&i, "Meristem runs no environment program").is_empty());
}

#[test]
fn honda81_becomes_collision_and_the_tentacles_that_meet_stop() {
    for object in ["cpfg-01-ulam-collide", "lpfg-01-ulam-collide"] {
        let i = imported(object);
        // density.spec: `radius: 0.01`, `3d case: on`.
        assert!(
            i.text.contains("\n#environment collision radius 0.01\n"),
            "{object}: {}",
            i.text
        );
        assert!(
            notes_with(&i, "honda81").is_empty(),
            "{object}: {:?}",
            i.notes
        );
        assert!(
            notes_with(&i, "?E(…)").is_empty(),
            "{object}: {:?}",
            i.notes
        );
    }
    // cpfg's object, one step: the axiom's four arms of length 1 (90° apart) each end in an apex
    // that decomposes into three tentacles f?E: straight on, and 90° to either side. The side
    // tentacles of neighbouring arms reach the same corner (1, 1), (1, −1), … and stop each other
    // (equal vigor); the four straight ones are free and each draws one F: 4 + 4 segments.
    let cpfg = imported("cpfg-01-ulam-collide");
    let b = build(&cpfg.text, &BuildOptions::default());
    assert!(b.ok(), "{:?}", b.diagnostics);
    assert_eq!(b.plant.stats.segments, 8);
    // lpfg's E1(x) is cpfg's ?E(x), `A()` is `A`, and the predecessor `f(l)E1(x)` is two
    // productions with each other as context, as cpfg's `f?E(x)` is.
    let lpfg = imported("lpfg-01-ulam-collide");
    assert!(notes_with(&lpfg, "lpfg's E1").is_empty());
    for line in [
        "axiom: !(WIDTH)[F(LENGTH)A][-(ANGLE)F(LENGTH)A][+(ANGLE)F(LENGTH)A][|F(LENGTH)A]\n",
        // lpfg's IncColor() is Meristem's ' (the next colour).
        "f(l) > ?E(x) : x == 1 -> 'F(l)A\n",
        "f(l) < ?E(x) : x == 1 -> ε\n",
        "A -> [-(ANGLE)f(LENGTH)?E(VIGOR)][+(ANGLE)f(LENGTH)?E(VIGOR)][f(LENGTH)?E(VIGOR)]\n",
    ] {
        assert!(lpfg.text.contains(line), "{line}{}", lpfg.text);
    }
    assert!(
        notes_with(&lpfg, "Meristem rejects").is_empty(),
        "{:?}",
        lpfg.notes
    );
    // The same first step as cpfg's: 4 + 4 segments.
    let one = BuildOptions {
        iterations: Some(1),
        ..BuildOptions::default()
    };
    let b = build(&lpfg.text, &one);
    assert!(b.ok(), "{:?}", b.diagnostics);
    assert_eq!(b.plant.stats.segments, 8);
}

#[test]
fn a_program_meristem_lacks_is_named() {
    let i = imported("cpfg-13-clover");
    let missing = notes_with(&i, "enviro.e runs the environmental program clover");
    assert_eq!(missing.len(), 1);
    assert!(!i.text.contains("#environment"));
    let at_e = notes_with(&i, "?E(…) asks the object's environmental program clover");
    assert_eq!(at_e.len(), 1);
}

#[test]
fn an_l_file_alone_says_the_e_file_was_not_opened() {
    let text =
        std::fs::read_to_string(tests().join("import-corpus/vlab/12-two-trees/tree.l")).unwrap();
    let i = import::import(&text, import::Dialect::Cpfg);
    assert_eq!(
        notes_with(&i, "the object's .e file, which names it, was not opened").len(),
        1
    );
    assert!(!i.text.contains("#environment"));
}

#[test]
fn obstacles_crossed_by_a_path_are_not_meristem_s_solids() {
    // obstacles.dat: 14 lines of the Celtic knot's frame (x0 y0 x1 y1 each).
    let i = imported("cpfg-CelticKnot");
    let missing = notes_with(&i, "enviro.e runs obcheck: 14 line obstacles");
    assert_eq!(missing.len(), 1, "{:?}", i.notes);
    assert!(!i.text.lines().any(|l| l.contains("#environment")));
    assert_eq!(
        notes_with(
            &i,
            "environmental program obcheck, which Meristem does not have"
        )
        .len(),
        1
    );
    let b = build(&i.text, &BuildOptions::default());
    assert!(b.ok(), "{:?}", b.diagnostics);
}
