//! The files the command line names, read: the grammar and the edits document.

use super::args::Args;
use super::build::is_stream;
use meristem::branches::{parse_edits, BranchEdit};
use meristem::import;
use std::io::Read;
use std::path::Path;
use std::process::ExitCode;

/// The most a file that is not a regular file (a pipe, `/dev/stdin`, a device such as
/// `/dev/zero`) is read for: the studio's largest grammar file (`MAX_FILE_BYTES` in
/// web/src/studio/files/grammar-files.ts). A regular file's size is known and read whole.
pub const MAX_STREAM_BYTES: u64 = 1_000_000;

/// The most a regular file is read for: what a vlab object's `.zip` may unpack to
/// ([`import::MAX_OBJECT_BYTES`], 64 MiB), far above any grammar (the studio opens 1 MB), so
/// that a file named by mistake (a disk image, `/proc/kcore`) is refused at once instead of
/// filling the memory.
pub const MAX_FILE_BYTES: u64 = import::MAX_OBJECT_BYTES as u64;

/// The bytes of the file at `path`; a file that is not a regular file is read up to
/// [`MAX_STREAM_BYTES`] and refused beyond, so `check /dev/zero` ends at once with a message;
/// a regular file up to [`MAX_FILE_BYTES`].
pub fn read_bytes(path: &Path) -> Result<Vec<u8>, String> {
    let cannot = |e: std::io::Error| format!("cannot read {}: {e}", path.display());
    let file = std::fs::File::open(path).map_err(cannot)?;
    let metadata = file.metadata().map_err(cannot)?;
    if metadata.is_file() {
        let too_large = || {
            format!(
                "{} is larger than {} MiB, the most Meristem reads of a file",
                path.display(),
                MAX_FILE_BYTES >> 20
            )
        };
        if metadata.len() > MAX_FILE_BYTES {
            return Err(too_large());
        }
        // (A file of /proc says 0 bytes and may give more: read no further than the limit.)
        let bytes = read_past(file, MAX_FILE_BYTES).map_err(cannot)?;
        if bytes.len() as u64 > MAX_FILE_BYTES {
            return Err(too_large());
        }
        return Ok(bytes);
    }
    let bytes = read_past(file, MAX_STREAM_BYTES).map_err(cannot)?;
    if bytes.len() as u64 > MAX_STREAM_BYTES {
        return Err(format!(
            "{} is not a regular file and gives more than {MAX_STREAM_BYTES} bytes, the largest \
             grammar the studio opens: write it to a file first",
            path.display()
        ));
    }
    Ok(bytes)
}

/// What `file` gives, read to its end or to one byte past `most`, whichever comes first: more
/// than `most` bytes means it is too large, and no more was read to know it.
pub fn read_past(file: std::fs::File, most: u64) -> std::io::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    file.take(most.saturating_add(1)).read_to_end(&mut bytes)?;
    Ok(bytes)
}

/// Refuses to write `output` when it is one of the files read (the grammar, the edits, a file of
/// the vlab object's folder): the command would lose its own input. A stream (`-`, `/dev/stdout`)
/// is no file read, and an output not there yet loses nothing.
pub fn check_not_input(args: &Args, output: &Path) -> Result<(), String> {
    let stream = is_stream(output);
    let Some(target) = std::fs::canonicalize(output).ok().filter(|_| !stream) else {
        return Ok(());
    };
    let inputs = [
        ("the grammar", Some(Path::new(&args.file))),
        ("the edits", args.edits.as_deref()),
    ];
    for (what, input) in inputs {
        let Some(read) = input.and_then(|i| std::fs::canonicalize(i).ok()) else {
            continue;
        };
        let (over, what) = if read.is_dir() {
            let inside = target.starts_with(&read) && target.is_file();
            (inside, "a file of the object")
        } else {
            (target == read, what)
        };
        if over {
            return Err(format!(
                "{} would be written over {what} this command reads ({}): give another output",
                output.display(),
                input.map_or(String::new(), |i| i.display().to_string())
            ));
        }
    }
    Ok(())
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
