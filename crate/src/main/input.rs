//! The files the command line names, read: the grammar and the edits document.

use super::args::Args;
use meristem::branches::{parse_edits, BranchEdit};
use std::process::ExitCode;

/// The grammar file's text. Files of other tools often predate UTF-8 (Lparser's are DOS text): an
/// import reads them with each invalid byte replaced, and says so.
pub fn read_source(args: &Args) -> Result<String, ExitCode> {
    let bytes = std::fs::read(&args.file).map_err(|e| {
        eprintln!("meristem: cannot read {}: {e}", args.file);
        ExitCode::from(2)
    })?;
    match String::from_utf8(bytes) {
        Ok(text) => Ok(text),
        Err(e) if args.verb == "import" => {
            eprintln!(
                "{}: note: not UTF-8 (invalid byte at offset {}); invalid bytes are read as U+FFFD",
                args.file,
                e.utf8_error().valid_up_to()
            );
            Ok(String::from_utf8_lossy(e.as_bytes()).into_owned())
        }
        Err(e) => {
            eprintln!(
                "{}: the file is not UTF-8 text (invalid byte at offset {})",
                args.file,
                e.utf8_error().valid_up_to()
            );
            Err(ExitCode::from(1))
        }
    }
}

/// The edits of `--edits`, checked.
pub fn read_edits(args: &Args) -> Result<Option<Vec<BranchEdit>>, ExitCode> {
    let Some(path) = &args.edits else {
        return Ok(None);
    };
    let text = std::fs::read_to_string(path).map_err(|e| {
        eprintln!("meristem: cannot read {}: {e}", path.display());
        ExitCode::from(2)
    })?;
    parse_edits(&text).map(Some).map_err(|e| {
        eprintln!("{}: {e}", path.display());
        ExitCode::from(2)
    })
}
