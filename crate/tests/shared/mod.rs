//! What several test files read: the gallery's examples (`public/examples/*.lsys`).

use std::path::PathBuf;

/// Every gallery example, by path, with its text, in file name order.
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
