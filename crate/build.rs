//! Lists the Python package `python/meristem_lsystem/` (its `.py` files) for the command line,
//! which embeds them with `include_str!` (`src/main/python.rs`): the binary runs L-Py and lpfg
//! models with the machine's `python3` without the package installed. The list is
//! `$OUT_DIR/python_package.rs`; without the package it is empty.

use std::path::{Path, PathBuf};

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap_or_default());
    let python = manifest.join("../python");
    let package = python.join("meristem_lsystem");
    println!("cargo:rerun-if-changed={}", python.display());
    println!("cargo:rerun-if-changed={}", package.display());
    let mut files = Vec::new();
    collect(&package, "meristem_lsystem", &mut files);
    files.sort();
    let mut code = String::from("/// The package's files: path inside `python/`, and text.\n");
    code.push_str("pub const PACKAGE: &[(&str, &str)] = &[\n");
    for (name, path) in &files {
        code.push_str(&format!("    ({name:?}, include_str!({path:?})),\n"));
    }
    code.push_str("];\n");
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    std::fs::write(out.join("python_package.rs"), code).expect("OUT_DIR is writable");
}

/// The `.py` files under `folder` (not `__pycache__`), each as its name under `prefix` and its
/// path on disk.
fn collect(folder: &Path, prefix: &str, files: &mut Vec<(String, String)>) {
    let Ok(entries) = std::fs::read_dir(folder) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        let name = entry.file_name().to_string_lossy().into_owned();
        if path.is_dir() {
            if name != "__pycache__" && !name.starts_with('.') {
                println!("cargo:rerun-if-changed={}", path.display());
                collect(&path, &format!("{prefix}/{name}"), files);
            }
        } else if name.ends_with(".py") {
            println!("cargo:rerun-if-changed={}", path.display());
            let absolute = path.canonicalize().unwrap_or(path);
            files.push((format!("{prefix}/{name}"), absolute.display().to_string()));
        }
    }
}
