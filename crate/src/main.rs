//! `meristem`, the command-line tool: the same core as the studio, for scripts, tests and CI.
//!
//! ```text
//! meristem derive FILE [--iterations N] [--seed S] [--stats]   the derived string, or stats as JSON
//! meristem check FILE                               diagnostics as FILE:LINE:COL: severity: message
//! meristem import FILE [--from D] [-o OUT.lsys]      another dialect translated; notes on stderr
//! ```

use meristem::diagnostics::{LocatedDiagnostic, Severity};
use meristem::import::{self, Dialect};
use meristem::{build, BuildOptions};
use std::process::ExitCode;

const USAGE: &str = "usage:
  meristem derive FILE [--iterations N] [--seed S] [--stats]
  meristem check FILE
  meristem import FILE [--from green|lparser|cpfg|lpy] [-o OUT.lsys]
  meristem --version";

struct Args {
    verb: String,
    file: String,
    iterations: Option<u32>,
    seed: Option<u64>,
    stats: bool,
    from: Option<String>,
    output: Option<String>,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut parser = lexopt::Parser::from_env();
    let mut verb = None;
    let mut file = None;
    let mut iterations = None;
    let mut seed = None;
    let mut stats = false;
    let mut from = None;
    let mut output = None;
    while let Some(arg) = parser.next()? {
        match arg {
            Long("iterations") | Short('n') => iterations = Some(parser.value()?.parse()?),
            Long("seed") | Short('s') => seed = Some(parser.value()?.parse()?),
            Long("stats") => stats = true,
            Long("from") => from = Some(parser.value()?.string()?),
            Long("output") | Short('o') => output = Some(parser.value()?.string()?),
            Long("version") | Short('V') => {
                println!("meristem {}", env!("CARGO_PKG_VERSION"));
                std::process::exit(0);
            }
            Long("help") | Short('h') => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            Value(v) if verb.is_none() => verb = Some(v.string()?),
            Value(v) if file.is_none() => file = Some(v.string()?),
            _ => return Err(arg.unexpected()),
        }
    }
    let verb = verb.ok_or("missing verb")?;
    let file = file.ok_or("missing FILE")?;
    Ok(Args {
        verb,
        file,
        iterations,
        seed,
        stats,
        from,
        output,
    })
}

fn print_diagnostics(file: &str, diagnostics: &[LocatedDiagnostic]) {
    for d in diagnostics {
        let severity = match d.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        eprintln!(
            "{file}:{}:{}: {severity}: {} [{}]",
            d.line, d.column, d.message, d.code
        );
    }
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(args) => args,
        Err(e) => {
            eprintln!("meristem: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    let source = match std::fs::read(&args.file) {
        Ok(bytes) => match String::from_utf8(bytes) {
            Ok(text) => text,
            // Files of other tools often predate UTF-8 (Lparser's are DOS text): an import reads
            // them with each invalid byte replaced, and says so.
            Err(e) if args.verb == "import" => {
                eprintln!(
                    "{}: note: not UTF-8 (invalid byte at offset {}); invalid bytes are read as U+FFFD",
                    args.file,
                    e.utf8_error().valid_up_to()
                );
                String::from_utf8_lossy(e.as_bytes()).into_owned()
            }
            Err(e) => {
                eprintln!(
                    "{}: the file is not UTF-8 text (invalid byte at offset {})",
                    args.file,
                    e.utf8_error().valid_up_to()
                );
                return ExitCode::from(1);
            }
        },
        Err(e) => {
            eprintln!("meristem: cannot read {}: {e}", args.file);
            return ExitCode::from(2);
        }
    };
    if args.verb == "import" {
        return import_file(&args, &source);
    }
    let result = build(
        &source,
        &BuildOptions {
            iterations: args.iterations,
            seed: args.seed,
            ..BuildOptions::default()
        },
    );
    let diagnostics = result.located_diagnostics(&source);
    print_diagnostics(&args.file, &diagnostics);
    match args.verb.as_str() {
        "check" => {}
        "derive" if result.ok() => {
            if args.stats {
                println!("{}", result.stats.to_json());
            } else {
                println!("{}", result.derived_text());
            }
        }
        "derive" => {}
        other => {
            eprintln!("meristem: unknown verb '{other}'\n{USAGE}");
            return ExitCode::from(2);
        }
    }
    if result.ok() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

/// `meristem import`: the translation on stdout (or in `-o OUT`), one `FILE:LINE: note: …` line on
/// stderr per note. Exit 0, or 1 when nothing could be imported (no axiom), 2 on usage errors.
fn import_file(args: &Args, source: &str) -> ExitCode {
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
    let result = import::import(source, dialect);
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
                eprintln!("meristem: cannot write {path}: {e}");
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
