//! `meristem`, the command-line tool: the same core as the studio, for scripts, tests and CI.
//!
//! ```text
//! meristem derive FILE [--iterations N] [--seed S] [--stats | --growth] [--time] [--edits EDITS.json]
//!                                                   the derived string, or stats as JSON;
//!                                                   --time: each stage's time on stderr
//! meristem derive FILE --growth                     what the growth attributes did, step by step (JSON)
//! meristem check FILE                               diagnostics as FILE:LINE:COL: severity: message
//! meristem lineage FILE MODULE [--iterations N | --at T] [--seed S]
//!                                                   module MODULE of the derived string, its
//!                                                   ancestor at each step back to the axiom and
//!                                                   the production that made each
//! meristem export FILE -o OUT.EXT [--format EXT] [--iterations N] [--seed S] [--sides N] [--smooth-all]
//!                 [--edits EDITS.json]              the model as OUT.wrl, .glb, .pov, .obj (+ .mtl), .iv or .svg
//!                 [--background C] [--line-width PX] [--size WxH] [--dpi D]
//!                                                   an SVG's picture settings (the studio's)
//!                 [--animate [--seconds-per-step S] [--targets-per-step K]]
//!                                                   glTF: the growth as an animation
//! meristem export FILE --frames N -o DIR | --at T -o OUT.svg
//!                                                   SVG (or, --format png / OUT.png, PNG)
//!                                                   pictures of the plant growing
//! meristem import FILE [--from D] [-o OUT.lsys]      another dialect translated; notes on stderr
//!                                                   (FILE may be a vlab object's folder or .zip)
//! meristem help [modules|directives]                the language's modules or directives, from
//!                                                   the vocabulary the core reads
//! ```
//!
//! `--edits` applies branch edits (the studio's edits document, docs/LANGUAGE.md) to the plant
//! before its stats or its export; an edit whose branch no longer exists is a warning.
//!
//! `derive`, `check`, `export` and `lineage` read an L-Py `.lpy`, a `.l` or a vlab object (folder
//! or `.zip`) as `import` gives it. An L-Py or lpfg model whose translation falls short is run by
//! the machine's Python (`python`; `MERISTEM_PYTHON`, `MERISTEM_PYTHON_TIMEOUT`).
//!
//! The files: `args` (the flags read, and where `export` writes), `input` (the grammar and edits
//! files read), `build` (`derive`, `check` and `export`), `import` and `help`, `python` (a model
//! run by Python); this one wires them.

mod args;
mod build;
mod frames;
mod help;
mod import;
mod input;
mod python;
mod raster;

use args::{check_flags, export_target, parse_args};
use build::{derive_or_check, export_file, print_lineage};
use frames::{at_as_picture, export_frames};
use help::help;
use import::{foreign_source, import_file, import_object, is_object};
use input::{read_edits, read_source};
use meristem::mesh::MeshOptions;
use meristem::pipeline::Hooks;
use meristem::BuildOptions;
use std::process::ExitCode;

pub const USAGE: &str = "usage:
  meristem derive FILE [--iterations N | --at T] [--seed S] [--stats | --growth] [--time] [--edits EDITS.json]
      --at T: the plant at growth time T in steps (0 or more, a fraction allowed): a timed grammar
      (#terminal_age) at time T·#dt, any other at its whole steps; --time prints the stages' timings
  meristem check FILE
  meristem lineage FILE MODULE [--iterations N | --at T] [--seed S]
      module MODULE (from 0) of the derived string, the module it came from at each step back to
      the axiom, and the production (LINE:COL and its text) that made each; the studio's debugger
  meristem export FILE -o OUT.EXT [--format EXT] [--iterations N | --at T] [--seed S] [--sides N] [--smooth-all]
                  [--edits EDITS.json] [--background C] [--line-width PX] [--size WxH] [--dpi D]
      EXT: wrl (VRML 2.0), glb (glTF 2.0), pov (POV-Ray 3.7), obj (OBJ, writes OUT.mtl too),
           iv (OpenInventor 2.1), svg (SVG); --format overrides the extension
      -o - --format EXT writes the file on stdout; a stream (-, /dev/stdout, a pipe) gets no
           .mtl or textures beside it (a note on stderr says so), and no 'wrote …' on stdout
      --sides N (3 to 64, default 6) and --smooth-all are the studio's view options
      --edits EDITS.json: branch edits made in the studio (its edits document), applied first
      SVG only, the studio's picture settings:
      --background white, none (the default: transparent) or a hex colour ('#' and six digits), --line-width PX (0.5 to 60:
      every line this wide in the picture's pixels, the Lines mode), --size WxH (16 to 8192
      pixels), --dpi D (10 to 2400: width and height in millimetres, e.g. 1748x2480 at 300 is A5)
      glTF only: --animate writes the plant's growth as an animation (morph targets keyed in time),
      --seconds-per-step S (0.001 to 3600, default 1), --targets-per-step K (1 to 16, default 4)
  meristem export FILE --frames N -o DIR   N SVG pictures of the plant growing, DIR/frame_000.svg …
                                           (--format png: PNGs of the same drawing, frame_000.png …)
  meristem export FILE --at T -o OUT.svg   the plant at growth time T (0 to the iterations; OUT.png:
                                           a PNG); a PNG is drawn in 2D as the SVG, at most 4096 px a side
  meristem import FILE [--from green|lparser|cpfg|lpy] [-o OUT.lsys]
      FILE may be a vlab object's folder or .zip: its .l with its view file, functions and colours
  meristem help [modules|directives]     the language's modules and directives
  meristem --version";

/// Writes on stdout as `print!` does, but a failure (the reader gone: `meristem derive … | head`;
/// a full disk) is a message and exit 2, as `export -o -` says it, not `print!`'s panic (exit 101).
pub fn print_out(text: std::fmt::Arguments) {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    if let Err(e) = out.write_fmt(text).and_then(|()| out.flush()) {
        eprintln!("meristem: cannot write to stdout: {e}");
        std::process::exit(2);
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
    if !["derive", "check", "export", "import", "lineage"].contains(&args.verb.as_str()) {
        eprintln!("meristem: unknown verb '{}'\n{USAGE}", args.verb);
        return ExitCode::from(2);
    }
    if let Err(e) = check_flags(&args) {
        eprintln!("meristem: {e}\n{USAGE}");
        return ExitCode::from(2);
    }
    let frames =
        args.verb == "export" && (args.growth_out.frames.is_some() || at_as_picture(&args));
    let export_target = if args.verb == "export" && !frames {
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
    // An .lpy, a .l or a vlab object: translated, or run by Python, first.
    let foreign = (args.verb != "import")
        .then(|| foreign_source(&args))
        .flatten();
    let source = match foreign.unwrap_or_else(|| read_source(&args)) {
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
        time: args.at,
        mesh: MeshOptions::view(args.sides, Some(args.smooth_all)),
        sketch: false,
    };
    if frames {
        return export_frames(&args, &source, options, &mut hooks);
    }
    if args.verb == "lineage" {
        return print_lineage(&args, &source, &options);
    }
    match export_target {
        Some(target) => export_file(&args, &source, options, edits, target, &mut hooks),
        None => derive_or_check(&args, &source, &options, edits, &mut hooks),
    }
}
