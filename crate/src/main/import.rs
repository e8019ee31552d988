//! `meristem import`: another dialect's grammar or a vlab object translated.

use super::args::Args;
use meristem::import::{self, Dialect};
use std::process::ExitCode;

/// `meristem import`: the translation on stdout (or in `-o OUT`), one `FILE:LINE: note: …` line on
/// stderr per note. Exit 0, or 1 when nothing could be imported (no axiom), 2 on usage errors.
pub fn import_file(args: &Args, source: &str) -> ExitCode {
    let dialect = match &args.from {
        Some(name) => match Dialect::from_name(name) {
            Some(d) => d,
            None => {
                eprintln!("meristem: unknown dialect '{name}' (green, lparser, cpfg or lpy)");
                return ExitCode::from(2);
            }
        },
        None => match import::detect(source, &args.file) {
            Some(d) => d,
            None => {
                eprintln!(
                    "meristem: cannot tell which dialect {} is written in; say it with --from green|lparser|cpfg|lpy",
                    args.file
                );
                return ExitCode::from(2);
            }
        },
    };
    write_import(args, &import::import(source, dialect))
}

/// True when `meristem import` is given a whole vlab object: a folder or a `.zip`.
pub fn is_object(file: &str) -> bool {
    let path = std::path::Path::new(file);
    path.is_dir() || file.to_ascii_lowercase().ends_with(".zip")
}

/// `meristem import FOLDER` or `OBJECT.zip`: the L-system with its view, functions and colours.
pub fn import_object(args: &Args) -> ExitCode {
    let path = std::path::Path::new(&args.file);
    let files = if path.is_dir() {
        let mut files = Vec::new();
        let mut folders = vec![path.to_path_buf()];
        // The folder and the folders in it, one level deep (an object's files are at its top).
        for depth in 0..2 {
            for folder in std::mem::take(&mut folders) {
                let Ok(entries) = std::fs::read_dir(&folder) else {
                    continue;
                };
                for entry in entries.flatten() {
                    let p = entry.path();
                    if p.is_dir() {
                        if depth == 0 {
                            folders.push(p);
                        }
                    } else if let Ok(bytes) = std::fs::read(&p) {
                        let name = p
                            .strip_prefix(path)
                            .unwrap_or(&p)
                            .to_string_lossy()
                            .into_owned();
                        files.push(import::ObjectFile { name, bytes });
                    }
                }
            }
        }
        files
    } else {
        let bytes = match std::fs::read(path) {
            Ok(b) => b,
            Err(e) => {
                eprintln!("meristem: cannot read {}: {e}", args.file);
                return ExitCode::from(2);
            }
        };
        match import::unzip(&bytes) {
            Ok(files) => files,
            Err(e) => {
                eprintln!("meristem: {}: {e}", args.file);
                return ExitCode::from(1);
            }
        }
    };
    write_import(args, &import::import_files(&files).0)
}

/// Writes an import's text (stdout or `-o`) and its notes (stderr).
pub fn write_import(args: &Args, result: &import::Import) -> ExitCode {
    for note in &result.notes {
        if note.line == 0 {
            eprintln!("{}: note: {}", args.file, note.message);
        } else {
            eprintln!("{}:{}: note: {}", args.file, note.line, note.message);
        }
    }
    match &args.output {
        Some(path) => {
            if let Err(e) = std::fs::write(path, &result.text) {
                eprintln!("meristem: cannot write {}: {e}", path.display());
                return ExitCode::from(2);
            }
        }
        None => print!("{}", result.text),
    }
    if result.is_empty() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
