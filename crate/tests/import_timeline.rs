//! lpfg's timeline functions (a `.tset` of vlab's `timeline` tool, read as `tfunc(NAME, t)`) and
//! values (a `.vset`, read as `val(NAME)`) imported with their object: a small object written for
//! these tests, whose lengths are checked by hand against lpfg's formula (`Interface::TFunc`,
//! `Func`, `Function::GetValue`), and vlab's Lychnis (VlabTools), whose files must read without a
//! note (sources and licence in `tests/import-timeline/SOURCES.md`).
#![cfg(not(target_arch = "wasm32"))]

mod shared;

use meristem::import::{self, Dialect, Import, ObjectFile};
use meristem::pipeline::{build, BuildOptions};
use std::path::PathBuf;

fn file(name: &str, text: &str) -> ObjectFile {
    ObjectFile {
        name: name.into(),
        bytes: text.as_bytes().to_vec(),
    }
}

/// lpfg numbers the `.fset` first whatever the command line's order: WIDTH is 1, GROWTH 2,
/// SCALE 3.
const SPECIFICATIONS: &str = "plant.l\nfunctions.tset\nvalues.vset\nfunctions.fset\n*\nmodel:\n\tgenerate:\n\t\tlpfg plant.l functions.tset values.vset functions.fset\n";

/// GROWTH runs from t = 2 to t = 8, the values BEGIN and FINISH (vlab's timeline tool ties its
/// ends to them). Its control points' x are 0, ⅓, ⅔, 1 and their y 1, 1, 1, 3:
/// the clamped cubic B-spline of four points is their Bézier curve, whose x is its parameter u
/// and whose y is 1 + 2u³. lpfg reads it through 21 samples (x = 0, 0.05, … 1).
const TSET: &str = "timeEdit 1 2
items: 1
start: 2
end: 8
name: GROWTH
color: 91,115,229
startLabel: BEGIN
endLabel: FINISH
timelineFunceditFileStart:
fver 1 1
name: GROWTH
samples: 21
flip: off
points: 4
0.000000 1.000000
0.333333 1.000000
0.666667 1.000000
1.000000 3.000000
timelineFunceditFileEnd:
";

/// WIDTH: y = u³ the same way, so WIDTH at 0.5 is 1/8.
const FSET: &str = "funcgalleryver 1 1
items: 1
fver 1 1
name: WIDTH
samples: 21
flip: off
points: 4
0.000000 0.000000
0.333333 0.000000
0.666667 0.000000
1.000000 1.000000
";

const VSET: &str = "#define SCALE 2\n#define BEGIN 2\n#define FINISH 8\n";

/// Each A(t) draws 2·GROWTH at t; B draws the same by numbers, then 8 · WIDTH(0.5) through
/// `func` and `tfunc` (an `.fset` function's times are 0 and 1).
const PLANT: &str = "#include <lpfgall.h>

module A(float);
module B(float);

derivation length: 1;

Axiom: A(0) A(2) A(3.5) A(5) A(5.15) A(8) A(10) B(5.15);

production:

A(t) :
{
\tproduce F(val(SCALE) * tfunc(GROWTH, t));
}

B(t) :
{
\tproduce F(val(3) * tfunc(2, t)) F(8 * func(WIDTH, 0.5)) F(8 * tfunc(1, 0.5));
}
";

fn object(tset: &str, vset: &str) -> Vec<ObjectFile> {
    vec![
        file("specifications", SPECIFICATIONS),
        file("plant.l", PLANT),
        file("functions.tset", tset),
        file("functions.fset", FSET),
        file("values.vset", vset),
    ]
}

/// lpfg's `tfunc(GROWTH, t)`: v = (t − start)/(end − start) clamped to 0…1 (`TFunc`, `Func`),
/// then the 21 samples of 1 + 2x³ joined by straight lines (`GetValue`).
fn lpfg_growth(t: f64) -> f64 {
    let y = |x: f64| 1.0 + 2.0 * x.powi(3);
    let v = ((t - 2.0) / (8.0 - 2.0)).clamp(0.0, 1.0);
    let index = v * 20.0;
    let i = index.floor();
    if i >= 20.0 {
        return y(1.0);
    }
    let w = index - i;
    (1.0 - w) * y(i / 20.0) + w * y((i + 1.0) / 20.0)
}

fn messages(import: &Import) -> Vec<&str> {
    import.notes.iter().map(|n| n.message.as_str()).collect()
}

#[test]
fn tfunc_and_val_give_lpfgs_lengths_at_the_start_middle_and_end_of_a_timeline() {
    let result = import::import_object(&object(TSET, VSET));
    // The object has no view file nor colours: those two notes and no other.
    assert_eq!(result.notes.len(), 2, "{:?}", messages(&result));
    assert!(result
        .text
        .contains("#define SCALE 2 // val(SCALE) of values.vset"));
    assert!(
        result
            .text
            .contains("A(t) -> F(SCALE * GROWTH(((t)-BEGIN)/(FINISH-BEGIN)))\n"),
        "{}",
        result.text
    );
    // By hand: t = 0 and 2 are before or at the start (1 + 0 = 1); t = 3.5 is x = 0.25, sample 5,
    // 1 + 2/64; t = 5 the middle, sample 10, 1 + 2/8; t = 5.15 is x = 0.525, halfway between
    // samples 10 and 11: (1.25 + 1 + 2·0.55³)/2 (the spline itself gives 1.2894…, lpfg the line
    // between its samples); t = 8 the end and t = 10 past it: 3. Each doubled by SCALE.
    let by_hand = [1.0, 1.0, 1.03125, 1.25, 1.291375, 3.0, 3.0];
    let times = [0.0, 2.0, 3.5, 5.0, 5.15, 8.0, 10.0];
    for (t, v) in times.iter().zip(by_hand) {
        assert!((lpfg_growth(*t) - v).abs() < 1e-12, "t = {t}");
    }
    let mut expected: Vec<f64> = by_hand.iter().map(|v| 2.0 * v).collect();
    // B: by numbers (SCALE is 3, GROWTH 2), then WIDTH at 0.5 through func and tfunc: 8/8.
    expected.extend([2.0 * 1.291375, 1.0, 1.0]);
    let b = build(&result.text, &BuildOptions::default());
    assert!(b.ok(), "{:?}\n{}", b.diagnostics, result.text);
    let lengths = shared::lengths(&b);
    assert_eq!(lengths.len(), expected.len(), "{lengths:?}");
    for (k, (got, want)) in lengths.iter().zip(&expected).enumerate() {
        // The control points' ⅓ and ⅔ are written with 6 decimals: 1e-5 covers it.
        assert!((got - want).abs() < 1e-5, "segment {k}: {got} ≠ {want}");
    }
}

#[test]
fn a_timeline_reads_times_from_its_labels_values_only_while_they_hold_them() {
    let plain = TSET.replace("BEGIN", "").replace("FINISH", "");
    let result = import::import_object(&object(&plain, VSET));
    assert!(result.text.contains("-> F(SCALE * GROWTH(((t)-2)/6))\n"));
    let moved = VSET.replace("FINISH 8", "FINISH 9");
    let result = import::import_object(&object(TSET, &moved));
    assert!(result
        .text
        .contains("-> F(SCALE * GROWTH(((t)-BEGIN)/(8-BEGIN)))\n"));
}

#[test]
fn function_files_on_lpfgs_command_line_come_after_the_sets() {
    // WIDTH is 1, GROWTH 2, SCALE, BEGIN and FINISH 3 to 5: LAST.func is 6.
    let mut files = object(TSET, VSET);
    files[0] = file(
        "specifications",
        &SPECIFICATIONS.replace("vset functions.fset\n", "vset functions.fset LAST.func\n"),
    );
    files[1] = file(
        "plant.l",
        &PLANT.replace("func(WIDTH, 0.5)", "func(6, 0.5)"),
    );
    files.push(file(
        "LAST.func",
        &FSET.replace("WIDTH", "LAST")["funcgalleryver 1 1\nitems: 1\n".len()..],
    ));
    let result = import::import_object(&files);
    assert!(result.text.contains("F(8 * LAST(0.5))"), "{}", result.text);
    assert_eq!(result.notes.len(), 2, "{:?}", messages(&result));
}

#[test]
fn without_specifications_the_folders_own_sets_are_read() {
    let mut files = object(TSET, VSET);
    let with = import::import_object(&files);
    files.retain(|f| f.name != "specifications");
    assert_eq!(import::import_object(&files), with);
}

#[test]
fn malformed_timeline_and_value_files_are_notes_with_their_lines() {
    let tset = TSET.replace("end: 8", "end: eight");
    let result = import::import_object(&object(
        &tset,
        "#define SCALE 2\nSCALE = 3\n#define OTHER\n",
    ));
    let said = messages(&result);
    for piece in [
        "functions.tset, line 4: 'end: eight' is not a number: lpfg refuses the file (and runs no model); its timeline functions from the 1st on are not translated",
        "values.vset, line 2: 'SCALE = 3' is not '#define NAME value' with a number",
        "values.vset, line 3: '#define OTHER' is not",
        "lpfg's tfunc(GROWTH, …) chooses its function by an expression or a name the object's files do not give",
        // The timeline's one item keeps its number: SCALE is still 3.
        "lpfg's tfunc(2, …): the object's files list no function 2 that could be read",
    ] {
        assert!(said.iter().any(|m| m.contains(piece)), "{piece}\n{said:#?}");
    }
    // What could be read still is: WIDTH, SCALE (WIDTH is not written, as the production that
    // reads it is left out).
    assert!(result.text.contains("#define SCALE 2"));
    assert!(result
        .text
        .contains("// Not written: the object's functions WIDTH "));
    assert!(build(&result.text, &BuildOptions::default()).ok());
}

#[test]
fn missing_files_and_a_file_opened_alone_say_what_tfunc_and_val_need() {
    let mut files = object(TSET, VSET);
    files.retain(|f| f.name != "functions.tset");
    let result = import::import_object(&files);
    let said = messages(&result);
    assert!(
        said.iter().any(|m| m
            .contains("functions.tset (lpfg's timeline functions) was not opened with the object")),
        "{said:#?}"
    );
    let alone = import::import(PLANT, Dialect::Cpfg);
    let said = messages(&alone);
    let pieces = [
        "lpfg's val(SCALE) reads the value SCALE of the object's .vset file, which was not opened",
        "lpfg's val(3) reads the value 3",
    ];
    for piece in pieces {
        assert!(said.iter().any(|m| m.contains(piece)), "{piece}\n{said:#?}");
    }
    let timeless = PLANT.replace("val(SCALE) * ", "").replace("val(3) * ", "");
    let alone = import::import(&timeless, Dialect::Cpfg);
    let said = messages(&alone);
    for piece in [
        "lpfg's tfunc(GROWTH, …) reads the timeline function GROWTH of the object's .tset file, which was not opened",
        "lpfg's tfunc(2, …) reads the timeline function 2",
    ] {
        assert!(said.iter().any(|m| m.contains(piece)), "{piece}\n{said:#?}");
    }
    // val of a function and tfunc of a value are refused, as lpfg has nothing to give.
    let wrong = PLANT
        .replace("val(SCALE)", "val(GROWTH)")
        .replace("tfunc(1, 0.5)", "tfunc(SCALE, 0.5)");
    let mut files = object(TSET, VSET);
    files[1] = file("plant.l", &wrong);
    let said: Vec<String> = import::import_object(&files)
        .notes
        .into_iter()
        .map(|n| n.message)
        .collect();
    for piece in [
        "lpfg's val(GROWTH) reads a value of the object's .vset file, and GROWTH is a function",
        "lpfg's tfunc(SCALE, …) reads a function, and SCALE is a value",
    ] {
        assert!(said.iter().any(|m| m.contains(piece)), "{piece}\n{said:#?}");
    }
}

fn lychnis() -> Vec<ObjectFile> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/import-timeline/Lychnis");
    shared::object(&dir)
}

#[test]
fn lychnis_reads_its_timeline_and_values_and_translates_its_tfunc_and_val() {
    let result = import::import_object(&lychnis());
    let said = messages(&result);
    // (Its loops are noted, issue 49's: a loop's note quotes its tfunc.)
    for about in [
        ".tset",
        ".vset",
        ".fset",
        "lpfg's tfunc",
        "lpfg's val",
        "lpfg's func",
    ] {
        assert!(
            !said.iter().any(|m| m.contains(about)),
            "{about}: {said:#?}"
        );
    }
    let text = &result.text;
    for piece in [
        // The timeline functions the L-system reads, each sampled as lpfg samples it.
        "// LEAF_LENGTH: the timeline function of functions.tset, from t = 0.07 to t = 36.9635,",
        "lpfg reads it through 100 samples, as here\n#table LEAF_LENGTH 0 0 ",
        // Those it does not read are named, not written (issue 50, 6): INTERNODE_LENGTH and
        // CALYX_PROFILE are read by productions that are not translated (`nproduce`).
        "// Not written: the object's functions CALYX_PROFILE, POD_PROFILE, INTERNODE_LENGTH, AGING (the L-system does not read them).\n",
        // Its values, and the Start: block's variables that read them.
        "#define BR_END 15.4362 // val(BR_END) of aging.vset\n",
        "#define SIM_END 23.2721 // val(SIM_END) of aging.vset\n",
        "#define branching_ends BR_END\n",
        "#define simulation_ends SIM_END\n",
        "A(t) : t > 0 && T < branching_ends -> ",
        // leaf_length(t) is LEAFSCALE*tfunc(LEAF_LENGTH,t).
        "~l(LEAFSCALE*LEAF_LENGTH(((t)-0.07)/36.8935))",
    ] {
        assert!(text.contains(piece), "{piece}\n{text}");
    }
    // LEAF_LENGTH's last control point, 0.823510, is its value at the end of its time.
    let table = text
        .lines()
        .find(|l| l.starts_with("#table LEAF_LENGTH "))
        .expect("LEAF_LENGTH");
    let numbers: Vec<&str> = table.split_whitespace().skip(2).collect();
    assert_eq!(numbers.len(), 2 * 100);
    assert_eq!(&numbers[198..], ["1", "0.82351"]);
    let b = build(text, &BuildOptions::default());
    assert!(b.ok(), "{:?}", b.diagnostics);
}

/// Any bytes in the timeline or values file give a translation that resolves, or notes: never a
/// panic or a hang.
#[test]
fn any_bytes_in_a_timeline_or_values_file_give_a_translation_or_a_note() {
    use proptest::prelude::*;
    use proptest::test_runner::{Config, TestRunner};
    let base = lychnis();
    let which: Vec<usize> = base
        .iter()
        .enumerate()
        .filter(|(_, f)| f.name.ends_with("set"))
        .map(|(i, _)| i)
        .collect();
    assert_eq!(which.len(), 3);
    let mut runner = TestRunner::new(Config {
        cases: 64,
        ..Config::default()
    });
    let strategy = (
        0..which.len(),
        proptest::collection::vec(any::<u8>(), 0..200),
        any::<u16>(),
        any::<bool>(),
    );
    runner
        .run(&strategy, |(k, noise, at, replace)| {
            let mut files = base.clone();
            let f = &mut files[which[k]];
            let at = at as usize % (f.bytes.len() + 1);
            let end = if replace {
                (at + noise.len()).min(f.bytes.len())
            } else {
                at
            };
            f.bytes.splice(at..end, noise.iter().copied());
            let result = import::import_object(&files);
            prop_assert!(resolves(&result.text), "{}", result.text);
            Ok(())
        })
        .expect("no input breaks the importer");
}

/// True when `text` parses and resolves without an error.
fn resolves(text: &str) -> bool {
    let (file, mut d) = meristem::syntax::parse(text);
    d.extend(meristem::model::resolve(&file).1);
    !meristem::diagnostics::has_errors(&d)
}

/// The fuzz test's case (0, [13], 40040, false): a carriage return before a value's name
/// (`#define \rBR_END 15.4362`). The name went into the translation's comment
/// `// val(\rBR_END)`, where Meristem's parser ends a line at the `\r`: the line after it was in
/// error, and the repair commented out the line the importer counted there (`#define SIM_END`),
/// which left the derivation length and then the axiom unresolved.
#[test]
fn a_carriage_return_in_a_value_file_does_not_shift_the_lines_the_import_repairs() {
    let mut files = lychnis();
    let vset = files
        .iter_mut()
        .find(|f| f.name == "aging.vset")
        .expect("aging.vset");
    vset.bytes.insert("#define ".len(), b'\r');
    let result = import::import_object(&files);
    assert!(resolves(&result.text), "{}", result.text);
    assert!(result
        .text
        .contains("#define SIM_END 23.2721 // val(SIM_END) of aging.vset\n"));
    assert!(result.text.contains("\naxiom: "), "{}", result.text);
    // What could not be translated is said.
    assert!(messages(&result)
        .iter()
        .any(|m| m.contains("Meristem rejects the translation `BR_END) of aging.vset`")));
}
