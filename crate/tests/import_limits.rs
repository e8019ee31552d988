//! Issue 50, finding 6: importer inputs of a few kilobytes (or a few hundred) that made output
//! orders of magnitude larger than themselves, or ran for minutes. Each must give a translation
//! of about its own size, or a note saying what was left out. No test here measures time: each
//! counts the output's bytes or reads the note (the quadratic search of finding 6d is counted in
//! `import/abop/cpfg/joins.rs`'s tests).
#![cfg(not(target_arch = "wasm32"))]

use meristem::import::{self, Dialect, Import, ObjectFile};

fn file(name: &str, text: &str) -> ObjectFile {
    ObjectFile {
        name: name.into(),
        bytes: text.as_bytes().to_vec(),
    }
}

fn said(import: &Import, piece: &str) -> bool {
    import.notes.iter().any(|n| n.message.contains(piece))
}

fn notes(import: &Import) -> Vec<&str> {
    import.notes.iter().map(|n| n.message.as_str()).collect()
}

/// Letters from a fixed sequence (no randomness: the same text every run).
fn letters(count: usize, separator: &str) -> String {
    let alphabet = ['A', 'B', 'C', 'D', 'E', 'G', 'H', 'J', 'K'];
    (0..count)
        .map(|i| alphabet[(i * 7 + i / 9) % alphabet.len()].to_string())
        .collect::<Vec<_>>()
        .join(separator)
}

/// 6a: a predecessor of 5,000 letters with an axiom of 1,000 modules (6 KB) made 25 MB of text
/// and took 3.9 GB (each module a production with the 4,999 others as its context).
#[test]
fn a_predecessor_of_5000_letters_imports_small_with_a_note() {
    let text = format!(
        "Lsystem: 1\nderivation length: 2\nAxiom: {}\n{} --> F\nendlsystem\n",
        letters(1000, ""),
        letters(5000, "")
    );
    let imported = import::import(&text, Dialect::Cpfg);
    assert!(
        imported.text.len() < 2 * text.len(),
        "{} bytes from {}",
        imported.text.len(),
        text.len()
    );
    assert!(
        said(&imported, "is 5000 modules, more than the 64"),
        "{:?}",
        notes(&imported)
    );
    assert!(!imported.is_empty());
}

/// A function set of `count` functions of `samples` samples each.
fn function_set(count: usize, samples: usize) -> String {
    let mut text = format!("funcgalleryver 1 1\nitems: {count}\n");
    for k in 0..count {
        text.push_str(&format!(
            "fver 1 1\nname: F{k}\nsamples: {samples}\nflip: off\npoints: 4\n0 0\n0.3 0.{}\n0.6 0.{}\n1 1\n",
            k % 10,
            (k / 10) % 10
        ));
    }
    text
}

/// An lpfg object whose L-system produces `F(func(NAME, 0.5))` for each name.
fn object_reading(fset: &str, names: &[String]) -> Vec<ObjectFile> {
    let calls: String = names
        .iter()
        .map(|n| format!("F(func({n}, 0.5)) "))
        .collect();
    let plant = format!(
        "#include <lpfgall.h>\nmodule A(float);\nderivation length: 2;\nAxiom: A(0);\nproduction:\nA(t) :\n{{\n\tproduce {calls}A(t+1);\n}}\n"
    );
    vec![
        file(
            "specifications",
            "plant.l\nfunctions.fset\n*\nmodel:\n\tgenerate:\n\t\tlpfg plant.l functions.fset\n",
        ),
        file("plant.l", &plant),
        file("functions.fset", fset),
    ]
}

/// 6b: a `.fset` of 5,000 functions of 1,000 samples (374 KB) made a 125 MB translation: every
/// function was sampled and written. Only those the L-system reads are; a comment names the
/// others.
#[test]
fn only_the_functions_the_l_system_reads_are_written() {
    let fset = function_set(5000, 1000);
    let imported = import::import_object(&object_reading(&fset, &["F7".to_string()]));
    assert!(
        imported.text.len() < 100_000,
        "{} bytes from {}",
        imported.text.len(),
        fset.len()
    );
    assert!(
        imported.text.contains("\n#table F7 0 "),
        "{}",
        imported.text
    );
    assert!(!imported.text.contains("#table F8 "));
    assert!(imported.text.contains(
        "// Not written: the object's functions F0, F1, F2, F3, F4, F5, F6, F8, F9, F10 and 4989 more (the L-system does not read them).\n"
    ));
    assert!(imported.text.contains("F(F7(0.5))"), "{}", imported.text);
}

/// 6b: the functions an L-system reads take at most 1 MB of text; a call of one past it is
/// noted and left out.
#[test]
fn the_functions_an_l_system_reads_are_capped_with_a_note() {
    let fset = function_set(100, 1000);
    let names: Vec<String> = (0..100).map(|k| format!("F{k}")).collect();
    let imported = import::import_object(&object_reading(&fset, &names));
    assert!(
        imported.text.len() < 1_100_000,
        "{} bytes",
        imported.text.len()
    );
    assert!(
        said(
            &imported,
            "is not written: with it, the functions the L-system reads would take more than 1 MB of text"
        ),
        "{:?}",
        notes(&imported)
    );
}

/// 6c: an array of a million values (2 MB) made a 2.5 GB translation: each read writes every
/// value in a choice by index.
#[test]
fn an_array_of_a_million_values_is_noted_not_written() {
    let values = vec!["1"; 1_000_000].join(",");
    let text = format!(
        "Lsystem: 1\nDefine: {{ array a[1000][1000] = {{{values}}}; }}\nderivation length: 2\nAxiom: A(1,2)\nA(i,j) --> F(a[i][j])A(i,j)\nendlsystem\n"
    );
    let imported = import::import(&text, Dialect::Cpfg);
    assert!(
        imported.text.len() < 10_000,
        "{} bytes",
        imported.text.len()
    );
    let notes_bytes: usize = imported.notes.iter().map(|n| n.message.len()).sum();
    assert!(notes_bytes < 10_000, "{notes_bytes} bytes of notes");
    assert!(
        said(
            &imported,
            "array a has 1000000 values, more than the 1000 Meristem writes"
        ),
        "{:?}",
        notes(&imported)
    );
}

/// 6c: a note about a translation Meristem rejects quotes the start of the line, not all of it
/// (the array above, read by a line the importer wrote whole, gave a 35 MB note).
#[test]
fn a_note_quotes_a_long_rejected_line_by_its_start() {
    // 300 values: the array is written, and its read is too long for Meristem's expressions.
    let values = vec!["1"; 300].join(",");
    let reads = vec!["F(a[i][j])"; 40].join("");
    let text = format!(
        "Lsystem: 1\nDefine: {{ array a[20][15] = {{{values}}}; }}\nderivation length: 2\nAxiom: A(1,2)\nA(i,j) --> {reads}A(i,j)\nendlsystem\n"
    );
    let imported = import::import(&text, Dialect::Cpfg);
    for n in &imported.notes {
        assert!(n.message.len() < 2_000, "{}", n.message.len());
    }
}

/// 6d: 200,000 lines continued by `\` (600 KB) took 25 s: each of the empty lines left in their
/// place searched on to the end for the next line with code. The axiom is one line.
#[test]
fn two_hundred_thousand_continued_lines_are_one_axiom() {
    let text = format!(
        "Lsystem: 1\nderivation length: 2\nAxiom: F\\\n{}F\nF --> FF\nendlsystem\n",
        "F\\\n".repeat(200_000)
    );
    let imported = import::import(&text, Dialect::Cpfg);
    let axiom = imported
        .text
        .lines()
        .find(|l| l.starts_with("axiom:"))
        .expect("an axiom");
    assert_eq!(axiom.matches('F').count(), 200_002);
    assert!(imported.notes.is_empty(), "{:?}", notes(&imported));
}

/// 6e: eight files of 400 bytes, each including all eight three times, ran for minutes (24
/// includes a file, eight deep): what `#include` brings in is bounded in total, 1 MB.
#[test]
fn files_that_include_each_other_bring_in_at_most_a_megabyte() {
    let names: Vec<String> = (0..8).map(|k| format!("f{k}.h")).collect();
    let mut files: Vec<ObjectFile> = names
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let includes: String = names
                .iter()
                .flat_map(|m| std::iter::repeat_n(format!("#include \"{m}\"\n"), 3))
                .collect();
            file(name, &format!("#define X{k} 1\n{includes}"))
        })
        .collect();
    files.push(file(
        "plant.l",
        "#include \"f0.h\"\nLsystem: 1\nderivation length: 2\nAxiom: F\nF --> FF\nendlsystem\n",
    ));
    let imported = import::import_object(&files);
    assert!(
        said(
            &imported,
            "and those after it are left out: the files they include would bring in more than 1 MB together"
        ),
        "{:?}",
        notes(&imported)
    );
    assert!(
        imported.text.len() < 1 << 20,
        "{} bytes",
        imported.text.len()
    );
    assert!(imported.text.contains("\naxiom: F\n"), "{}", imported.text);
}

/// 6f: a `.func` of 500,000 points took 37 s (each of its samples weighs every point) and its
/// comment quoted them all.
#[test]
fn a_function_of_half_a_million_points_is_noted_not_read() {
    let n = 500_000;
    let mut func = format!("fver 1 1\nname: BIG\nsamples: 100\nflip: off\npoints: {n}\n");
    for i in 0..n {
        func.push_str(&format!(
            "{} {}\n",
            i as f64 / (n - 1) as f64,
            (i % 13) as f64 / 13.0
        ));
    }
    let files = vec![
        file(
            "specifications",
            "plant.l\nbig.func\n*\nmodel:\n\tgenerate:\n\t\tlpfg plant.l big.func\n",
        ),
        file(
            "plant.l",
            "#include <lpfgall.h>\nmodule A(float);\nderivation length: 2;\nAxiom: A(0);\nproduction:\nA(t) :\n{\n\tproduce F(func(BIG, 0.5)) A(t+1);\n}\n",
        ),
        file("big.func", &func),
    ];
    let imported = import::import_object(&files);
    assert!(
        imported.text.len() < 10_000,
        "{} bytes",
        imported.text.len()
    );
    assert!(
        said(
            &imported,
            "big.func: the function BIG has more than 100 control points (with their multiplicities), more than Meristem reads: it is not translated"
        ),
        "{:?}",
        notes(&imported)
    );
}

/// The comment naming the functions not written quotes the files' names without their line
/// breaks (Meristem's parser ends a line at a `\r`: the rest would be code).
#[test]
fn the_functions_not_written_are_named_on_one_line() {
    let fset = function_set(2, 10).replace("name: F1\n", "name: F\r1\n");
    let imported = import::import_object(&object_reading(&fset, &["F0".to_string()]));
    assert!(
        imported.text.contains(
            "// Not written: the object's functions F 1 (the L-system does not read them).\n"
        ),
        "{}",
        imported.text
    );
    assert!(
        !said(&imported, "Meristem rejects"),
        "{:?}",
        notes(&imported)
    );
}

/// The same predecessor in an L+C file: the note names lpfg, whose file it is (it said "cpfg's
/// predecessor": lpfg's files are read as cpfg's).
#[test]
fn an_lpfg_predecessor_of_5000_modules_is_named_as_lpfg_s() {
    let text = format!(
        "#include <lpfgall.h>\nderivation length: 2;\nAxiom: {};\nproduction:\n{}:\n{{\n\tproduce F;\n}}\n",
        letters(100, " "),
        letters(5000, " ")
    );
    let imported = import::import(&text, Dialect::Cpfg);
    assert!(
        said(
            &imported,
            "lpfg's predecessor here is 5000 modules, more than the 64"
        ),
        "{:?}",
        notes(&imported)
    );
    assert!(!notes(&imported)
        .iter()
        .any(|n| n.contains("cpfg's predecessor")));
}

/// A line of 3,000 uses of a macro that does not grow: the note says which limit it passed
/// (before: "a macro here expands without end; the line is left as it is", neither true).
#[test]
fn a_line_of_many_macro_uses_says_which_limit_it_passed() {
    let text = format!(
        "#define X F\nLsystem: 1\nderivation length: 1\nAxiom: {}\nendlsystem\n",
        vec!["X"; 3000].join(" ")
    );
    let imported = import::import(&text, Dialect::Cpfg);
    assert!(
        said(
            &imported,
            "expand more than 2000 times or past 100000 characters"
        ),
        "{:?}",
        notes(&imported)
    );
    assert!(said(&imported, "the rest of the line is left unexpanded"));
}
