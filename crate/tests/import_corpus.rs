//! The import corpus: whole vlab objects (cpfg's `.l` with its view file, function files and
//! colour map or materials) and L-Py models as their authors wrote them, beyond the files of
//! `tests/import/` (sources and licences in `tests/import-corpus/SOURCES.md`). Each must import,
//! resolve without errors, carry exactly its expected notes (so that no import claims a complete
//! translation when something was dropped or approximated) and build a plant of the recorded size.
//!
//! The sizes are those of a reference run of this translation (two checked against the source:
//! SOURCES.md says which); neither cpfg nor L-Py runs on this machine, so the others
//! guard the translation against regressions rather than prove it equal to the source tool's.
//! Native only: it reads the corpus from disk, and proptest is not a wasm32 dependency.
#![cfg(not(target_arch = "wasm32"))]

use meristem::import::{self, Dialect, Import, ObjectFile};
use meristem::pipeline::{build, BuildOptions};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/import-corpus")
}

/// Every entry: its path under the corpus, the modules and segments of its plant, and its notes
/// (line, a piece of the message), exactly.
type Entry = (&'static str, usize, usize, &'static [(usize, &'static str)]);

const CORPUS: &[Entry] = &[
    (
        "vlab/01-Lychnis",
        1370,
        1985,
        &[
            (
                0,
                "the view file's surface p is read from petal.s, which Meristem does not ",
            ),
            (
                0,
                "the view file's surface l is read from leaf.s, which Meristem does not r",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
            (76, "cpfg's @! is not a Meristem command; dropped"),
            (76, "cpfg's @# is not a Meristem command; dropped"),
            (
                81,
                "cpfg's @Gc marks a control point of a generalized cylinder; Meristem's s",
            ),
        ],
    ),
    ("vlab/01-hormone-up", 27, 11, &[]),
    ("vlab/01-pipe-model", 137, 30, &[]),
    ("vlab/01-planation", 198, 65, &[]),
    ("vlab/01-quadratic-Koch", 7608, 4096, &[]),
    ("vlab/02-decussate", 937, 341, &[]),
    ("vlab/02-hormone-down", 27, 11, &[]),
    ("vlab/02-snowflake-exercise", 82, 0, &[]),
    (
        "vlab/03-decussate-shaded",
        233,
        85,
        &[(
            0,
            "the materials of material.mat become their diffuse colours: their ambien",
        )],
    ),
    ("vlab/03-signal-down", 27, 11, &[]),
    ("vlab/04-compound", 452, 130, &[]),
    ("vlab/04-florigen", 19, 16, &[]),
    (
        "vlab/04-perspective",
        234,
        85,
        &[(
            0,
            "the materials of material.mat become their diffuse colours: their ambien",
        )],
    ),
    ("vlab/05-florigen-param", 19, 16, &[]),
    (
        "vlab/05-monopodial",
        354,
        117,
        &[(
            0,
            "the materials of material.mat become their diffuse colours: their ambien",
        )],
    ),
    (
        "vlab/06-comp-leaf-perspective",
        135,
        11,
        &[
            (
                0,
                "the view file's surface l is read from leaf.s, which Meristem does not r",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
            (
                22,
                "cpfg's @Tx is not a Meristem command; kept as a module the turtle ignore",
            ),
            (22, "cpfg's @ is not a Meristem command; dropped"),
        ],
    ),
    ("vlab/06-compound-param", 402, 161, &[]),
    ("vlab/06-florigen+auxin", 19, 16, &[]),
    ("vlab/07-acrotonic-2-signals", 150, 72, &[]),
    ("vlab/07-fractal-ferns", 6032, 1983, &[]),
    (
        "vlab/07-leaf-rnd",
        95,
        11,
        &[
            (
                0,
                "the view file's surface l is read from leaf.s, which Meristem does not r",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
        ],
    ),
    ("vlab/08-basipetal-2-signals", 130, 52, &[]),
    ("vlab/08-continuous-time", 852, 341, &[]),
    (
        "vlab/08-leaf-pos",
        140,
        16,
        &[
            (
                0,
                "the view file's surface l is read from leaf.s, which Meristem does not r",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
        ],
    ),
    ("vlab/09-continuous-decomp", 852, 341, &[]),
    (
        "vlab/09-monopodial-spiral",
        224,
        44,
        &[
            (
                0,
                "the view file's surface l is read from leaf.s, which Meristem does not r",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
        ],
    ),
    (
        "vlab/09-mycelis-schematic",
        148,
        23,
        &[
            (
                12,
                "cpfg's '#' without a value widens by the width increment; Meristem has n",
            ),
            (
                12,
                "cpfg's @oZG is not a Meristem command; kept as a module the turtle ignor",
            ),
            (
                15,
                "cpfg's @o is not a Meristem command; kept as a module the turtle ignores",
            ),
        ],
    ),
    (
        "vlab/10-sympodial",
        5114,
        1022,
        &[(
            0,
            "the materials of material.mat become their diffuse colours: their ambien",
        )],
    ),
    (
        "vlab/11-acropetal-1-signal",
        379,
        48,
        &[
            (
                30,
                "cpfg's '#' without a value widens by the width increment; Meristem has n",
            ),
            (
                40,
                "cpfg's @o is not a Meristem command; kept as a module the turtle ignores",
            ),
        ],
    ),
    ("vlab/11-alternating-exercise", 852, 341, &[]),
    (
        "vlab/11-sympodial-asym",
        4684,
        936,
        &[
            (
                0,
                "the view file's surface l is read from leaf.s, which Meristem does not r",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
        ],
    ),
    (
        "vlab/12-basipetal-1-signal",
        381,
        48,
        &[
            (
                30,
                "cpfg's '#' without a value widens by the width increment; Meristem has n",
            ),
            (
                40,
                "cpfg's @o is not a Meristem command; kept as a module the turtle ignores",
            ),
        ],
    ),
    ("vlab/DragonCurve", 1277, 256, &[]),
    (
        "vlab/HilbertPanels",
        214,
        129,
        &[
            (
                27,
                "Meristem rejects the translation `Sl : GRID -> ['(-1)'(-1)'(-1)!(GW)|f(a",
            ),
            (
                28,
                "Meristem rejects the translation `Sr : GRID -> ['(-1)'(-1)'(-1)!(GW)|f(a",
            ),
            (
                30,
                "Meristem rejects the translation `Tl : TILE -> ['(-1){f(c)+f(c)+f(c)+f(c",
            ),
            (
                31,
                "Meristem rejects the translation `Tr : TILE -> ['(-1)'(-1){f(c)-f(c)-f(c",
            ),
        ],
    ),
    ("vlab/RandomMoss", 2445, 699, &[]),
    (
        "vlab/Ring",
        32,
        32,
        &[(
            5,
            "'ring lsystem' is not part of the notation Meristem imports; skipped",
        )],
    ),
    (
        "vlab/Shedding",
        2244,
        1149,
        &[
            (
                29,
                "a production for cpfg's ',' becomes one for Meristem's ';', which also s",
            ),
            (
                33,
                "cpfg's @o is not a Meristem command; kept as a module the turtle ignores",
            ),
        ],
    ),
    ("lpy/01-equilat-triangle.lpy", 6, 3, &[]),
    ("lpy/03-koch-curve.lpy", 2390, 1024, &[]),
    ("lpy/04-sierpinski.lpy", 728, 0, &[]),
    (
        "lpy/05-simple-sympodial-plant.lpy",
        694,
        126,
        &[
            (15, "L-Py's @o is not a Meristem command"),
            (
                20,
                "the Python function '__initialiseContext__' is not translated",
            ),
        ],
    ),
    (
        "lpy/07-continuous-growth.lpy",
        8,
        7,
        &[(1, "Python imports are not translated")],
    ),
    (
        "lpy/09-flower-continous-growth.lpy",
        6042,
        453,
        &[
            (17, "the Python function 'Start' is not translated"),
            (21, "the Python function 'End' is not translated"),
            (25, "the Python function 'StartEach' is not translated"),
            (28, "the Python function 'EndEach' is not translated"),
            (
                71,
                "a production for L-Py's '_' becomes one for Meristem's '!', which also s",
            ),
        ],
    ),
    (
        "lpy/12-hidden-markov-1stem.lpy",
        598,
        149,
        &[
            (1, "Python imports are not translated"),
            (27, "the Python function 'Start' is not translated"),
            (
                50,
                "the Python code 'r = random()' is not translated (Meristem imports bodie",
            ),
            (
                56,
                "the Python code 'r = random()' is not translated (Meristem imports bodie",
            ),
            (
                85,
                "the Python function '__initialiseContext__' is not translated",
            ),
        ],
    ),
    ("lpy/13-branched-signal.lpy", 16, 7, &[]),
    (
        "lpy/17-open-lsystem-simple-growth.lpy",
        1368,
        576,
        &[(
            13,
            "the condition 4*y*y +(z-10)^2 > 100: Python's ^ is a bitwise or, not a p",
        )],
    ),
    ("lpy/Frame.lpy", 5, 1, &[]),
    ("lpy/branching.lpy", 6, 3, &[]),
    ("lpy/combined.lpy", 37, 7, &[]),
    (
        "lpy/ex_lsystem2.lpy",
        1368,
        576,
        &[(
            13,
            "the condition 4*y*y +(z-10)^2 > 100: Python's ^ is a bitwise or, not a p",
        )],
    ),
    ("lpy/ex_lsystem3.lpy", 134, 48, &[]),
    ("lpy/filledPolygons.lpy", 20, 1, &[]),
    ("lpy/generalizedCylinders.lpy", 12, 6, &[]),
    ("lpy/harderExample.lpy", 61, 10, &[]),
    ("lpy/movement.lpy", 6, 1, &[]),
    (
        "lpy/orientation.lpy",
        6,
        1,
        &[(
            2,
            "'Pinpoint' is not a module Meristem knows; kept as a module its turtle i",
        )],
    ),
    (
        "lpy/polygons.lpy",
        7,
        3,
        &[(
            2,
            "'Frame' is not a module Meristem knows; kept as a module its turtle igno",
        )],
    ),
    (
        "lpy/resolution.lpy",
        5,
        3,
        &[(
            2,
            "'SectionResolution' is not a module Meristem knows; kept as a module its",
        )],
    ),
    ("lpy/scale.lpy", 13, 7, &[]),
    ("lpy/visualize.lpy", 10, 7, &[]),
    ("lpy/width.lpy", 7, 4, &[]),
];

/// A vlab object folder as the CLI and the studio hand it over: every file with its bytes.
fn object(dir: &Path) -> Vec<ObjectFile> {
    let mut files: Vec<ObjectFile> = std::fs::read_dir(dir)
        .expect("object folder")
        .flatten()
        .map(|e| ObjectFile {
            name: e.file_name().to_string_lossy().into_owned(),
            bytes: std::fs::read(e.path()).expect("object file"),
        })
        .collect();
    files.sort_by(|a, b| a.name.cmp(&b.name));
    files
}

fn import_entry(path: &str) -> Import {
    let full = root().join(path);
    if full.is_dir() {
        import::import_object(&object(&full))
    } else {
        let text = std::fs::read_to_string(&full).expect("UTF-8 model");
        assert_eq!(import::detect(&text, path), Some(Dialect::Lpy), "{path}");
        import::import(&text, Dialect::Lpy)
    }
}

#[test]
fn the_corpus_holds_every_file_it_lists_and_no_other() {
    let mut listed: Vec<String> = Vec::new();
    for kind in ["vlab", "lpy"] {
        for e in std::fs::read_dir(root().join(kind))
            .expect("corpus")
            .flatten()
        {
            listed.push(format!("{kind}/{}", e.file_name().to_string_lossy()));
        }
    }
    listed.sort();
    let mut expected: Vec<String> = CORPUS.iter().map(|e| e.0.to_string()).collect();
    expected.sort();
    assert_eq!(listed, expected);
    assert!(CORPUS.len() >= 40);
}

#[test]
fn every_corpus_file_imports_with_exactly_its_notes_and_builds_its_plant() {
    let mut wrong = Vec::new();
    for &(path, modules, segments, notes) in CORPUS {
        let result = import_entry(path);
        let mut unmatched: Vec<&(usize, &str)> = notes.iter().collect();
        for note in &result.notes {
            match unmatched
                .iter()
                .position(|(line, piece)| *line == note.line && note.message.contains(piece))
            {
                Some(i) => {
                    unmatched.remove(i);
                }
                None => wrong.push(format!("{path}: unexpected note {note:?}")),
            }
        }
        if !unmatched.is_empty() {
            wrong.push(format!("{path}: missing notes {unmatched:?}"));
        }
        let b = build(&result.text, &BuildOptions::default());
        if !b.ok() {
            wrong.push(format!("{path}: {:?}", b.diagnostics));
            continue;
        }
        let size = (b.plant.stats.modules, b.plant.stats.segments);
        if size != (modules, segments) {
            wrong.push(format!(
                "{path}: {size:?} modules and segments, not {:?}",
                (modules, segments)
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn an_object_gives_its_view_and_functions_and_the_l_alone_says_what_it_lacks() {
    let dir = root().join("vlab/05-monopodial");
    let whole = import::import_object(&object(&dir));
    assert!(whole.text.contains("#angle 9\n"), "{}", whole.text);
    assert!(whole.text.contains("#table internode 0 0 "));
    assert!(whole.text.contains("internode("));
    let alone = std::fs::read_to_string(dir.join("leaf.l")).expect("leaf.l");
    let alone = import::import(&alone, Dialect::Cpfg);
    let said: Vec<&str> = alone.notes.iter().map(|n| n.message.as_str()).collect();
    assert!(
        said.iter()
            .any(|m| m.contains("func(1, …) reads function 1 of the object's view file")),
        "{said:?}"
    );
    assert!(
        said.iter()
            .any(|m| m.contains("colours are in the object's view file")),
        "{said:?}"
    );
}

#[test]
fn a_zipped_object_imports_as_its_folder_does() {
    let dir = root().join("vlab/09-monopodial-spiral");
    let files = object(&dir);
    let entries: Vec<(String, &[u8])> = files
        .iter()
        .map(|f| {
            (
                format!("09-monopodial-spiral/{}", f.name),
                f.bytes.as_slice(),
            )
        })
        .collect();
    let entries: Vec<(&str, &[u8])> = entries.iter().map(|(n, b)| (n.as_str(), *b)).collect();
    let zip = meristem::export::zip::stored(&entries).expect("zip");
    let (zipped, dialect) = import::import_files(&[ObjectFile {
        name: "spiral.zip".into(),
        bytes: zip,
    }]);
    assert_eq!(dialect, Some(Dialect::Cpfg));
    assert_eq!(zipped, import::import_object(&files));
    let (broken, dialect) = import::import_files(&[ObjectFile {
        name: "spiral.zip".into(),
        bytes: b"PK\x03\x04 not really".to_vec(),
    }]);
    assert_eq!(dialect, None);
    assert!(broken.text.is_empty());
    assert!(broken.notes[0]
        .message
        .starts_with("spiral.zip: not a zip archive"));
}

/// Any bytes in any file of an object (the archive, the view file, a function file, the colour
/// map, the L-system) give a translation that resolves, or notes: never a panic or a hang.
#[test]
fn any_bytes_in_an_object_give_a_translation_or_a_note() {
    use proptest::prelude::*;
    use proptest::test_runner::{Config, TestRunner};
    let base = object(&root().join("vlab/08-leaf-pos"));
    let mut runner = TestRunner::new(Config {
        cases: 64,
        ..Config::default()
    });
    let strategy = (
        0..base.len() + 1,
        proptest::collection::vec(any::<u8>(), 0..400),
        any::<u16>(),
    );
    runner
        .run(&strategy, |(which, noise, at)| {
            let mut files = base.clone();
            match files.get_mut(which) {
                // Overwrite part of one file with noise.
                Some(f) => {
                    let at = at as usize % (f.bytes.len() + 1);
                    let end = (at + noise.len()).min(f.bytes.len());
                    f.bytes.splice(at..end, noise.iter().copied());
                }
                None => files.push(ObjectFile {
                    name: "noise.zip".into(),
                    bytes: noise,
                }),
            }
            let (result, _) = import::import_files(&files);
            if !result.is_empty() {
                let (file, mut d) = meristem::syntax::parse(&result.text);
                d.extend(meristem::model::resolve(&file).1);
                prop_assert!(!meristem::diagnostics::has_errors(&d), "{}", result.text);
            }
            Ok(())
        })
        .expect("no input breaks the importer");
}
