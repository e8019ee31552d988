//! `meristem`, the command-line tool: the same core as the studio, for scripts, tests and CI.
//!
//! ```text
//! meristem derive FILE [--iterations N] [--seed S] [--stats]   the derived string, or stats as JSON
//! meristem derive FILE --growth                     what the growth attributes did, step by step (JSON)
//! meristem check FILE                               diagnostics as FILE:LINE:COL: severity: message
//! ```

use meristem::diagnostics::{LocatedDiagnostic, Severity};
use meristem::{build, BuildOptions};
use std::process::ExitCode;

const USAGE: &str = "usage:
  meristem derive FILE [--iterations N] [--seed S] [--stats | --growth]
  meristem check FILE
  meristem --version";

struct Args {
    verb: String,
    file: String,
    iterations: Option<u32>,
    seed: Option<u64>,
    stats: bool,
    growth: bool,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut parser = lexopt::Parser::from_env();
    let mut verb = None;
    let mut file = None;
    let mut iterations = None;
    let mut seed = None;
    let mut stats = false;
    let mut growth = false;
    while let Some(arg) = parser.next()? {
        match arg {
            Long("iterations") | Short('n') => iterations = Some(parser.value()?.parse()?),
            Long("seed") | Short('s') => seed = Some(parser.value()?.parse()?),
            Long("stats") => stats = true,
            Long("growth") => growth = true,
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
        growth,
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
            if args.growth {
                // One report per step; `[]` when the grammar sets no growth attribute.
                let steps = result
                    .growth
                    .as_ref()
                    .map_or("[]".into(), |g| g.steps_json());
                println!("{steps}");
            } else if args.stats {
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
