//! What several test files read: the gallery's examples (`public/examples/*.lsys`, all or one by
//! name), a derived string's modules with their parameters, a grammar
//! resolved without a diagnostic, a vlab object's folder as its files, and a plant's segments'
//! lengths. (Each test file compiles this module on its own and uses a
//! part of it: hence `allow(dead_code)`.)

use meristem::import::ObjectFile;
use meristem::model::{resolve, Model};
use meristem::pipeline::Build;
use meristem::syntax::parse;
use std::path::{Path, PathBuf};

/// `src` parsed and resolved, asserting that neither says anything.
#[allow(dead_code)]
pub fn model(src: &str) -> Model {
    let (file, diags) = parse(src);
    assert!(diags.is_empty(), "{diags:?}");
    let (model, diags) = resolve(&file);
    assert!(diags.is_empty(), "{diags:?}");
    model.expect("model")
}

/// Every gallery example, by path, with its text, in file name order.
#[allow(dead_code)]
pub fn examples() -> Vec<(PathBuf, String)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../public/examples");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("public/examples exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "lsys"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no examples in {}", dir.display());
    files
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("example is UTF-8");
            (p, text)
        })
        .collect()
}

/// A vlab object folder as the CLI and the studio hand it over: every file with its bytes, in
/// name order.
#[allow(dead_code)]
pub fn object(dir: &Path) -> Vec<ObjectFile> {
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

/// The length of each segment of a build's plant, in drawing order.
#[allow(dead_code)]
pub fn lengths(b: &Build) -> Vec<f64> {
    b.plant
        .skeleton
        .segments
        .iter()
        .map(|s| (s.end - s.start).length())
        .collect()
}

/// The text of the gallery example whose file name ends with `name`.
#[allow(dead_code)]
pub fn example(name: &str) -> String {
    examples()
        .into_iter()
        .find(|(p, _)| p.to_string_lossy().ends_with(name))
        .unwrap_or_else(|| panic!("no example {name}"))
        .1
}

/// A derived string's modules as (name, parameters): `I(1)[&(40)B]` is `I` (1), `[`, `&` (40),
/// `B`, `]`. Names are one character, or a letter with a subscript (`F_a`), as the gallery's
/// chapter 3 and 4 examples write them.
#[allow(dead_code)]
pub fn modules(derived: &str) -> Vec<(String, Vec<f64>)> {
    let chars: Vec<char> = derived.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let mut name = chars[i].to_string();
        i += 1;
        if chars.get(i) == Some(&'_') {
            name.push('_');
            name.push(chars[i + 1]);
            i += 2;
        }
        let mut params = Vec::new();
        if chars.get(i) == Some(&'(') {
            let close = i + chars[i..]
                .iter()
                .position(|&c| c == ')')
                .expect("closing )");
            let inside: String = chars[i + 1..close].iter().collect();
            params = inside
                .split(',')
                .map(|x| x.parse().expect("a number"))
                .collect();
            i = close + 1;
        }
        out.push((name, params));
    }
    out
}
