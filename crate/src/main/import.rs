//! `meristem import`: another dialect's grammar or a vlab object translated.

use super::args::Args;
use super::input::{check_not_input, read_bytes, read_past, MAX_FILE_BYTES};
use super::python;
use meristem::import::{self, Dialect, Import};
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
    let translation = import::import(source, dialect);
    // An .lpy or an L+C .l read with its own dialect may be run by Python instead.
    let result = match dialect {
        Dialect::Lpy | Dialect::Cpfg => {
            let file = import::ObjectFile {
                name: base_name(&args.file),
                bytes: source.as_bytes().to_vec(),
            };
            opened(args, &[file], translation)
        }
        _ => translation,
    };
    write_import(args, &result)
}

/// True when `meristem import` is given a whole vlab object: a folder or a `.zip`.
pub fn is_object(file: &str) -> bool {
    let path = std::path::Path::new(file);
    path.is_dir() || file.to_ascii_lowercase().ends_with(".zip")
}

/// `meristem import FOLDER` or `OBJECT.zip`: the L-system with its view, functions and colours
/// (an lpfg object run by Python when its translation falls short, [`opened`]).
pub fn import_object(args: &Args) -> ExitCode {
    match read_object(args) {
        Ok(files) => {
            let translation = import::import_files(&files).0;
            write_import(args, &opened(args, &files, translation))
        }
        Err(code) => code,
    }
}

/// The files of a vlab object: a folder's (and its folders', one level deep), or a `.zip`'s.
pub fn read_object(args: &Args) -> Result<Vec<import::ObjectFile>, ExitCode> {
    let path = std::path::Path::new(&args.file);
    if !path.is_dir() {
        let bytes = read_bytes(path).map_err(|e| {
            eprintln!("meristem: {e}");
            ExitCode::from(2)
        })?;
        return import::unzip(&bytes).map_err(|e| {
            eprintln!("meristem: {}: {e}", args.file);
            ExitCode::from(1)
        });
    }
    read_folder(path).map_err(|e| {
        eprintln!("meristem: {e}");
        ExitCode::from(2)
    })
}

/// The files of a vlab object's folder and of the folders in it, one level deep (an object's
/// files are at its top). Bounded as a `.zip` is ([`import::MAX_OBJECT_FILES`] files,
/// [`MAX_FILE_BYTES`] together), and only regular files are read (links followed): a named pipe
/// would wait for a writer forever, a link to `/dev/zero` never end; each one skipped is said.
fn read_folder(path: &std::path::Path) -> Result<Vec<import::ObjectFile>, String> {
    let mut files = Vec::new();
    let mut left = MAX_FILE_BYTES;
    let mut folders = vec![path.to_path_buf()];
    for depth in 0..2 {
        for folder in std::mem::take(&mut folders) {
            let Ok(entries) = std::fs::read_dir(&folder) else {
                continue;
            };
            for entry in entries.flatten() {
                let p = entry.path();
                let Ok(metadata) = std::fs::metadata(&p) else {
                    continue;
                };
                if metadata.is_dir() {
                    if depth == 0 {
                        folders.push(p);
                    }
                    continue;
                }
                if !metadata.is_file() {
                    eprintln!(
                        "meristem: note: {} is not a regular file: not read",
                        p.display()
                    );
                    continue;
                }
                let too_many = || {
                    format!(
                        "{} is not a vlab object: its files are more than {} or more than {} MiB \
                         together",
                        path.display(),
                        import::MAX_OBJECT_FILES,
                        MAX_FILE_BYTES >> 20
                    )
                };
                if files.len() == import::MAX_OBJECT_FILES || metadata.len() > left {
                    return Err(too_many());
                }
                // (A file of /proc says 0 bytes and may give more: read no further than the limit.)
                let read = std::fs::File::open(&p).and_then(|file| read_past(file, left));
                let Ok(bytes) = read else {
                    continue;
                };
                left = left.checked_sub(bytes.len() as u64).ok_or_else(too_many)?;
                let name = p.strip_prefix(path).unwrap_or(&p);
                let name = name.to_string_lossy().into_owned();
                files.push(import::ObjectFile { name, bytes });
            }
        }
    }
    Ok(files)
}

/// The import the user gets of `files` (a vlab object, or one file), given their hand
/// `translation`: the core's rule ([`import::needs_python`]) says whether Python runs the model
/// instead (lpfg's L+C and L-Py only, [`import::python_main`]); when Python cannot (missing, too
/// old, a timeout, the model's error), the translation with a note saying why.
pub fn opened(args: &Args, files: &[import::ObjectFile], translation: Import) -> Import {
    let Some(main) = import::python_main(files) else {
        return translation;
    };
    if !import::needs_python(&translation) {
        return translation;
    }
    let seed = args.seed.unwrap_or(0);
    let derived = match python::run(files, &main, args.iterations, seed) {
        Ok(json) => import::import_derived(&json, &main.main, files, seed),
        Err(why) => Import {
            text: String::new(),
            notes: vec![import::ImportNote {
                line: 0,
                message: why,
            }],
        },
    };
    import::prefer_derived(translation, derived)
}

/// `derive`, `check`, `export` and `lineage` of an L-Py `.lpy`, a cpfg or lpfg `.l` or a vlab
/// object (folder or `.zip`): the Meristem text [`opened`] gives, its notes on stderr; `None` for
/// any other file (Meristem's own text, read as it is).
pub fn foreign_source(args: &Args) -> Option<Result<String, ExitCode>> {
    let lower = args.file.to_ascii_lowercase();
    let files = if is_object(&args.file) {
        match read_object(args) {
            Ok(files) => files,
            Err(code) => return Some(Err(code)),
        }
    } else if lower.ends_with(".lpy") || lower.ends_with(".l") {
        match read_bytes(std::path::Path::new(&args.file)) {
            Ok(bytes) => vec![import::ObjectFile {
                name: base_name(&args.file),
                bytes,
            }],
            Err(e) => {
                eprintln!("meristem: {e}");
                return Some(Err(ExitCode::from(2)));
            }
        }
    } else {
        return None;
    };
    let translation = import::import_files(&files).0;
    let result = opened(args, &files, translation);
    print_notes(args, &result);
    if result.is_empty() {
        eprintln!("meristem: nothing could be imported from {}", args.file);
        return Some(Err(ExitCode::from(1)));
    }
    Some(Ok(result.text))
}

/// Writes an import's text (stdout or `-o`) and its notes (stderr).
pub fn write_import(args: &Args, result: &import::Import) -> ExitCode {
    print_notes(args, result);
    match &args.output {
        Some(path) => {
            if let Err(e) = check_not_input(args, path) {
                eprintln!("meristem: {e}");
                return ExitCode::from(2);
            }
            if let Err(e) = std::fs::write(path, &result.text) {
                eprintln!("meristem: cannot write {}: {e}", path.display());
                return ExitCode::from(2);
            }
        }
        None => super::print_out(format_args!("{}", result.text)),
    }
    if result.is_empty() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// An import's notes on stderr, `FILE:LINE: note: …` (`FILE: note: …` for the whole file).
fn print_notes(args: &Args, result: &Import) {
    for note in &result.notes {
        if note.line == 0 {
            eprintln!("{}: note: {}", args.file, note.message);
        } else {
            eprintln!("{}:{}: note: {}", args.file, note.line, note.message);
        }
    }
}

/// A path's file name (the name Python reports the model's lines under).
fn base_name(path: &str) -> String {
    std::path::Path::new(path)
        .file_name()
        .map_or_else(|| path.to_string(), |n| n.to_string_lossy().into_owned())
}
