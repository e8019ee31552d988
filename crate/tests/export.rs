//! Export goldens: every `tests/golden/export/NAME.lsys` is exported in every format and compared
//! byte for byte with `NAME.wrl`, `NAME.glb`, `NAME.pov`, `NAME.obj` + `NAME.mtl`, `NAME.iv` and
//! `NAME.svg` (the files are named `NAME`, so the OBJ names `NAME.mtl`). A grammar named
//! `*-lines.lsys` is built with a vertex limit of 0, so the writers take their fallback for models
//! too large to mesh. Rewrite with `UPDATE_GOLDEN=1 cargo test --test export` after an intended
//! change and read the diff; the Node consumer tests (`tests/export/`) feed these files to the
//! real tools too.

use meristem::export::{self, Format};
use meristem::mesh::MeshOptions;
use meristem::pipeline::{build, BuildOptions};
use std::path::{Path, PathBuf};

fn golden_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden/export")
}

/// The grammars, sorted by name.
fn grammars() -> Vec<PathBuf> {
    let mut files: Vec<_> = std::fs::read_dir(golden_dir())
        .expect("tests/golden/export exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "lsys"))
        .collect();
    files.sort();
    files
}

/// Every file every format writes for one grammar.
fn exports(path: &Path) -> Vec<export::ExportedFile> {
    let source = std::fs::read_to_string(path).expect("grammar is UTF-8");
    let stem = path
        .file_stem()
        .and_then(|s| s.to_str())
        .expect("a UTF-8 name");
    let mut options = BuildOptions::default();
    if stem.ends_with("-lines") {
        options.mesh = MeshOptions {
            max_vertices: 0,
            ..MeshOptions::default()
        };
    }
    let result = build(&source, &options);
    assert!(result.ok(), "{}: {:?}", path.display(), result.diagnostics);
    Format::ALL
        .into_iter()
        .flat_map(|format| export::export(format, &result.plant.mesh, &result.plant.skeleton, stem))
        .collect()
}

#[test]
fn exports_match_their_golden_files() {
    let update = std::env::var_os("UPDATE_GOLDEN").is_some();
    let grammars = grammars();
    assert!(
        grammars.len() >= 3,
        "two small grammars and the lines fallback at least"
    );
    let mut failures = Vec::new();
    for grammar in &grammars {
        for file in exports(grammar) {
            let golden = golden_dir().join(&file.name);
            if update {
                std::fs::write(&golden, &file.bytes).expect("write golden");
                continue;
            }
            let expected = std::fs::read(&golden).unwrap_or_default();
            if expected != file.bytes {
                let at = expected
                    .iter()
                    .zip(&file.bytes)
                    .position(|(a, b)| a != b)
                    .unwrap_or(expected.len().min(file.bytes.len()));
                let line = file.bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
                failures.push(format!(
                    "{}: differs from its golden at byte {at} (line {line}); UPDATE_GOLDEN=1 to rewrite",
                    file.name
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_lines_grammar_really_takes_the_fallback() {
    let grammar = golden_dir().join("tiny-lines.lsys");
    let files = exports(&grammar);
    let wrl = files
        .iter()
        .find(|f| f.name == "tiny-lines.wrl")
        .expect("wrl");
    let text = String::from_utf8_lossy(&wrl.bytes);
    assert!(text.contains("IndexedLineSet") && !text.contains("IndexedFaceSet"));
}

#[test]
fn exports_are_the_same_bytes_every_time() {
    for grammar in grammars() {
        assert_eq!(
            exports(&grammar),
            exports(&grammar),
            "{}",
            grammar.display()
        );
    }
}
