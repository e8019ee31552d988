//! `meristem export FILE --frames N -o DIR` and `--at T -o OUT.svg`: the plant growing, as SVG
//! pictures at growth times from 0 to N (docs/LANGUAGE.md, "Growth in time"), each framed on the
//! whole plant so that the frames line up; or as PNG pictures of the same drawing (`--format png`,
//! `-o OUT.png`), filled on the CPU by `raster.rs`.

use super::args::{svg_look, Args};
use super::build::{is_stream, print_diagnostics, print_timings};
use super::input::check_not_input;
use super::raster;
use meristem::export::{svg, Format};
use meristem::mesh::{growth_schedule, skeleton_at};
use meristem::pipeline::{self, Hooks};
use meristem::BuildOptions;
use std::path::PathBuf;
use std::process::ExitCode;

/// True when `--at T` asks `export` for a picture of the growth at T (an SVG output) rather than
/// the plant at T in a file of another format (a timed grammar at T, any other at its whole steps).
pub fn at_as_picture(args: &Args) -> bool {
    let picture = |name: &str| picture_kind(name).is_some();
    let extension = args
        .output
        .as_ref()
        .and_then(|o| o.extension())
        .and_then(|e| e.to_str());
    args.at.is_some() && args.format.as_deref().or(extension).is_some_and(picture)
}

/// A picture of the growth: an SVG drawing or a PNG of it.
#[derive(Clone, Copy, PartialEq)]
enum Picture {
    Svg,
    Png,
}

/// The picture a format's name or extension asks for, if it is one.
fn picture_kind(name: &str) -> Option<Picture> {
    if Format::from_extension(name) == Some(Format::Svg) {
        Some(Picture::Svg)
    } else if name.eq_ignore_ascii_case("png") {
        Some(Picture::Png)
    } else {
        None
    }
}

/// Most frames one export writes.
pub const MAX_FRAMES: u32 = 10_000;

/// The pictures to write: each file (`extension`: a frame's) and its growth time, for `steps`
/// steps; or why not.
fn frames_of(
    args: &Args,
    output: PathBuf,
    steps: u32,
    extension: &str,
) -> Result<Vec<(PathBuf, f32)>, String> {
    let n = steps as f32;
    match (args.growth_out.frames, args.at) {
        (Some(_), Some(_)) => Err("--frames and --at: give one of them".into()),
        (Some(count), None) => {
            if !(1..=MAX_FRAMES).contains(&count) {
                return Err(format!("--frames {count}: give 1 to {MAX_FRAMES} frames"));
            }
            let digits = (count - 1).max(1).ilog10() as usize + 1;
            let width = digits.max(3);
            Ok((0..count)
                .map(|k| {
                    let t = if count == 1 {
                        n
                    } else {
                        n * k as f32 / (count - 1) as f32
                    };
                    (output.join(format!("frame_{k:0width$}.{extension}")), t)
                })
                .collect())
        }
        (None, Some(t)) if t.is_finite() => Ok(vec![(output, (t as f32).clamp(-1.0, n))]),
        (None, Some(t)) => Err(format!("--at {t}: give a growth time, a number of steps")),
        (None, None) => Ok(Vec::new()),
    }
}

/// The kind and picture settings of frames: SVG (by default) or PNG.
fn frame_look(args: &Args) -> Result<(Picture, svg::Look), String> {
    let extension = args
        .output
        .as_ref()
        .filter(|_| args.growth_out.frames.is_none())
        .and_then(|o| o.extension())
        .and_then(|e| e.to_str());
    let kind = match args.format.as_deref().or(extension) {
        Some(name) => picture_kind(name).ok_or_else(|| {
            format!(
                "frames of the growth are SVG or PNG pictures, not '{name}' (the glTF animation \
                 is --animate)"
            )
        })?,
        None => Picture::Svg,
    };
    Ok((kind, svg_look(args, Format::Svg)?))
}

/// The file of one picture: the SVG's text, or a PNG of the same drawing (at most
/// [`raster::MAX_SIDE`] pixels on a side).
fn picture_file(
    kind: Picture,
    plant: &meristem::pipeline::Plant,
    at: &meristem::turtle::Skeleton,
    look: &svg::Look,
) -> Result<Vec<u8>, String> {
    if kind == Picture::Svg {
        return Ok(svg::write_framed(&plant.mesh, at, Some(&plant.skeleton), look).into_bytes());
    }
    let flat = svg::flat_framed(&plant.mesh, at, Some(&plant.skeleton), look);
    if flat.width.max(flat.height) > raster::MAX_SIDE {
        return Err(format!(
            "a PNG frame of {} × {} pixels: the most is {} on a side (--size)",
            flat.width,
            flat.height,
            raster::MAX_SIDE
        ));
    }
    Ok(raster::png(&flat))
}

/// Writes the frames; the exit code.
pub fn export_frames(
    args: &Args,
    source: &str,
    mut options: BuildOptions,
    hooks: &mut Hooks,
) -> ExitCode {
    let fail = |message: String| {
        eprintln!("meristem: {message}");
        ExitCode::from(2)
    };
    let Some(output) = args.output.clone() else {
        return fail("frames need an output: -o DIR with --frames, -o OUT.svg with --at".into());
    };
    // (`-` is stdout elsewhere: here it made a folder named `-`.)
    if args.growth_out.frames.is_some() && is_stream(&output) {
        return fail(format!(
            "--frames writes its pictures into a folder, not to {}: give -o DIR",
            output.display()
        ));
    }
    let (kind, look) = match frame_look(args) {
        Ok(picture) => picture,
        Err(e) => return fail(e),
    };
    // The pictures draw the skeleton: the mesh needs no triangles, only its growth. The whole
    // plant is that of its steps; a timed or stepwise grammar is derived again at each frame's time.
    options.mesh.growth = true;
    options.mesh.max_vertices = 0;
    options.time = None;
    let build = pipeline::build_with(source, &options, hooks);
    print_timings(args, build.timings);
    print_diagnostics(&args.file, &build.located_diagnostics(source));
    if !build.ok() {
        return ExitCode::from(1);
    }
    let extension = if kind == Picture::Png { "png" } else { "svg" };
    let frames = match frames_of(args, output.clone(), build.derived_with.steps, extension) {
        Ok(frames) => frames,
        Err(e) => return fail(e),
    };
    if let Some(e) = frames
        .iter()
        .find_map(|(path, _)| check_not_input(args, path).err())
    {
        return fail(e);
    }
    if args.growth_out.frames.is_some() {
        if let Err(e) = std::fs::create_dir_all(&output) {
            return fail(format!("cannot create {}: {e}", output.display()));
        }
    }
    let (plant, schedule) = (&build.plant, growth_schedule(&build.plant.skeleton));
    // A timed grammar is derived at each frame's time, a stepwise one at its whole steps.
    let derived = build
        .model
        .as_ref()
        .is_some_and(|m| m.settings.timed() || m.settings.stepwise());
    for (path, t) in frames {
        let at = if derived {
            let time = Some(f64::from(t.max(0.0)));
            let options = BuildOptions {
                time,
                ..options.clone()
            };
            pipeline::build(source, &options).plant.skeleton
        } else {
            skeleton_at(&plant.skeleton, &schedule, t)
        };
        let bytes = match picture_file(kind, plant, &at, &look) {
            Ok(bytes) => bytes,
            Err(e) => return fail(e),
        };
        // `--at T -o - --format svg`: the one picture on stdout, as `export -o -` writes.
        let written = if path.as_os_str() == "-" {
            std::io::Write::write_all(&mut std::io::stdout().lock(), &bytes)
        } else {
            std::fs::write(&path, bytes)
        };
        if let Err(e) = written {
            return fail(format!("cannot write {}: {e}", path.display()));
        }
    }
    ExitCode::SUCCESS
}
