//! A model run by Python (the `meristem_lsystem` package, `python/README.md`) turned into
//! Meristem text: the derived string goes through the existing importers, so the turtle mapping is
//! written once. An L-Py run's string becomes an L-Py text `Axiom: <string>` with derivation
//! length 0 (with the source's `module` declarations, so long names stay whole); an lpfg run's
//! string becomes the axiom of an L+C text that replaces the object's `.l`, and the object is
//! imported as before, so its view file, functions, colours and surfaces still apply. The text
//! starts with comment lines saying where it came from: it is the plant, not its rules.
//!
//! [`needs_python`] is the one rule that says when the Python route is taken.

use super::vlab::ObjectFile;
use super::{import, import_files, number, Dialect, Import, ImportNote};
use crate::diagnostics::has_errors;
use crate::syntax::PARENTHESES;
use serde::Deserialize;

/// The result of `meristem_lsystem.run` (its JSON), as far as Meristem reads it.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(default)]
pub struct DerivedRun {
    pub ok: bool,
    pub dialect: String,
    pub steps: u64,
    pub lstring: String,
    pub materials: Vec<RunMaterial>,
    pub notes: Vec<RunNote>,
    pub error: Option<RunError>,
}

/// A material of the model's set-up: a colour index and its colour (0 to 255).
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(default)]
pub struct RunMaterial {
    pub index: i64,
    pub rgb: [f64; 3],
}

/// Something the run did not reproduce, at a line of the source.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(default)]
pub struct RunNote {
    pub line: usize,
    pub message: String,
}

/// Why the run stopped, at a line and column of the source.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(default)]
pub struct RunError {
    pub line: usize,
    pub column: usize,
    pub message: String,
}

/// lpfg's predefined modules (its `include/stdmods.h`): never declared again (the importer maps
/// those it knows to Meristem's turtle, `abop/lpfg.rs`).
const LPFG_PREDEFINED: &[&str] = &[
    "SB",
    "EB",
    "F",
    "f",
    "Left",
    "Right",
    "Down",
    "Up",
    "RollL",
    "RollR",
    "IncColor",
    "DecColor",
    "SetColor",
    "SetWidth",
    "Label",
    "TurnAround",
    "Cut",
    "GetPos",
    "GetHead",
    "GetLeft",
    "GetUp",
    "Circle",
    "MoveTo",
    "Sphere",
    "SetHead",
    "Sphere0",
    "Circle0",
    "Line2f",
    "Line2d",
    "Line3f",
    "Line3d",
    "LineTo2f",
    "LineTo2d",
    "LineTo3f",
    "LineTo3d",
    "LineRel2f",
    "LineRel2d",
    "LineRel3f",
    "LineRel3d",
    "Surface",
    "RollToVert",
    "SetElasticity",
    "IncElasticity",
    "DecElasticity",
    "CurrentContour",
    "StartGC",
    "PointGC",
    "EndGC",
    "Mesh",
    "E1",
    "MoveTo2f",
    "MoveTo2d",
    "MoveTo3f",
    "MoveTo3d",
    "E2",
    "SP",
    "EP",
    "PP",
    "Rhombus",
    "Triangle",
    "MouseIns",
    "BlendedContour",
    "CurrentTexture",
    "TextureVCoeff",
    "Orient",
    "ScaleContour",
    "Elasticity",
    "DSurface",
    "G",
    "g",
    "MouseInsPos",
    "Surface3",
    "ContourSides",
    "InitSurface",
    "SurfacePoint",
    "DrawSurface",
    "Propensity",
    "CircleFront",
    "CircleFront0",
    "SetUPrecision",
    "SetVPrecision",
    "LineTo",
    "BSurface",
    "MoveRel2f",
    "MoveRel2d",
    "MoveRel3f",
    "MoveRel3d",
    "DBSurfaceS",
    "DBSurfaceM",
    "Camera",
    "EA20",
    "Rotate",
    "RotateHLU",
    "RotateXYZ",
    "Terrain",
    "PovRayStart",
    "SetHead3f",
    "SetTropismDirection3f",
    "CircleB",
    "CircleFrontB",
    "SetCoordinateSystem",
    "Mesh3",
    "ContourNormal",
];

/// The Meristem import of a Python run: `result_json` is what `run` returned for the file named
/// `main` among `files` (the same files it was given), with `seed`. A run that stopped (its
/// `error`, or JSON Meristem cannot read) gives an empty text and a note at the error's line;
/// [`prefer_derived`] then keeps the hand translation.
pub fn import_derived(result_json: &str, main: &str, files: &[ObjectFile], seed: u64) -> Import {
    let run: DerivedRun = match serde_json::from_str(result_json) {
        Ok(run) => run,
        Err(e) => return failed(0, format!("the Python run's result cannot be read: {e}")),
    };
    if let Some(error) = &run.error {
        let at = if error.column > 0 {
            format!("column {}: ", error.column)
        } else {
            String::new()
        };
        return failed(
            error.line,
            format!(
                "running the model with Python stopped: {at}{}",
                error.message
            ),
        );
    }
    if !run.ok {
        return failed(
            0,
            "the Python run did not finish and gave no reason".to_string(),
        );
    }
    let lpfg = run.dialect == "lpfg";
    let scanned = scan(&run.lstring, !lpfg);
    let source = files
        .iter()
        .find(|f| f.name == main || base(&f.name) == base(main))
        .map(|f| String::from_utf8_lossy(&f.bytes).into_owned())
        .unwrap_or_default();
    let mut imported = if lpfg {
        let text = lpfg_text(&source, &scanned);
        let replaced: Vec<ObjectFile> = files
            .iter()
            .map(|f| match base(&f.name) == base(main) {
                true => ObjectFile {
                    name: f.name.clone(),
                    bytes: text.clone().into_bytes(),
                },
                false => f.clone(),
            })
            .collect();
        import_files(&replaced).0
    } else {
        import(&lpy_text(&source, &scanned.text), Dialect::Lpy)
    };
    // The importer's notes are about the written string, not about a line of the source.
    for note in &mut imported.notes {
        note.line = 0;
    }
    finish(imported, &run, &scanned, main, seed)
}

/// The derived import's header, colours and notes.
fn finish(imported: Import, run: &DerivedRun, scanned: &Scanned, main: &str, seed: u64) -> Import {
    let name = base(main);
    let steps = match run.steps {
        1 => "1 step".to_string(),
        n => format!("{n} steps"),
    };
    let mut text = format!(
        "// Derived by Python from {name} in {steps}, with seed {seed} (meristem_lsystem).\n\
         // This is the plant's final string, not its rules: to change the rules, edit {name}\n\
         // and open it again.\n"
    );
    for m in &run.materials {
        let declared = format!("#color {} ", m.index);
        if m.index < 0 || imported.text.lines().any(|l| l.starts_with(&declared)) {
            continue;
        }
        let [r, g, b] = m.rgb.map(|c| c.clamp(0.0, 255.0).round() as u8);
        text.push_str(&format!("#color {} {r} {g} {b}\n", m.index));
    }
    text.push_str(&imported.text);
    let mut notes = imported.notes;
    for (name, count) in &scanned.objects {
        notes.push(ImportNote {
            line: 0,
            message: format!(
                "{count} module(s) {name} carry Python objects as parameters (PlantGL geometry or \
                 curves, strings): Meristem keeps the module without its parameters and draws \
                 nothing for those objects"
            ),
        });
    }
    notes.extend(run.notes.iter().map(|n| ImportNote {
        line: n.line,
        message: n.message.clone(),
    }));
    notes.sort_by_key(|n| n.line);
    Import { text, notes }
}

/// An import that failed: no text, one note.
fn failed(line: usize, message: String) -> Import {
    Import {
        text: String::new(),
        notes: vec![ImportNote { line, message }],
    }
}

/// The derived import when it has a plant, else the hand translation with the derived import's
/// notes (why Python did not give one) added. The one place that chooses between them.
pub fn prefer_derived(translation: Import, derived: Import) -> Import {
    if !derived.is_empty() {
        return derived;
    }
    let mut kept = translation;
    for note in derived.notes {
        kept.notes.push(ImportNote {
            line: note.line,
            message: format!("{}; the hand translation is used", note.message),
        });
    }
    kept.notes.sort_by_key(|n| n.line);
    kept
}

/// The steps after which [`needs_python`] looks whether a translation draws, in turn: most
/// plants draw within 3, a continuous-growth model (an apex that lays an internode every few
/// steps of `dt`) within tens.
const STEPS_TO_SEE_A_PLANT: [u32; 3] = [3, 30, 100];

/// The most modules [`needs_python`] derives to see whether a translation draws.
const MODULES_TO_SEE_A_PLANT: usize = 200_000;

/// Whether a hand translation falls short, so that the model is better run by Python: it has
/// no axiom, carries a note (something dropped or approximated), or draws nothing (no segment
/// and no triangle) after 3, 30 or 100 of its steps ([`STEPS_TO_SEE_A_PLANT`]; a translation that
/// passes [`MODULES_TO_SEE_A_PLANT`] modules before it draws is left to Python). Whether Python
/// can run the files at all is [`crate::import::python_main`]'s answer.
pub fn needs_python(translation: &Import) -> bool {
    if translation.is_empty() || !translation.notes.is_empty() {
        return true;
    }
    let (file, diagnostics) = crate::syntax::parse(&translation.text);
    let (model, more) = crate::model::resolve(&file);
    let errors = has_errors(&diagnostics) || has_errors(&more);
    let Some(mut model) = model.filter(|_| !errors) else {
        return true;
    };
    model.settings.max_modules = model.settings.max_modules.min(MODULES_TO_SEE_A_PLANT);
    let iterations = model.settings.iterations;
    let mut looked = None;
    for steps in STEPS_TO_SEE_A_PLANT.map(|s| s.min(iterations)) {
        if looked == Some(steps) {
            break;
        }
        looked = Some(steps);
        let options = crate::derive::DeriveOptions {
            steps,
            ..Default::default()
        };
        let Ok(derivation) = crate::derive::derive(&model, &options) else {
            return true;
        };
        let skeleton = crate::turtle::interpret(&model, derivation.turtle_string());
        if !(skeleton.segments.is_empty()
            && skeleton.polygons.is_empty()
            && skeleton.surfaces.is_empty()
            && skeleton.spheres.is_empty())
        {
            return false;
        }
    }
    true
}

/// The last part of a path.
fn base(name: &str) -> &str {
    name.rsplit(['/', '\\']).next().unwrap_or(name)
}

/// The derived string made readable by the importers: numbers as Meristem writes them, Python
/// booleans as 1 and 0, the parameters of a module that carries a Python object dropped.
#[derive(Debug, Default)]
struct Scanned {
    text: String,
    /// Each name written before a `(`, with its number of parameters (first seen).
    modules: Vec<(String, usize)>,
    /// The names whose parameters were dropped, with how many times.
    objects: Vec<(String, usize)>,
}

/// Scans the derived string; `drop_empty` writes `A()` as `A` (L-Py's importer wants no empty
/// parentheses; lpfg's writes every module with them).
fn scan(lstring: &str, drop_empty: bool) -> Scanned {
    let chars: Vec<char> = lstring.chars().collect();
    let mut s = Scanned::default();
    // Where the last module with parentheses ended: a name starts no earlier.
    let mut boundary = 0;
    let mut i = 0;
    while i < chars.len() {
        if chars[i] != '(' {
            s.text.push(chars[i]);
            i += 1;
            continue;
        }
        let Some(close) = PARENTHESES.closing_char(&chars, i) else {
            s.text.extend(&chars[i..]);
            break;
        };
        let inner: String = chars[i + 1..close].iter().collect();
        let name: String = {
            let tail: Vec<char> = s.text[boundary..]
                .chars()
                .rev()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            let start = s.text.len() - tail.len();
            // L-Py's `@L`, `~l`: the sign is part of the name.
            let sign = s.text[boundary..start]
                .chars()
                .next_back()
                .filter(|c| "@~".contains(*c));
            sign.into_iter().chain(tail.into_iter().rev()).collect()
        };
        let args: Option<Vec<String>> = if inner.trim().is_empty() {
            Some(Vec::new())
        } else {
            PARENTHESES
                .split(&inner, ',')
                .into_iter()
                .map(|(_, a)| parameter(a))
                .collect()
        };
        let count = match args {
            Some(args) if args.is_empty() => {
                if !drop_empty {
                    s.text.push_str("()");
                }
                0
            }
            Some(args) => {
                s.text.push_str(&format!("({})", args.join(",")));
                args.len()
            }
            None => {
                match s.objects.iter_mut().find(|(n, _)| *n == name) {
                    Some((_, k)) => *k += 1,
                    None => s.objects.push((name.clone(), 1)),
                }
                if !drop_empty {
                    s.text.push_str("()");
                }
                0
            }
        };
        if !name.is_empty() && !s.modules.iter().any(|(n, _)| *n == name) {
            s.modules.push((name, count));
        }
        boundary = s.text.len();
        i = close + 1;
    }
    s
}

/// One parameter as Meristem reads it, or `None` when it is not a number (a Python object).
fn parameter(text: &str) -> Option<String> {
    match text.trim() {
        "True" => Some("1".into()),
        "False" => Some("0".into()),
        t => t.parse::<f64>().ok().filter(|v| v.is_finite()).map(number),
    }
}

/// The L-Py text whose axiom is the derived string: the source's `module` declarations (so its
/// long names stay whole), the axiom, no step.
fn lpy_text(source: &str, lstring: &str) -> String {
    let mut text = String::new();
    for line in source.lines() {
        if line.trim_start().starts_with("module ") && !line.starts_with([' ', '\t']) {
            text.push_str(line.trim());
            text.push('\n');
        }
    }
    text.push_str(&format!("Axiom: {lstring}\nderivation length: 0\n"));
    text
}

/// The L+C text whose axiom is the derived string: the source's `module` declarations and one
/// for every other long name of the string (lpfg's own names apart), no step.
fn lpfg_text(source: &str, scanned: &Scanned) -> String {
    let mut text = String::from("#include <lpfgall.h>\nderivation length: 0;\n");
    let mut declared: Vec<String> = Vec::new();
    for line in source.lines().map(str::trim) {
        if let Some(rest) = line.strip_prefix("module ").filter(|_| line.ends_with(';')) {
            text.push_str(line);
            text.push('\n');
            for item in rest.trim_end_matches(';').split(';') {
                declared.push(item.split('(').next().unwrap_or("").trim().to_string());
            }
        }
    }
    for (name, count) in &scanned.modules {
        let known = declared.contains(name) || LPFG_PREDEFINED.contains(&name.as_str());
        let identifier = name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            && !name.starts_with(|c: char| c.is_ascii_digit());
        if name.len() > 1 && !known && identifier {
            let params = vec!["float"; *count].join(", ");
            text.push_str(&format!("module {name}({params});\n"));
            declared.push(name.clone());
        }
    }
    if declared.is_empty() {
        // An L+C file declares its modules; the importer tells L+C from cpfg by them.
        text.push_str("module DerivedString();\n");
    }
    text.push_str(&format!("Axiom: {};\n", scanned.text));
    text
}

#[cfg(test)]
mod tests;
