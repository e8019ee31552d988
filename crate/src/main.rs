//! `meristem`, the command-line tool: the same core as the studio, for scripts, tests and CI.
//!
//! ```text
//! meristem derive FILE [--iterations N] [--seed S] [--stats | --growth] [--time] [--edits EDITS.json]
//!                                                   the derived string, or stats as JSON;
//!                                                   --time: each stage's time on stderr
//! meristem derive FILE --growth                     what the growth attributes did, step by step (JSON)
//! meristem check FILE                               diagnostics as FILE:LINE:COL: severity: message
//! meristem export FILE -o OUT.EXT [--format EXT] [--iterations N] [--seed S] [--sides N] [--smooth-all]
//!                 [--edits EDITS.json]              the model as OUT.wrl, .glb, .pov, .obj (+ .mtl), .iv or .svg
//!                 [--background C] [--line-width PX] [--size WxH] [--dpi D]
//!                                                   an SVG's picture settings (the studio's)
//! meristem import FILE [--from D] [-o OUT.lsys]      another dialect translated; notes on stderr
//!                                                   (FILE may be a vlab object's folder or .zip)
//! meristem help [modules|directives]                the language's modules or directives, from
//!                                                   the vocabulary the core reads
//! ```
//!
//! `--edits` applies branch edits (the studio's edits document, docs/LANGUAGE.md) to the plant
//! before its stats or its export; an edit whose branch no longer exists is a warning.

use meristem::branches::{parse_edits, BranchEdit, EditReport};
use meristem::diagnostics::{locate_all, LocatedDiagnostic, Severity};
use meristem::export::{self, svg, Format};
use meristem::import::{self, Dialect};
use meristem::mesh::{MeshOptions, MAX_SIDES, MIN_SIDES};
use meristem::pipeline::{
    self, Build, ExportError, ExportOptions, Hooks, PlantEditor, StageTimings,
};
use meristem::vocabulary::{Param, ParamDefault, DIRECTIVES, MODULES};
use meristem::BuildOptions;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

const USAGE: &str = "usage:
  meristem derive FILE [--iterations N] [--seed S] [--stats | --growth] [--time] [--edits EDITS.json]
  meristem check FILE
  meristem export FILE -o OUT.EXT [--format EXT] [--iterations N] [--seed S] [--sides N] [--smooth-all]
                  [--edits EDITS.json] [--background C] [--line-width PX] [--size WxH] [--dpi D]
      EXT: wrl (VRML 2.0), glb (glTF 2.0), pov (POV-Ray 3.7), obj (OBJ, writes OUT.mtl too),
           iv (OpenInventor 2.1), svg (SVG); --format overrides the extension
      --sides N (3 to 64, default 6) and --smooth-all are the studio's view options
      --edits EDITS.json: branch edits made in the studio (its edits document), applied first
      SVG only, the studio's picture settings:
      --background white, none (the default: transparent) or a hex colour ('#' and six digits), --line-width PX (0.5 to 60:
      every line this wide in the picture's pixels, the Lines mode), --size WxH (16 to 8192
      pixels), --dpi D (10 to 2400: width and height in millimetres, e.g. 1748x2480 at 300 is A5)
  meristem import FILE [--from green|lparser|cpfg|lpy] [-o OUT.lsys]
      FILE may be a vlab object's folder or .zip: its .l with its view file, functions and colours
  meristem help [modules|directives]     the language's modules and directives
  meristem --version";

struct Args {
    verb: String,
    file: String,
    iterations: Option<u32>,
    seed: Option<u64>,
    stats: bool,
    time: bool,
    from: Option<String>,
    growth: bool,
    output: Option<PathBuf>,
    format: Option<String>,
    sides: Option<u32>,
    smooth_all: bool,
    edits: Option<PathBuf>,
    background: Option<String>,
    line_width: Option<f64>,
    size: Option<String>,
    dpi: Option<f64>,
}

/// The command line. Long because it is the list of flags, one arm and one variable each: split,
/// it would only scatter that list.
fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut parser = lexopt::Parser::from_env();
    let mut verb = None;
    let mut file = None;
    let mut iterations = None;
    let mut seed = None;
    let mut stats = false;
    let mut time = false;
    let mut from = None;
    let mut growth = false;
    let mut output = None;
    let mut format = None;
    let mut sides = None;
    let mut smooth_all = false;
    let mut edits = None;
    let mut background = None;
    let mut line_width = None;
    let mut size = None;
    let mut dpi = None;
    while let Some(arg) = parser.next()? {
        match arg {
            Long("iterations") | Short('n') => iterations = Some(parser.value()?.parse()?),
            Long("seed") | Short('s') => seed = Some(parser.value()?.parse()?),
            Long("stats") => stats = true,
            Long("time") => time = true,
            Long("from") => from = Some(parser.value()?.string()?),
            Long("growth") => growth = true,
            Long("output") | Short('o') => output = Some(PathBuf::from(parser.value()?)),
            Long("format") | Short('f') => format = Some(parser.value()?.string()?),
            Long("sides") => sides = Some(parser.value()?.string()?),
            Long("smooth-all") => smooth_all = true,
            Long("edits") => edits = Some(PathBuf::from(parser.value()?)),
            Long("background") => background = Some(parser.value()?.string()?),
            Long("line-width") => line_width = Some(parser.value()?.parse()?),
            Long("size") => size = Some(parser.value()?.string()?),
            Long("dpi") => dpi = Some(parser.value()?.parse()?),
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
    // Refused, not clamped: an export with other sides than asked for would be a silent surprise.
    let sides = match sides {
        None => None,
        Some(text) => match text.trim().parse::<u32>() {
            Ok(n) if (MIN_SIDES..=MAX_SIDES).contains(&n) => Some(n),
            _ => {
                return Err(format!(
                    "--sides {text} is out of range: a branch tube has {MIN_SIDES} to {MAX_SIDES} sides (a whole number)"
                )
                .into())
            }
        },
    };
    let verb = verb.ok_or("missing verb")?;
    let file = match (verb.as_str(), file) {
        ("help", topic) => topic.unwrap_or_default(),
        (_, Some(file)) => file,
        (_, None) => return Err("missing FILE".into()),
    };
    Ok(Args {
        verb,
        file,
        iterations,
        seed,
        stats,
        time,
        from,
        growth,
        output,
        format,
        sides,
        smooth_all,
        edits,
        background,
        line_width,
        size,
        dpi,
    })
}

/// An SVG's picture settings from `--background`, `--line-width`, `--size` and `--dpi`, checked;
/// refused for the other formats.
fn svg_look(args: &Args, format: Format) -> Result<svg::Look, String> {
    let given = args.background.is_some()
        || args.line_width.is_some()
        || args.size.is_some()
        || args.dpi.is_some();
    if given && format != Format::Svg {
        return Err(format!(
            "--background, --line-width, --size and --dpi are an SVG's picture settings, not {}'s",
            format.extension()
        ));
    }
    let size = match &args.size {
        Some(text) => {
            let parsed = text
                .split_once(['x', 'X', '×'])
                .and_then(|(w, h)| Some((w.trim().parse().ok()?, h.trim().parse().ok()?)));
            Some(
                parsed
                    .ok_or_else(|| format!("--size takes WIDTHxHEIGHT in pixels, not '{text}'"))?,
            )
        }
        None => None,
    };
    svg::Look::read(args.background.as_deref(), args.line_width, size, args.dpi)
}

/// Where `export` writes, in which format, and an SVG's look.
struct ExportTarget {
    output: PathBuf,
    format: Format,
    look: svg::Look,
}

/// Where `export` writes and in which format: `-o` is required; the format is `--format`, else
/// the output's extension.
fn export_target(args: &Args) -> Result<ExportTarget, String> {
    let output = args
        .output
        .clone()
        .ok_or("export needs an output file: -o OUT.EXT")?;
    let name = match &args.format {
        Some(name) => name.clone(),
        None => output
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or("")
            .to_string(),
    };
    let format = Format::from_extension(&name).ok_or_else(|| {
        let what = if args.format.is_some() {
            format!("unknown format '{name}'")
        } else if name.is_empty() {
            format!("{} has no extension to tell the format", output.display())
        } else {
            format!("unknown extension '.{name}'")
        };
        format!(
            "{what}; the formats are {} (PNG comes from the studio's renderer)",
            Format::names()
        )
    })?;
    let look = svg_look(args, format)?;
    Ok(ExportTarget {
        output,
        format,
        look,
    })
}

/// Writes the files of an export: the first at `output`, any others (OBJ's MTL) beside it with
/// their own extension, texture images (POV-Ray's) beside it with their own names.
fn write_export(output: &Path, files: &[export::ExportedFile]) -> Result<(), String> {
    for (k, file) in files.iter().enumerate() {
        let path = if k == 0 {
            output.to_path_buf()
        } else if file.mime == "image/png" {
            // A texture keeps its own name (`bark.png`): the scene refers to it by that name.
            output.with_file_name(&file.name)
        } else {
            let extension = file.name.rsplit('.').next().unwrap_or("");
            output.with_extension(extension)
        };
        std::fs::write(&path, &file.bytes)
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        println!("wrote {} ({} bytes)", path.display(), file.bytes.len());
    }
    Ok(())
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
    if args.verb == "help" {
        return help(&args.file);
    }
    if !["derive", "check", "export", "import"].contains(&args.verb.as_str()) {
        eprintln!("meristem: unknown verb '{}'\n{USAGE}", args.verb);
        return ExitCode::from(2);
    }
    let export_target = if args.verb == "export" {
        match export_target(&args) {
            Ok(target) => Some(target),
            Err(e) => {
                eprintln!("meristem: {e}\n{USAGE}");
                return ExitCode::from(2);
            }
        }
    } else {
        None
    };
    if args.verb == "import" && is_object(&args.file) {
        return import_object(&args);
    }
    let source = match read_source(&args) {
        Ok(source) => source,
        Err(code) => return code,
    };
    if args.verb == "import" {
        return import_file(&args, &source);
    }
    // The edits document is read (and checked) before building, so a bad one fails fast.
    let edits = match read_edits(&args) {
        Ok(edits) => edits,
        Err(code) => return code,
    };
    // The core reads no clock; this binary lends it one.
    let start = std::time::Instant::now();
    let mut clock = || start.elapsed().as_secs_f64() * 1000.0;
    let mut hooks = Hooks {
        clock: Some(&mut clock),
        progress: None,
    };
    let options = BuildOptions {
        iterations: args.iterations,
        seed: args.seed,
        mesh: MeshOptions::view(args.sides, Some(args.smooth_all)),
        sketch: false,
    };
    match export_target {
        Some(target) => export_file(&args, &source, options, edits, target, &mut hooks),
        None => derive_or_check(&args, &source, &options, edits, &mut hooks),
    }
}

/// The grammar file's text. Files of other tools often predate UTF-8 (Lparser's are DOS text): an
/// import reads them with each invalid byte replaced, and says so.
fn read_source(args: &Args) -> Result<String, ExitCode> {
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
fn read_edits(args: &Args) -> Result<Option<Vec<BranchEdit>>, ExitCode> {
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

/// `--time`: each stage's time on stderr.
fn print_timings(args: &Args, timings: Option<StageTimings>) {
    if let (true, Some(t)) = (args.time, timings) {
        eprintln!(
            "parse+resolve {:.3} ms, derive {:.3} ms, interpret {:.3} ms, mesh {:.3} ms",
            t.parse_resolve, t.derive, t.interpret, t.mesh
        );
    }
}

/// Warns about each edit whose branch no longer exists.
fn print_edit_report(args: &Args, report: &EditReport) {
    let Some(path) = &args.edits else {
        return;
    };
    for skipped in &report.not_applied {
        eprintln!(
            "{}: warning: the edit of branch {:?} does not apply: {}",
            path.display(),
            skipped.path,
            skipped.reason
        );
    }
}

/// `meristem derive` and `meristem check`.
fn derive_or_check(
    args: &Args,
    source: &str,
    options: &BuildOptions,
    edits: Option<Vec<BranchEdit>>,
    hooks: &mut Hooks,
) -> ExitCode {
    let mut build = pipeline::build_with(source, options, hooks);
    print_timings(args, build.timings);
    print_diagnostics(&args.file, &build.located_diagnostics(source));
    if !build.ok() {
        return ExitCode::from(1);
    }
    if let Some(edits) = edits {
        let mut editor = PlantEditor::new(std::mem::take(&mut build.plant));
        print_edit_report(args, &editor.apply_edits(&edits));
        build.plant = editor.into_plant();
    }
    if args.verb == "derive" {
        println!("{}", derived_output(args, &build));
    }
    ExitCode::SUCCESS
}

/// What `derive` prints: the growth report, the stats, or the derived string.
fn derived_output(args: &Args, build: &Build) -> String {
    if args.growth {
        // One report per step; `[]` when the grammar sets no growth attribute.
        build
            .growth
            .as_ref()
            .map_or("[]".into(), |g| g.steps_json())
    } else if args.stats {
        build.plant.stats.to_json()
    } else {
        build.derived_text()
    }
}

/// `meristem export`: the files of the format at `output` (and beside it).
fn export_file(
    args: &Args,
    source: &str,
    build: BuildOptions,
    edits: Option<Vec<BranchEdit>>,
    target: ExportTarget,
    hooks: &mut Hooks,
) -> ExitCode {
    let ExportTarget {
        output,
        format,
        look,
    } = target;
    // The stem names the MTL file inside the OBJ, so it is the output's own stem.
    let stem = output
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "plant".into());
    let options = ExportOptions {
        build,
        format,
        stem,
        edits,
        look,
    };
    let exported = match pipeline::export(source, &options, hooks) {
        Ok(exported) => exported,
        Err(ExportError::Grammar(build)) => {
            print_timings(args, build.timings);
            print_diagnostics(&args.file, &build.located_diagnostics(source));
            return ExitCode::from(1);
        }
    };
    print_timings(args, exported.timings);
    print_diagnostics(&args.file, &locate_all(source, &exported.diagnostics));
    if let Some(report) = &exported.edits {
        print_edit_report(args, report);
    }
    match write_export(&output, &exported.files) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("meristem: {e}");
            ExitCode::from(2)
        }
    }
}

/// `meristem help [modules|directives]`: the usage, or a table of the vocabulary.
fn help(topic: &str) -> ExitCode {
    match topic {
        "" => println!("{USAGE}"),
        "modules" => {
            for m in MODULES {
                println!("{:<10} {:<24} {}", m.name, params_text(m.params), m.doc);
            }
        }
        "directives" => {
            for d in DIRECTIVES {
                println!("#{:<20} {:<28} {}", d.name, d.forms_text(), d.doc);
            }
        }
        other => {
            eprintln!("meristem: no help on '{other}'; try 'meristem help modules' or 'meristem help directives'");
            return ExitCode::from(2);
        }
    }
    ExitCode::SUCCESS
}

/// `(l = #step)`, `(x, y, z)`, or nothing.
fn params_text(params: &[Param]) -> String {
    if params.is_empty() {
        return String::new();
    }
    let each: Vec<String> = params
        .iter()
        .map(|p| match p.default {
            Some(ParamDefault::Value(v)) => format!("{} = {v}", p.name),
            Some(ParamDefault::Directive(d)) => format!("{} = {}", p.name, d.written()),
            None => p.name.to_string(),
        })
        .collect();
    format!("({})", each.join(", "))
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
    write_import(args, &import::import(source, dialect))
}

/// True when `meristem import` is given a whole vlab object: a folder or a `.zip`.
fn is_object(file: &str) -> bool {
    let path = std::path::Path::new(file);
    path.is_dir() || file.to_ascii_lowercase().ends_with(".zip")
}

/// `meristem import FOLDER` or `OBJECT.zip`: the L-system with its view, functions and colours.
fn import_object(args: &Args) -> ExitCode {
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
fn write_import(args: &Args, result: &import::Import) -> ExitCode {
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
