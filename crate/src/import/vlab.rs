//! A Virtual Laboratory object opened whole: the L-system (`plant.l`), its view file (`.v`: the
//! angle increment, widths, colours, the function files), function files (`.func`, a function set
//! `.fset`; lpfg's timeline functions `.tset` and values `.vset`, [`lpfg_functions`]), and its
//! colour map (`.map`) or materials (`.mat`). Which files belong together is read from the
//! object's `specifications` (the `cpfg …` or `lpfg …` command line), else guessed from the names.
//! An object without a `.l` but with an L-Py `.lpy` is imported as L-Py.

pub(super) mod contour_file;
mod environment_file;
mod function_file;
mod lpfg_functions;
mod lpfg_surface;
mod python_main;
mod specifications;
mod surface_file;

use function_file::{function, function_set, short};
pub use python_main::{python_main, PythonMain};
use specifications::{command, Command};

use super::abop::{self, Flavour};
use super::{Dialect, Import};
use crate::vocabulary::{function_named, value_named, DirectiveKind};

/// One file of an object: its name (a path inside the folder or zip; only the last part counts)
/// and its bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ObjectFile {
    pub name: String,
    pub bytes: Vec<u8>,
}

/// What the view file and the colour files say, in Meristem's terms.
#[derive(Clone, Debug, Default)]
pub(super) struct View {
    /// `angle factor: n` (360/n) or `angle increment: d`.
    pub angle: Option<f64>,
    pub width: Option<f64>,
    pub width_step: Option<f64>,
    /// cpfg draws lines as polygons or cylinders, whose width is in the model's units (`line
    /// style: polygon | cylinder`, or `initial line width: w` without `pixels`), not as lines
    /// `w` pixels wide (`line style: pixel`, cpfg's default): [`line_style`].
    pub model_widths: bool,
    pub color: Option<f64>,
    pub color_increment: Option<f64>,
    /// `tropism direction: x,y,z` and `initial elasticity: e` (or `tropism: T: x,y,z E: e`).
    pub tropism: Option<[f64; 3]>,
    pub elasticity: Option<f64>,
    /// The functions `func(k, x)` reads, k from 1 (lpfg's `tfunc(k, t)` and `val(k)` too: its
    /// function sets, timelines and values share one list): each a name and the lines that
    /// define it; `None` for one that could not be read (it keeps its number).
    pub functions: Vec<Option<CurveFunction>>,
    /// The contours `curveX(k, t)`, `curveY`, `curveZ` and `curveGAL(k)` read, k from 1 (the
    /// view file's `curve:` lines); `None` for one that could not be read.
    pub contours: Vec<Option<contour_file::Contour>>,
    /// `#color` lines from the colour map or materials.
    pub palette: Vec<String>,
    /// `#surface` and `#patch` lines from the view file's surfaces and their `.s` files.
    pub surfaces: Vec<String>,
    /// The letters those lines declare (`~X` draws them).
    pub surface_letters: Vec<String>,
    /// lpfg's surfaces by id: the view file's `surface: file.s …` lines in order, each with the
    /// letter it is declared by (lpfg's `Surface(id, s)` draws `~X(s)`); a file not opened or not
    /// read takes no id, as lpfg leaves out a file it cannot load.
    pub lpfg_surfaces: Vec<LpfgSurface>,
    /// An lpfg surface file the view file names was not opened with the object (what lpfg's
    /// `Surface` then draws is not known).
    pub lpfg_surface_missing: bool,
    /// The object has materials (`.mat`) rather than a colour map: cpfg then draws a `.s`
    /// surface in the turtle's material, not in its patches' colours.
    pub materials: bool,
    /// The object's environmental program (its `.e` file), translated or named as missing.
    pub environment: Option<environment_file::Environment>,
    /// Notes about the view and colour files (line 0).
    pub notes: Vec<String>,
    /// The file names, for the header.
    pub sources: Vec<String>,
}

/// One of lpfg's surfaces: the view file's text after `surface:` (lpfg loads a line once) and the
/// letter that draws it.
#[derive(Clone, Debug)]
pub(super) struct LpfgSurface {
    pub line: String,
    pub letter: String,
}

/// A cpfg function as a Meristem `#curve` or `#table` (an lpfg value as a `#define`).
#[derive(Clone, Debug)]
pub(super) struct CurveFunction {
    /// The Meristem name, and the name the function file gives (what `func(NAME, x)` says).
    pub name: String,
    pub source: String,
    /// What the comment above a function says it is: `the function of f.fset`.
    pub about: String,
    pub body: Body,
    pub kind: FunctionKind,
}

/// What a [`CurveFunction`] writes.
#[derive(Clone, Debug)]
pub(super) enum Body {
    /// These lines (an lpfg value's `#define`).
    Lines(Vec<String>),
    /// A function of control points `x y …`, sampled when it is written ([`CurveFunction::lines`]):
    /// only the functions the L-system reads are, so a set of thousands costs nothing to read
    /// (issue 50, 6).
    Points {
        points: Vec<f64>,
        samples: usize,
        tool: &'static str,
    },
}

/// What an entry of the object's function list is.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum FunctionKind {
    /// A function of x from 0 to 1 (`.func`, `.fset`): `func(NAME, x)`.
    Curve,
    /// lpfg's timeline function (`.tset`): `tfunc(NAME, t)` reads it at
    /// `(t − start)/(end − start)`, clamped to 0…1; `func(NAME, x)` at x.
    Timeline(Span),
    /// lpfg's value (`.vset`, `#define NAME value`): `val(NAME)`; its lines `#define` it.
    Value(f64),
}

/// A timeline function's times, and the labels vlab's timeline tool ties them to: the names of
/// the `.vset` values it keeps equal to them (empty when none).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Span {
    pub start: f64,
    pub end: f64,
    pub start_label: String,
    pub end_label: String,
}

/// The last part of a path.
fn base(name: &str) -> &str {
    name.rsplit(['/', '\\']).next().unwrap_or(name)
}

/// The files of an object by base name (the shallowest when two share one).
struct Files<'a> {
    files: Vec<(&'a str, &'a [u8])>,
}

impl<'a> Files<'a> {
    fn new(files: &'a [ObjectFile]) -> Self {
        let mut sorted: Vec<&ObjectFile> = files.iter().collect();
        sorted.sort_by_key(|f| f.name.matches(['/', '\\']).count());
        let mut list: Vec<(&str, &[u8])> = Vec::new();
        for f in sorted {
            let b = base(&f.name);
            if !b.is_empty() && !list.iter().any(|(n, _)| *n == b) {
                list.push((b, &f.bytes));
            }
        }
        Files { files: list }
    }

    fn get(&self, name: &str) -> Option<&'a [u8]> {
        let name = base(name.trim());
        self.files.iter().find(|(n, _)| *n == name).map(|(_, b)| *b)
    }

    fn text(&self, name: &str) -> Option<String> {
        self.get(name)
            .map(|b| String::from_utf8_lossy(b).into_owned())
    }

    /// The names ending with `.ext`, in order.
    fn with(&self, ext: &str) -> Vec<&'a str> {
        self.files
            .iter()
            .map(|(n, _)| *n)
            .filter(|n| n.to_ascii_lowercase().ends_with(ext))
            .collect()
    }
}

/// The file among `names` with the stem `stem`, else the only one, else the first.
fn pick<'a>(names: &[&'a str], stem: &str) -> Option<&'a str> {
    names
        .iter()
        .find(|n| n.rsplit_once('.').map(|(s, _)| s) == Some(stem))
        .or_else(|| names.first())
        .copied()
}

/// Imports what was opened together (a folder's files, several files, a `.zip`): any `.zip`
/// among them is unpacked, then the whole is imported as one object. A broken archive gives a
/// note and nothing else. With the dialect read (`None` when nothing was).
pub fn import_files(files: &[ObjectFile]) -> (Import, Option<Dialect>) {
    let mut all = Vec::new();
    for f in files {
        if !f.name.to_ascii_lowercase().ends_with(".zip") {
            all.push(f.clone());
            continue;
        }
        match super::unzip(&f.bytes) {
            Ok(inner) => all.extend(inner),
            Err(why) => {
                let mut import = Import::default();
                import.notes.push(super::ImportNote {
                    line: 0,
                    message: format!("{}: {why}", base(&f.name)),
                });
                return (import, None);
            }
        }
    }
    let import = import_object(&all);
    let dialect = (!import.is_empty()).then(|| object_dialect(&all)).flatten();
    (import, dialect)
}

/// The dialect [`import_object`] reads the files in: cpfg when there is a `.l`, else L-Py's
/// `.lpy`, else Lparser's `.ls`.
fn object_dialect(files: &[ObjectFile]) -> Option<Dialect> {
    let has = |ext: &str| {
        files
            .iter()
            .any(|f| f.name.to_ascii_lowercase().ends_with(ext))
    };
    [
        (".l", Dialect::Cpfg),
        (".lpy", Dialect::Lpy),
        (".ls", Dialect::Lparser),
    ]
    .into_iter()
    .find(|(ext, _)| has(ext))
    .map(|(_, d)| d)
}

/// Imports a vlab object (or any folder holding one L-system file).
pub fn import_object(files: &[ObjectFile]) -> Import {
    let all = Files::new(files);
    let spec = all
        .text("specifications")
        .and_then(|s| command(&s))
        .unwrap_or_else(|| Command {
            lpfg: lpfg_functions::LpfgFiles::guessed(&all),
            ..Command::default()
        });
    let Some(lsystem) = lsystem_file(&all, &spec) else {
        return other_dialect(&all);
    };
    let stem = lsystem.trim_end_matches(".l").to_string();
    let text = all.text(&lsystem).unwrap_or_default();
    let views = all.with(".v");
    let view_name = spec
        .view
        .clone()
        .filter(|v| all.get(v).is_some())
        .or_else(|| pick(&views, &stem).map(str::to_string));
    let mut view = View {
        materials: colour_files(&all, &spec, &stem).1.is_some(),
        ..View::default()
    };
    view.sources.push(lsystem.clone());
    match &view_name {
        Some(name) => {
            view.sources.push(name.clone());
            read_view(&all.text(name).unwrap_or_default(), &all, &mut view);
        }
        None => view.notes.push(
            "the object has no view file (.v): the angle increment, widths and colours are not known, so Meristem's defaults are used (90°, width 1, its palette)".into(),
        ),
    }
    // lpfg's function sets, timelines and values, unless the view file already read them
    // (`function set:`).
    let view_text = view_name
        .as_ref()
        .and_then(|v| all.text(v))
        .unwrap_or_default();
    lpfg_functions::read(&all, &spec.lpfg, &view_text, &mut view);
    colours(&all, &spec, &stem, &mut view);
    let communication = spec.environment.clone().or_else(|| {
        let es = all.with(".e");
        (es.len() == 1).then(|| es[0].to_string())
    });
    if let Some(e) = communication {
        view.environment = environment_file::read(&e, &all);
        if view.environment.is_some() {
            view.sources.push(e);
        }
    }
    let include = |name: &str| all.text(name);
    abop::import_with(&text, Flavour::Cpfg, Some(&view), &include)
}

/// The object's L-system file: the one `specifications` names, else `plant.l` or `lsystem.l`,
/// else the first `.l`.
fn lsystem_file(all: &Files, spec: &Command) -> Option<String> {
    spec.lsystem
        .clone()
        .filter(|l| all.get(l).is_some())
        .or_else(|| {
            ["plant.l", "lsystem.l"]
                .iter()
                .find(|n| all.get(n).is_some())
                .map(|s| s.to_string())
        })
        .or_else(|| all.with(".l").first().map(|s| s.to_string()))
}

/// A folder without a cpfg `.l`: its L-Py `.lpy`, Lparser `.ls` or Meristem `.lsys`.
fn other_dialect(all: &Files) -> Import {
    for (ext, dialect) in [(".lpy", Dialect::Lpy), (".ls", Dialect::Lparser)] {
        if let Some(name) = all.with(ext).first() {
            return super::import(&all.text(name).unwrap_or_default(), dialect);
        }
    }
    let mut import = Import::default();
    import.notes.push(super::ImportNote {
        line: 0,
        message: "no L-system file in what was opened: a vlab object has a .l file (cpfg), an L-Py model a .lpy file".into(),
    });
    import
}

/// Reads the view file's lines that shape the plant.
fn read_view(text: &str, all: &Files, view: &mut View) {
    for line in text.lines() {
        let Some((key, value)) = line.split_once(':') else {
            continue;
        };
        let key = key.trim().to_ascii_lowercase();
        let first = value
            .split_whitespace()
            .next()
            .and_then(|w| w.parse::<f64>().ok())
            .filter(|v| v.is_finite());
        match key.as_str() {
            "angle factor" => view.angle = first.filter(|v| *v != 0.0).map(|v| 360.0 / v),
            "angle increment" => view.angle = first,
            "initial line width" => (view.width, view.model_widths) = (first, line_style(value, true)),
            "line style" => view.model_widths = line_style(value, false),
            "line width increment" => view.width_step = first,
            "initial color" => view.color = first,
            "color increment" => view.color_increment = first,
            "tropism direction" => view.tropism = vector(value),
            "initial elasticity" => view.elasticity = first,
            "tropism" => {
                // The newer form: `tropism: T: x,y,z E: e` (one tropism of several).
                let (t, e) = value.split_once("E:").unwrap_or((value, ""));
                view.tropism = vector(t.trim().trim_start_matches("T:"));
                view.elasticity = e.split_whitespace().next().and_then(|w| w.parse().ok());
            }
            "elasticity increment" if first.is_some_and(|e| e != 0.0) => view.notes.push(format!(
                "the view file's elasticity increment ({}) is not translated: Meristem's tropism keeps one susceptibility",
                value.trim()
            )),
            "surface" => {
                let words: Vec<&str> = value.split_whitespace().collect();
                let number = |w: &&str| w.parse::<f64>().is_ok();
                match words.as_slice() {
                    [] => {}
                    // lpfg's form: the file, then numbers; its surfaces are numbered in order.
                    [file, rest @ ..] if rest.first().is_none_or(number) => {
                        lpfg_surface::read(file, rest, all, view)
                    }
                    [name, file, rest @ ..] => surface(name, file, rest.to_vec(), all, view),
                    _ => {}
                }
            }
            "function" => {
                let mut words = value.split_whitespace();
                let file = words.next().unwrap_or("").to_string();
                let samples = words.next().and_then(|w| w.parse::<usize>().ok());
                let function = all
                    .text(&file)
                    .and_then(|t| function(&t, samples, &file, Reader::Cpfg, view));
                if function.is_none() {
                    view.notes.push(format!(
                        "the function file {file} could not be read: func({}, …) is not translated",
                        view.functions.len() + 1
                    ));
                }
                view.functions.push(function);
            }
            // lpfg's tropism: `stropism: x y z, e`.
            "stropism" => view.notes.push(format!(
                "the view file's {key} line ({}) is not translated: the plant does not bend by it",
                value.trim()
            )),
            "curve" => contour(value, all, view),
            "function set" => {
                let file = value.trim().to_string();
                match all.text(&file) {
                    Some(t) => function_set(&t, &file, Reader::Cpfg, view),
                    None => view.notes.push(format!(
                        "the function set {file} was not opened with the object: its functions are not translated"
                    )),
                }
            }
            _ => {}
        }
    }
}

/// Whether cpfg draws widths in the model's units after a view file's `initial line width: w
/// [unit]` (`width_line`) or `line style: s` line (vlab `cpfg/interpret.c`, `ReadViewData`): a
/// width followed by a word starting with p (`pixels`) draws lines in pixels, one followed by
/// nothing (polygons) or by a word starting with s (cylinders) in model units; the line style
/// `pixel` (or 1) draws in pixels, `polygon` and `cylinder` (2, 3) in model units, since
/// cpfg's cylinder is a unit cylinder of diameter 1 scaled by the width (`MakeCylinder`,
/// `iGlEndCylNode` in `cpfg/irisGL.c`). lpfg reads the same `line style:` words (default pixel,
/// `lpfg/drawparam.cpp`) and has no `initial line width:`.
fn line_style(value: &str, width_line: bool) -> bool {
    let mut words = value.split_whitespace();
    if width_line {
        return !words.nth(1).is_some_and(|unit| unit.starts_with('p'));
    }
    let style = words.next().unwrap_or("");
    !(style == "pixel" || style.starts_with('1'))
}

/// A view file's `surface: X file.s scale [s t]`: the file's patches as `#surface X …` and
/// `#patch X …` lines, or a note saying why not (what `~X` then draws).
fn surface(name: &str, file: &str, rest: Vec<&str>, all: &Files, view: &mut View) {
    let (scale, precision, _) = surface_numbers(&rest);
    let own = match name {
        "p" => "Meristem's own petal",
        "l" => "Meristem's own leaf",
        _ => "nothing",
    };
    let one_letter = name.len() == 1 && name.chars().all(|c| c.is_ascii_alphabetic());
    let wanted = surface_file::Wanted {
        file: base(file),
        letter: name,
        scale,
        precision,
        colours: !view.materials,
    };
    let read = match all.text(file) {
        _ if !one_letter => Err(format!("Meristem cannot use: '{name}' is not one letter")),
        Some(text) => {
            surface_file::read(&text, &wanted).map_err(|why| format!("cannot be read ({why})"))
        }
        None => Err("was not opened with the object".to_string()),
    };
    match read {
        Ok(lines) => {
            view.surfaces.extend(lines.lines);
            view.surface_letters.push(name.to_string());
            view.notes.extend(lines.note);
        }
        Err(why) => view.notes.push(format!(
            "the view file's surface {name} is read from {file}, which {why}: ~{name} draws {own}"
        )),
    }
}

/// The numbers after a surface line's file: its scale (0 or below is 1, as cpfg and lpfg read
/// it), its precisions s and t (0 0 when not given: the file's, or the tool's default), and how
/// many numbers there are.
fn surface_numbers(rest: &[&str]) -> (f64, [u32; 2], usize) {
    let numbers: Vec<f64> = rest
        .iter()
        .map_while(|w| w.parse::<f64>().ok().filter(|v| v.is_finite()))
        .collect();
    let scale = numbers.first().copied().filter(|s| *s > 0.0).unwrap_or(1.0);
    let precision = match numbers.get(1..3) {
        Some([s, t]) => [*s, *t].map(|v| v.clamp(0.0, 1e6) as u32),
        _ => [0, 0],
    };
    (scale, precision, numbers.len())
}

/// Three numbers separated by commas or spaces.
fn vector(text: &str) -> Option<[f64; 3]> {
    let v: Vec<f64> = text
        .split([',', ' ', '\t'])
        .filter(|w| !w.is_empty())
        .map(|w| w.parse::<f64>().ok().filter(|v| v.is_finite()))
        .collect::<Option<_>>()?;
    v.try_into().ok()
}

/// Whose reading of a function file to follow: cpfg samples a function when the view file (or
/// a `fver 1 1` file) asks for more than 2 samples, else reads the spline itself; lpfg always
/// samples, 10 to 1,000 times (`Function::_Load0101`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Reader {
    Cpfg,
    Lpfg,
}

impl Reader {
    fn tool(self) -> &'static str {
        match self {
            Reader::Cpfg => "cpfg",
            Reader::Lpfg => "lpfg",
        }
    }
}

/// The view file's `curve: file.con` (the text after the colon): the next contour of `curveX(k, …)`.
fn contour(value: &str, all: &Files, view: &mut View) {
    let file = value.split_whitespace().next().unwrap_or("").to_string();
    let stem = identifier(base(&file).trim_end_matches(".con"), view);
    let contour = all.text(&file).and_then(|t| contour_file::read(&t, &stem));
    if contour.is_none() {
        view.notes.push(format!(
            "the contour file {file} could not be read (it was not opened, or it is no B-spline): curveX({}, …) and the others are not translated",
            view.contours.len() + 1
        ));
    }
    view.contours.push(contour);
}

/// A Meristem name for a function (or an lpfg value): letters, digits and `_`, not a built-in function's nor one
/// already taken.
fn identifier(name: &str, view: &View) -> String {
    let mut id: String = name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    if !id.starts_with(|c: char| c.is_ascii_alphabetic()) {
        id.insert_str(0, "f_");
    }
    let taken = |id: &str| {
        function_named(id).is_some()
            || value_named(id).is_some_and(|v| !v.definable)
            || ["func", "tfunc", "val"].contains(&id)
            || view.functions.iter().flatten().any(|f| f.name == id)
    };
    while taken(&id) {
        id.push_str("_f");
    }
    id
}

/// The colour map (`.map`: 256 × red, green, blue bytes) or materials (`.mat`: records of an
/// index and 14 bytes: transparency, ambient, diffuse, emissive, specular, shininess) as `#color`
/// ramps.
fn colours(all: &Files, spec: &Command, stem: &str, view: &mut View) {
    let (map, mat) = colour_files(all, spec, stem);
    let mut entries: Vec<Option<[u8; 3]>> = vec![None; 256];
    if let Some(bytes) = map.as_deref().and_then(|m| all.get(m)) {
        for (i, rgb) in bytes.chunks_exact(3).take(256).enumerate() {
            entries[i] = Some([rgb[0], rgb[1], rgb[2]]);
        }
        view.sources.push(map.clone().unwrap_or_default());
    } else if let Some(bytes) = mat.as_deref().and_then(|m| all.get(m)) {
        for record in bytes.chunks_exact(15) {
            entries[record[0] as usize] = Some([record[5], record[6], record[7]]);
        }
        view.sources.push(mat.clone().unwrap_or_default());
        view.notes.push(format!(
            "the materials of {} become their diffuse colours: their ambient, emissive and specular light, shininess and transparency are not kept",
            mat.clone().unwrap_or_default()
        ));
    } else {
        view.notes.push(
            "the object has no colour map (.map) or materials (.mat): Meristem's palette is used"
                .into(),
        );
        return;
    }
    view.palette = ramps(&entries);
}

/// The colour map the object is drawn with, else its materials: each a file opened with it.
fn colour_files(all: &Files, spec: &Command, stem: &str) -> (Option<String>, Option<String>) {
    let (map, mat) = if spec.colormap.is_some() || spec.materials.is_some() {
        (spec.colormap.clone(), spec.materials.clone())
    } else {
        let maps = all.with(".map");
        let mats = all.with(".mat");
        (
            pick(&maps, stem).map(str::to_string),
            pick(&mats, stem).map(str::to_string),
        )
    };
    let opened = |f: Option<String>| f.filter(|f| all.get(f).is_some());
    match opened(map) {
        Some(map) => (Some(map), None),
        None => (None, opened(mat)),
    }
}

/// `#color` lines for the entries: runs that change linearly become one ramp.
fn ramps(entries: &[Option<[u8; 3]>]) -> Vec<String> {
    let color = DirectiveKind::Color.written();
    let mut lines = Vec::new();
    let mut i = 0;
    while i < entries.len() {
        let Some(a) = entries[i] else {
            i += 1;
            continue;
        };
        // The longest run from i whose entries lie on the line from a to its last entry.
        let mut end = i;
        for j in i + 1..entries.len() {
            let Some(b) = entries[j] else { break };
            let linear = (i + 1..j).all(|k| {
                entries[k].is_some_and(|c| {
                    (0..3).all(|ch| {
                        let t = (k - i) as f64 / (j - i) as f64;
                        let v = a[ch] as f64 + (b[ch] as f64 - a[ch] as f64) * t;
                        (c[ch] as f64 - v).abs() <= 1.0
                    })
                })
            });
            if !linear {
                break;
            }
            end = j;
        }
        if end > i + 1 {
            let b = entries[end].unwrap_or(a);
            lines.push(format!(
                "{color} {i} {end} {} {} {} {} {} {}",
                a[0], a[1], a[2], b[0], b[1], b[2]
            ));
            i = end + 1;
        } else {
            lines.push(format!("{color} {i} {} {} {}", a[0], a[1], a[2]));
            i += 1;
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cpfg_command_line_names_the_files() {
        let c = command(
            "model:\n\tgenerate:\n\t\tcpfg -M material.mat -w 300 500 leaf.l leaf.v leaf.a\n",
        )
        .expect("command");
        assert_eq!(c.lsystem.as_deref(), Some("leaf.l"));
        assert_eq!(c.view.as_deref(), Some("leaf.v"));
        assert_eq!(c.materials.as_deref(), Some("material.mat"));
        assert_eq!(c.colormap, None);
    }

    #[test]
    fn a_linear_colour_map_is_one_ramp() {
        let entries: Vec<Option<[u8; 3]>> = (0..256)
            .map(|i| Some([i as u8, 0, (255 - i) as u8]))
            .collect();
        assert_eq!(ramps(&entries), ["#color 0 255 0 0 255 255 0 0"]);
        let mut two = vec![None; 256];
        two[3] = Some([1, 2, 3]);
        two[4] = Some([9, 9, 9]);
        assert_eq!(ramps(&two), ["#color 3 1 2 3", "#color 4 9 9 9"]);
    }

    #[test]
    fn cpfg_draws_cylinders_and_polygons_in_model_units_and_lines_in_pixels() {
        assert!(line_style(" 0.5", true), "a width alone: polygons");
        assert!(!line_style(" 2 pixels", true));
        assert!(line_style(" 2 s", true), "cpfg reads s as cylinders");
        assert!(line_style(" cylinder", false));
        assert!(line_style(" polygon /* or cylinder */", false));
        assert!(line_style(" 3", false));
        assert!(!line_style(" pixel // this is the default", false));
        assert!(!line_style(" 1", false));
        let mut view = View::default();
        let text = "initial line width: 2 pixels\nline style: cylinder\n";
        read_view(text, &Files::new(&[]), &mut view);
        assert!(
            view.model_widths,
            "the later line wins, as cpfg reads them in order"
        );
        let mut view = View::default();
        read_view(
            "line style: cylinder\ninitial line width: 2 pixels\n",
            &Files::new(&[]),
            &mut view,
        );
        assert!(!view.model_widths);
    }

    #[test]
    fn short_numbers_keep_seven_digits() {
        assert_eq!(short(0.0045550001), "0.004555");
        assert_eq!(short(1.0031760), "1.003176");
        assert_eq!(short(-0.0), "0");
        assert_eq!(short(123456.789), "123456.8");
    }
}
