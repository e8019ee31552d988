//! `meristem derive`, `check` and `export`: a build, and what is printed or written of it.

use super::args::{Args, ExportTarget};
use super::input::check_not_input;
use meristem::branches::{BranchEdit, EditReport};
use meristem::diagnostics::{locate_all, LocatedDiagnostic, Severity};
use meristem::export;
use meristem::export::animation::Animation;
use meristem::pipeline::{
    self, Build, ExportError, ExportOptions, Hooks, PlantEditor, StageTimings,
};
use meristem::BuildOptions;
use std::path::Path;
use std::process::ExitCode;

/// Writes the files of an export: the first at `output`, any others beside it with their own
/// names (OBJ's MTL, as its `mtllib` names it; POV-Ray's texture images, as the scene names them),
/// each said on stdout. When `output` is a stream (`-` for stdout, a device such as
/// `/dev/stdout`, a pipe) the first file goes there and nothing is said on stdout (it may be the
/// file itself); the others are not written (there is no "beside" a stream): a note on stderr
/// says which, and the OBJ's `mtllib` then names a library that is not there.
pub fn write_export(output: &Path, files: &[export::ExportedFile]) -> Result<(), String> {
    let stream = is_stream(output);
    for (k, file) in files.iter().enumerate() {
        if k > 0 && stream {
            eprintln!(
                "meristem: note: {} is not a regular file: {} is not written beside it",
                output.display(),
                file.name
            );
            continue;
        }
        let path = if k == 0 {
            output.to_path_buf()
        } else {
            // A texture keeps its own name (`bark.png`), the MTL the one the OBJ's `mtllib`
            // gives (the output's stem made safe: `my plant.obj` names `my-plant.mtl`).
            output.with_file_name(&file.name)
        };
        if path.as_os_str() == "-" {
            std::io::Write::write_all(&mut std::io::stdout().lock(), &file.bytes)
                .map_err(|e| format!("cannot write to stdout: {e}"))?;
            continue;
        }
        std::fs::write(&path, &file.bytes)
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        if !stream {
            let size = file.bytes.len();
            super::print_out(format_args!("wrote {} ({size} bytes)\n", path.display()));
        }
    }
    Ok(())
}

/// True when `output` is no place beside which other files can go: `-` (stdout), a path under
/// `/dev/` or `/proc/` (`/dev/stdout`, `/dev/fd/3`, which may even point to a regular file when
/// stdout is redirected), or an existing file that is not a regular file (a named pipe).
pub fn is_stream(output: &Path) -> bool {
    output.as_os_str() == "-"
        || output.starts_with("/dev")
        || output.starts_with("/proc")
        || std::fs::metadata(output).is_ok_and(|m| !m.is_file() && !m.is_dir())
}

pub fn print_diagnostics(file: &str, diagnostics: &[LocatedDiagnostic]) {
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

/// `--time`: each stage's time on stderr.
pub fn print_timings(args: &Args, timings: Option<StageTimings>) {
    if let (true, Some(t)) = (args.time, timings) {
        eprintln!(
            "parse+resolve {:.3} ms, derive {:.3} ms, interpret {:.3} ms, mesh {:.3} ms",
            t.parse_resolve, t.derive, t.interpret, t.mesh
        );
    }
}

/// Warns about each edit whose branch no longer exists.
pub fn print_edit_report(args: &Args, report: &EditReport) {
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
pub fn derive_or_check(
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
        super::print_out(format_args!("{}\n", derived_output(args, &build)));
    }
    ExitCode::SUCCESS
}

/// What `derive` prints: the growth report, the stats, or the derived string.
pub fn derived_output(args: &Args, build: &Build) -> String {
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
pub fn export_file(
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
    // The stem names the MTL file inside the OBJ, so it is the output's own stem (`plant` for a
    // stream such as `-` or `/dev/stdout`, whose name is no file's).
    let stem = output
        .file_stem()
        .filter(|_| !is_stream(&output))
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "plant".into());
    let options = ExportOptions {
        build,
        format,
        stem,
        edits,
        look,
        animation: args.growth_out.animate.then(|| {
            let defaults = Animation::default();
            Animation {
                seconds_per_step: args
                    .growth_out
                    .seconds_per_step
                    .unwrap_or(defaults.seconds_per_step),
                targets_per_step: args
                    .growth_out
                    .targets_per_step
                    .unwrap_or(defaults.targets_per_step),
            }
        }),
    };
    let exported = match pipeline::export(source, &options, hooks) {
        Ok(exported) => exported,
        Err(ExportError::Grammar(build)) => {
            print_timings(args, build.timings);
            print_diagnostics(&args.file, &build.located_diagnostics(source));
            return ExitCode::from(1);
        }
        Err(ExportError::Refused(message)) => {
            eprintln!("meristem: {message}");
            return ExitCode::from(2);
        }
    };
    print_timings(args, exported.timings);
    print_diagnostics(&args.file, &locate_all(source, &exported.diagnostics));
    if let Some(report) = &exported.edits {
        print_edit_report(args, report);
    }
    // Nothing is written when any file would go over one the command reads.
    let beside = exported.files.iter().skip(1);
    let paths =
        std::iter::once(output.clone()).chain(beside.map(|f| output.with_file_name(&f.name)));
    for (k, path) in paths.enumerate() {
        // (`-o plant.mtl --format obj` wrote the OBJ, then its MTL over it.)
        let over_first = k > 0 && !is_stream(&output) && path == output;
        let checked = if over_first {
            Err(format!(
                "{} would be written over {}, the {} file itself: give the output its own extension",
                exported.files[k].name,
                output.display(),
                format.extension()
            ))
        } else {
            check_not_input(args, &path)
        };
        if let Err(e) = checked {
            eprintln!("meristem: {e}");
            return ExitCode::from(2);
        }
    }
    match write_export(&output, &exported.files) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("meristem: {e}");
            ExitCode::from(2)
        }
    }
}

/// `meristem lineage FILE MODULE`: the module's ancestors step by step, the last step first
/// (`pipeline::lineage_text`), as the studio's debugger lists them.
pub fn print_lineage(args: &Args, source: &str, options: &BuildOptions) -> ExitCode {
    let module = match args.module.as_deref().map(|m| m.trim().parse::<usize>()) {
        Some(Ok(module)) => module,
        Some(Err(_)) | None => {
            eprintln!(
                "meristem: lineage needs a module index from 0: meristem lineage FILE MODULE\n{}",
                super::USAGE
            );
            return ExitCode::from(2);
        }
    };
    let build = pipeline::build(
        source,
        &BuildOptions {
            sketch: true,
            ..options.clone()
        },
    );
    print_diagnostics(&args.file, &build.located_diagnostics(source));
    let (true, Some(model)) = (build.ok(), build.model.as_ref()) else {
        return ExitCode::from(1);
    };
    match pipeline::lineage(model, &build.derived_with, module) {
        Ok(rows) => {
            let text = pipeline::lineage_text(source, model, &rows);
            super::print_out(format_args!("{text}"));
            ExitCode::SUCCESS
        }
        Err(e) => {
            print_diagnostics(&args.file, &locate_all(source, &[e]));
            ExitCode::from(1)
        }
    }
}
