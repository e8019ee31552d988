//! The command line read: its flags, and what `export` writes where.

use super::USAGE;
use meristem::export::{svg, Format};
use meristem::mesh::{MAX_SIDES, MIN_SIDES};
use std::path::PathBuf;

pub struct Args {
    pub verb: String,
    pub file: String,
    /// `lineage FILE MODULE`: the module's index in the derived string, as written.
    pub module: Option<String>,
    pub iterations: Option<u32>,
    pub seed: Option<u64>,
    /// `--at T`: the growth time, in steps.
    pub at: Option<f64>,
    pub stats: bool,
    pub time: bool,
    pub from: Option<String>,
    pub growth: bool,
    pub output: Option<PathBuf>,
    pub format: Option<String>,
    pub sides: Option<u32>,
    pub smooth_all: bool,
    pub edits: Option<PathBuf>,
    pub picture: PictureArgs,
    pub growth_out: GrowthOutArgs,
}

/// `--background`, `--line-width`, `--size` and `--dpi`: an SVG's picture settings, as written.
#[derive(Default)]
pub struct PictureArgs {
    pub background: Option<String>,
    pub line_width: Option<f64>,
    pub size: Option<String>,
    pub dpi: Option<f64>,
}

/// The growth out of the command line.
#[derive(Default)]
pub struct GrowthOutArgs {
    /// `export --animate`: the growth as a glTF animation, with `--seconds-per-step` and
    /// `--targets-per-step`.
    pub animate: bool,
    pub seconds_per_step: Option<f64>,
    pub targets_per_step: Option<u32>,
    /// `export --frames N`: N pictures of the growth into the output folder (`--at T` with an SVG
    /// or PNG output: one, at growth time T).
    pub frames: Option<u32>,
}

/// The command line. Long because it is the list of flags, one arm and one variable each: split,
/// it would only scatter that list.
pub fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut parser = lexopt::Parser::from_env();
    let mut verb = None;
    let mut file = None;
    let mut module = None;
    let mut iterations = None;
    let mut seed = None;
    let mut at = None;
    let mut stats = false;
    let mut time = false;
    let mut from = None;
    let mut growth = false;
    let mut output = None;
    let mut format = None;
    let mut sides = None;
    let mut smooth_all = false;
    let mut edits = None;
    let mut picture = PictureArgs::default();
    let mut growth_out = GrowthOutArgs::default();
    let mut seen = Vec::new();
    while let Some(arg) = parser.next()? {
        given_once(&arg, &mut seen)?;
        match arg {
            Long("iterations") | Short('n') => {
                iterations = Some(number(&mut parser, "--iterations")?)
            }
            Long("seed") | Short('s') => seed = Some(number(&mut parser, "--seed")?),
            Long("at") => at = Some(growth_time(&parser.value()?.string()?)?),
            Long("stats") => stats = true,
            Long("time") => time = true,
            Long("from") => from = Some(parser.value()?.string()?),
            Long("growth") => growth = true,
            Long("animate") => growth_out.animate = true,
            Long("seconds-per-step") => {
                growth_out.seconds_per_step = Some(number(&mut parser, "--seconds-per-step")?)
            }
            Long("targets-per-step") => {
                growth_out.targets_per_step = Some(number(&mut parser, "--targets-per-step")?)
            }
            Long("frames") => growth_out.frames = Some(number(&mut parser, "--frames")?),
            Long("output") | Long("out") | Short('o') => {
                output = Some(PathBuf::from(parser.value()?))
            }
            Long("format") | Short('f') => format = Some(parser.value()?.string()?),
            Long("sides") => sides = Some(parser.value()?.string()?),
            Long("smooth-all") => smooth_all = true,
            Long("edits") => edits = Some(PathBuf::from(parser.value()?)),
            Long("background") => picture.background = Some(parser.value()?.string()?),
            Long("line-width") => picture.line_width = Some(number(&mut parser, "--line-width")?),
            Long("size") => picture.size = Some(parser.value()?.string()?),
            Long("dpi") => picture.dpi = Some(number(&mut parser, "--dpi")?),
            Long("version") | Short('V') => {
                super::print_out(format_args!("meristem {}\n", env!("CARGO_PKG_VERSION")));
                std::process::exit(0);
            }
            Long("help") | Short('h') => {
                super::print_out(format_args!("{USAGE}\n"));
                std::process::exit(0);
            }
            Value(v) if verb.is_none() => verb = Some(v.string()?),
            Value(v) if file.is_none() => file = Some(v.string()?),
            Value(v) if verb.as_deref() == Some("lineage") && module.is_none() => {
                module = Some(v.string()?)
            }
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
        module,
        iterations,
        seed,
        at,
        stats,
        time,
        from,
        growth,
        output,
        format,
        sides,
        smooth_all,
        edits,
        picture,
        growth_out,
    })
}

/// The flags that take a value, each with the short or other names that are the same flag.
const VALUE_FLAGS: [(&str, &[&str]); 15] = [
    ("--iterations", &["n"]),
    ("--seed", &["s"]),
    ("--at", &[]),
    ("--from", &[]),
    ("--seconds-per-step", &[]),
    ("--targets-per-step", &[]),
    ("--frames", &[]),
    ("-o", &["o", "output", "out"]),
    ("--format", &["f"]),
    ("--sides", &[]),
    ("--edits", &[]),
    ("--background", &[]),
    ("--line-width", &[]),
    ("--size", &[]),
    ("--dpi", &[]),
];

/// Refuses a flag that takes a value given a second time (`-n 3 … -n 5` took the last without a
/// word: a script that adds a flag to one it forgot got another plant than it asked for).
fn given_once(arg: &lexopt::Arg, seen: &mut Vec<&'static str>) -> Result<(), lexopt::Error> {
    let name = match arg {
        lexopt::Arg::Long(name) => name.to_string(),
        lexopt::Arg::Short(c) => c.to_string(),
        lexopt::Arg::Value(_) => return Ok(()),
    };
    let flag = VALUE_FLAGS.iter().find(|(flag, other)| {
        flag.trim_start_matches('-') == name || other.contains(&name.as_str())
    });
    let Some(&(flag, _)) = flag else {
        return Ok(());
    };
    if seen.contains(&flag) {
        return Err(format!("{flag} is given twice: give it once").into());
    }
    seen.push(flag);
    Ok(())
}

/// The number after `flag`, or a message that names the flag and what it takes (lexopt's own
/// said only `cannot parse argument "abc"`, not for which flag).
fn number<T: Number>(parser: &mut lexopt::Parser, flag: &str) -> Result<T, lexopt::Error> {
    let value = parser.value()?;
    let text = value.to_string_lossy();
    text.trim()
        .parse()
        .map_err(|_| format!("{flag} {text}: give {}", T::WHAT).into())
}

/// A number a flag takes, and how it is said.
trait Number: std::str::FromStr {
    const WHAT: &'static str;
}

impl Number for u32 {
    const WHAT: &'static str = "a whole number from 0 to 4294967295";
}

impl Number for u64 {
    const WHAT: &'static str = "a whole number from 0 to 18446744073709551615";
}

impl Number for f64 {
    const WHAT: &'static str = "a number, e.g. 2.5";
}

/// `--at T`: a growth time from 0, in steps (refused otherwise, not clamped).
fn growth_time(text: &str) -> Result<f64, lexopt::Error> {
    match text.trim().parse::<f64>() {
        Ok(t) if t.is_finite() && t >= 0.0 => Ok(t),
        _ => Err(
            format!("--at {text}: the growth time is a number of steps from 0, e.g. 3.5").into(),
        ),
    }
}

/// An SVG's picture settings from `--background`, `--line-width`, `--size` and `--dpi`, checked;
/// refused for the other formats.
pub fn svg_look(args: &Args, format: Format) -> Result<svg::Look, String> {
    let given = args.picture.background.is_some()
        || args.picture.line_width.is_some()
        || args.picture.size.is_some()
        || args.picture.dpi.is_some();
    if given && format != Format::Svg {
        return Err(format!(
            "--background, --line-width, --size and --dpi are an SVG's picture settings, not {}'s",
            format.extension()
        ));
    }
    let size = match &args.picture.size {
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
    svg::Look::read(
        args.picture.background.as_deref(),
        args.picture.line_width,
        size,
        args.picture.dpi,
    )
}

/// Where `export` writes, in which format, and an SVG's look.
pub struct ExportTarget {
    pub output: PathBuf,
    pub format: Format,
    pub look: svg::Look,
}

/// Where `export` writes and in which format: `-o` is required; the format is `--format`, else
/// the output's extension.
pub fn export_target(args: &Args) -> Result<ExportTarget, String> {
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
            "{what}; the formats are {} (a PNG is a picture of the growth: --at T or --frames N)",
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

/// Refuses a flag the verb has no use for (`derive plant.lsys -o out.txt` printed the string on
/// stdout and wrote no file, with exit 0), and flags that exclude each other.
pub fn check_flags(args: &Args) -> Result<(), String> {
    let given = [
        (
            "--iterations",
            args.iterations.is_some(),
            "derive check lineage export import",
        ),
        ("--at", args.at.is_some(), "derive check lineage export"),
        (
            "--seed",
            args.seed.is_some(),
            "derive check lineage export import",
        ),
        ("--stats", args.stats, "derive"),
        ("--growth", args.growth, "derive"),
        ("--time", args.time, "derive check export"),
        ("--from", args.from.is_some(), "import"),
        ("-o", args.output.is_some(), "export import"),
        ("--format", args.format.is_some(), "export"),
        ("--sides", args.sides.is_some(), "derive check export"),
        ("--smooth-all", args.smooth_all, "derive check export"),
        ("--edits", args.edits.is_some(), "derive check export"),
        ("--background", args.picture.background.is_some(), "export"),
        ("--line-width", args.picture.line_width.is_some(), "export"),
        ("--size", args.picture.size.is_some(), "export"),
        ("--dpi", args.picture.dpi.is_some(), "export"),
        ("--animate", args.growth_out.animate, "export"),
        (
            "--seconds-per-step",
            args.growth_out.seconds_per_step.is_some(),
            "export",
        ),
        (
            "--targets-per-step",
            args.growth_out.targets_per_step.is_some(),
            "export",
        ),
        ("--frames", args.growth_out.frames.is_some(), "export"),
    ];
    for (flag, is_given, verbs) in given {
        if is_given && !verbs.split(' ').any(|v| v == args.verb) {
            let hint = if flag == "-o" {
                " (it prints on stdout: redirect it, > FILE)"
            } else {
                ""
            };
            return Err(format!("{} takes no {flag}{hint}", args.verb));
        }
    }
    if args.stats && args.growth {
        return Err("--stats and --growth: give one of them".into());
    }
    // (`--at` won without a word.)
    if args.iterations.is_some() && args.at.is_some() {
        return Err("--iterations and --at: give one of them".into());
    }
    let animation =
        args.growth_out.seconds_per_step.is_some() || args.growth_out.targets_per_step.is_some();
    if animation && !args.growth_out.animate {
        return Err(
            "--seconds-per-step and --targets-per-step set the glTF animation: add --animate"
                .into(),
        );
    }
    Ok(())
}
