use super::*;

fn file(name: &str, text: &str) -> ObjectFile {
    ObjectFile {
        name: name.into(),
        bytes: text.as_bytes().to_vec(),
    }
}

fn stats(text: &str) -> crate::export::Stats {
    let build = crate::pipeline::build(text, &crate::BuildOptions::default());
    assert!(build.ok(), "{text}\n{:?}", build.diagnostics);
    build.plant.stats.clone()
}

#[test]
fn an_lpy_run_becomes_its_string_as_an_axiom_with_a_header_colours_and_notes() {
    let source = "module Apex\nAxiom: Apex(1)\nderivation length: 3\nproduction:\n\
                  Apex(x) :\n  produce F(x)[+(30)Apex(x/2)]\n";
    let result = r#"{"ok": true, "dialect": "lpy", "steps": 3,
        "lstring": "F(1)[+(30)F(0.5)[+(30)Apex(0.125)]]F(1e-05)Apex(True)",
        "materials": [{"index": 2, "rgb": [10, 200.4, 300]}],
        "notes": [{"line": 5, "message": "something not reproduced"}], "error": null}"#;
    let import = import_derived(result, "tree.lpy", &[file("tree.lpy", source)], 7);
    assert!(import
        .text
        .starts_with("// Derived by Python from tree.lpy in 3 steps, with seed 7"));
    assert!(
        import.text.contains("#color 2 10 200 255"),
        "{}",
        import.text
    );
    assert!(import.text.contains("#module Apex"), "{}", import.text);
    assert!(import.text.contains("F(0.00001)Apex(1)"), "{}", import.text);
    assert!(import.text.contains("derivation length: 0"));
    assert_eq!(import.notes.len(), 1, "{:?}", import.notes);
    assert_eq!(import.notes[0].line, 5);
    // Three segments (the 0.00001 one too), by hand.
    assert_eq!(stats(&import.text).segments, 3);
}

#[test]
fn python_objects_as_parameters_are_dropped_with_a_note() {
    let result = r#"{"ok": true, "dialect": "lpy", "steps": 1,
        "lstring": "F(1)Leaf(@obj0,2)Leaf(@obj1,3)F(2)", "materials": [], "notes": [], "error": null}"#;
    let import = import_derived(result, "x.lpy", &[file("x.lpy", "module Leaf\n")], 0);
    assert!(
        import.text.contains("F(1)Leaf Leaf F(2)") || import.text.contains("F(1)LeafLeafF(2)"),
        "{}",
        import.text
    );
    assert_eq!(import.notes.len(), 1, "{:?}", import.notes);
    assert!(import.notes[0]
        .message
        .starts_with("2 module(s) Leaf carry Python objects"));
    assert_eq!(stats(&import.text).segments, 2);
}

#[test]
fn an_error_gives_no_text_and_a_note_at_its_line_and_the_translation_is_kept() {
    let result = r#"{"ok": false, "dialect": "lpy", "steps": 0, "lstring": "", "materials": [],
        "notes": [], "error": {"line": 12, "column": 5, "message": "NameError: name 'q' is not defined"}}"#;
    let derived = import_derived(result, "x.lpy", &[], 0);
    assert!(derived.is_empty());
    assert_eq!(derived.notes[0].line, 12);
    assert!(derived.notes[0].message.contains("column 5: NameError"));
    let translation = import("Axiom: F\n", Dialect::Lpy);
    let kept = prefer_derived(translation.clone(), derived);
    assert_eq!(kept.text, translation.text);
    assert!(kept.notes[0]
        .message
        .ends_with("the hand translation is used"));
    let garbage = import_derived("{not json", "x.lpy", &[], 0);
    assert!(garbage.is_empty() && garbage.notes[0].message.contains("cannot be read"));
}

#[test]
fn an_lpfg_run_replaces_the_objects_l_and_keeps_its_view_and_colours() {
    let l = "#include <lpfgall.h>\nderivation length: 2;\nmodule A(float);\nAxiom: A(1);\n\
             A(x): { produce F(x) SB() Left(45) A(x/2) EB(); }\n";
    let files = [
        file("o/specifications", "lpfg lsystem.l view.v color.map\n"),
        file("o/lsystem.l", l),
        file("o/view.v", "line style: cylinder\n"),
        file("o/color.map", "255 0 0\n0 255 0\n"),
    ];
    let result = r#"{"ok": true, "dialect": "lpfg", "steps": 2,
        "lstring": "SetColor(1)F(1)SB()Left(45)F(0.5)SB()Left(45)Apex()EB()EB()",
        "materials": [{"index": 1, "rgb": [1, 2, 3]}], "notes": [], "error": null}"#;
    let import = import_derived(result, "o/lsystem.l", &files, 0);
    assert!(
        import
            .text
            .contains("axiom: ;(1)F(1)[+(45)F(0.5)[+(45)Apex]]"),
        "{}",
        import.text
    );
    assert!(import.text.contains("#module Apex"), "{}", import.text);
    assert!(
        !import.text.contains("#color 1 1 2 3"),
        "the object's colour map wins"
    );
    assert!(
        import.notes.iter().all(|n| n.line == 0),
        "{:?}",
        import.notes
    );
    assert_eq!(stats(&import.text).segments, 2);
}

#[test]
fn python_is_needed_when_the_translation_has_notes_or_draws_nothing() {
    let clean = import("Axiom: F\n", Dialect::Lpy);
    assert!(clean.notes.is_empty(), "{:?}", clean.notes);
    assert!(!needs_python(&clean));
    let nothing = import("Axiom: A\n", Dialect::Lpy);
    assert!(needs_python(&nothing));
    // An apex that lays its first internode after 20 steps (L-Py's continuous growth) draws:
    // the hand translation is kept.
    let late = import(
        "Axiom: A(0)\nderivation length: 40\nproduction:\nA(t) :\n    if t < 20:\n        produce A(t+1)\n    else:\n        produce F A(0)\nendlsystem\n",
        Dialect::Lpy,
    );
    assert!(late.notes.is_empty(), "{:?}", late.notes);
    assert!(!needs_python(&late));
    let never = import(
        "Axiom: A\nderivation length: 500\nproduction:\nA --> A\nendlsystem\n",
        Dialect::Lpy,
    );
    assert!(needs_python(&never), "nothing drawn after 100 steps");
    let noted = import("import numpy\nAxiom: F(1)\n", Dialect::Lpy);
    assert!(!noted.notes.is_empty());
    assert!(needs_python(&noted));
    // Python's modules of numbers lose nothing: their names are translated where they are used.
    for numbers in [
        "import math",
        "from math import *",
        "from random import uniform, seed",
        "import math, random",
    ] {
        let clean = import(&format!("{numbers}\nAxiom: F(math.pi)\n"), Dialect::Lpy);
        assert!(clean.notes.is_empty(), "{numbers}: {:?}", clean.notes);
        assert!(!needs_python(&clean), "{numbers}");
    }
    let unknown = import("from math import erf\nAxiom: F(erf(1))\n", Dialect::Lpy);
    assert!(
        needs_python(&unknown),
        "a name Meristem lacks is noted where it is used"
    );
    assert!(needs_python(&Import::default()));
}

#[test]
fn lpfgs_polygons_and_circles_are_drawn() {
    let files = [
        file("o/specifications", "lpfg lsystem.l view.v\n"),
        file("o/lsystem.l", "module A();\nAxiom: A();\n"),
        file("o/view.v", ""),
    ];
    let result = r#"{"ok": true, "dialect": "lpfg", "steps": 1,
        "lstring": "SP()F(1)Left(90)F(1)Left(90)F(1)EP()IncColor()Circle(0.5)Circle0()",
        "materials": [], "notes": [], "error": null}"#;
    let import = import_derived(result, "o/lsystem.l", &files, 0);
    assert!(
        import
            .text
            .contains("axiom: {F(1)+(90)F(1)+(90)F(1)}'@O(0.5)@O"),
        "{}",
        import.text
    );
    assert!(import
        .notes
        .iter()
        .any(|n| n.message.contains("Circle draws a disc")));
    // The F inside the polygon are its edges, not segments.
    let stats = stats(&import.text);
    assert_eq!(stats.segments, 0);
    assert!(stats.triangles > 0);
}
