//! The files the command line names, read: the grammar and the edits document.

use super::args::Args;
use meristem::branches::{parse_edits, BranchEdit};
use std::io::Read;
use std::path::Path;
use std::process::ExitCode;

/// The most a file that is not a regular file (a pipe, `/dev/stdin`, a device such as
/// `/dev/zero`) is read for: the studio's largest grammar file (`MAX_FILE_BYTES` in
/// web/src/studio/files/grammar-files.ts). A regular file's size is known and read whole.
pub const MAX_STREAM_BYTES: u64 = 1_000_000;

/// The bytes of the file at `path`; a file that is not a regular file is read up to
/// [`MAX_STREAM_BYTES`] and refused beyond, so `check /dev/zero` ends at once with a message.
pub fn read_bytes(path: &Path) -> Result<Vec<u8>, String> {
    let cannot = |e: std::io::Error| format!("cannot read {}: {e}", path.display());
    let file = std::fs::File::open(path).map_err(cannot)?;
    let regular = file.metadata().map_err(cannot)?.is_file();
    let mut bytes = Vec::new();
    if regular {
        (&file).read_to_end(&mut bytes).map_err(cannot)?;
        return Ok(bytes);
    }
    file.take(MAX_STREAM_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > MAX_STREAM_BYTES {
        return Err(format!(
            "{} is not a regular file and gives more than {MAX_STREAM_BYTES} bytes, the largest \
             grammar the studio opens: write it to a file first",
            path.display()
        ));
    }
    Ok(bytes)
}

/// The grammar file's text. Files of other tools often predate UTF-8 (Lparser's are DOS text): an
/// import reads them with each invalid byte replaced, and says so.
pub fn read_source(args: &Args) -> Result<String, ExitCode> {
    let bytes = read_bytes(Path::new(&args.file)).map_err(|e| {
        eprintln!("meristem: {e}");
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
    let bytes = read_bytes(path).map_err(|e| {
        eprintln!("meristem: {e}");
        ExitCode::from(2)
    })?;
    let text = String::from_utf8(bytes).map_err(|_| {
        eprintln!("meristem: {}: the edits are not UTF-8 text", path.display());
        ExitCode::from(2)
    })?;
    parse_edits(&text).map(Some).map_err(|e| {
        eprintln!("{}: {e}", path.display());
        ExitCode::from(2)
    })
}
