//! A cpfg function file (`.func`) or function set (`.fset`, lpfg's too): its control points,
//! read into a [`CurveFunction`] and written, when the L-system reads it, as the `#table` of the
//! samples the tool reads (or a `#curve`).

use super::{base, identifier, Body, CurveFunction, FunctionKind, Reader, View};
use crate::import::number;
use crate::maths;
use crate::model::{Curve, CurveKind};
use crate::vocabulary::DirectiveKind;

impl CurveFunction {
    /// The lines that define it: a comment, then a `#table` of the samples the tool reads when
    /// there are more than two, else a `#curve` of its control points; or a value's `#define`.
    pub fn lines(&self) -> Vec<String> {
        let (points, samples, tool) = match &self.body {
            Body::Lines(lines) => return lines.clone(),
            Body::Points {
                points,
                samples,
                tool,
            } => (points, *samples, tool),
        };
        let name = &self.name;
        let about = &self.about;
        let written: Vec<String> = points.iter().map(|v| number(*v)).collect();
        let written = written.join(" ");
        let curve = match Curve::new(CurveKind::Spline, points) {
            Ok(curve) if samples > 2 => curve,
            _ => {
                return vec![
                    format!("// {name}: {about}"),
                    format!("{} {name} {written}", DirectiveKind::Curve.written()),
                ]
            }
        };
        let samples = samples.min(1000);
        let values: Vec<String> = (0..samples)
            .map(|i| {
                let x = i as f64 / (samples - 1) as f64;
                format!("{} {}", number(x), short(curve.value(x)))
            })
            .collect();
        vec![
            format!("// {name}: {about}, control points {written}; {tool} reads it through {samples} samples, as here"),
            format!(
                "{} {name} {}",
                DirectiveKind::Table.written(),
                values.join(" ")
            ),
        ]
    }
}

/// A `.fset`: `funcgalleryver 1 1`, `items: n`, then n functions of the `.func` format.
pub(super) fn function_set(text: &str, file: &str, reader: Reader, view: &mut View) {
    let starts: Vec<usize> = text
        .match_indices("fver")
        .map(|(i, _)| i)
        .filter(|&i| i == 0 || text.as_bytes()[i - 1] == b'\n')
        .collect();
    for (k, &start) in starts.iter().enumerate() {
        let end = starts.get(k + 1).copied().unwrap_or(text.len());
        let f = function(&text[start..end], None, file, reader, view);
        view.functions.push(f);
    }
}

/// The most control points a function may have (vlab's function editor draws a few dozen).
const MAX_POINTS: usize = 100;

/// One function file (`fver 1 1` with `name:`, `samples:`, `points:`, points `x y [multiplicity]`;
/// or the old `range: … points: n`). cpfg reads a function through `samples` values of its spline
/// joined by straight lines when samples > 2 (a `#table` of those values), else the spline itself
/// (a `#curve`); lpfg always through 10 to 1,000 samples. The first of its lines is a comment.
pub(super) fn function(
    text: &str,
    samples: Option<usize>,
    file: &str,
    reader: Reader,
    view: &mut View,
) -> Option<CurveFunction> {
    let mut name = base(file).trim_end_matches(".func").to_string();
    let mut own_samples = None;
    let mut numbers = Vec::new();
    let mut reading = false;
    for line in text.lines() {
        let line = line.trim();
        if let Some(v) = line.strip_prefix("name:") {
            name = v.trim().to_string();
        } else if let Some(v) = line.strip_prefix("samples:") {
            own_samples = v.trim().parse::<usize>().ok();
        } else if line.starts_with("points:") {
            reading = true;
        } else if reading {
            let values: Vec<f64> = line
                .split_whitespace()
                .filter_map(|w| w.parse().ok())
                .collect();
            if let [x, y, rest @ ..] = values.as_slice() {
                let times = rest.first().map_or(1, |m| (*m as usize).clamp(1, 16));
                for _ in 0..times {
                    numbers.extend([*x, *y]);
                }
            }
            // Each value of the spline weighs every point: a function of 500,000 points took
            // 37 s to sample, and its comment quoted them all (issue 50, 6).
            if numbers.len() > 2 * MAX_POINTS {
                view.notes.push(format!(
                    "{file}: the function {name} has more than {MAX_POINTS} control points (with their multiplicities), more than Meristem reads: it is not translated"
                ));
                return None;
            }
        }
    }
    // fver 1.1 files carry their own sample count; the old format takes the view file's.
    let samples = if text.starts_with("fver") {
        own_samples
    } else {
        samples
    }
    .unwrap_or(0);
    let samples = match reader {
        Reader::Cpfg => samples,
        Reader::Lpfg => samples.clamp(10, 1000),
    };
    Curve::new(CurveKind::Spline, &numbers).ok()?;
    let source = name.clone();
    let name = identifier(&name, view);
    Some(CurveFunction {
        name,
        source,
        about: format!("the function of {file}"),
        body: Body::Points {
            points: numbers,
            samples,
            tool: reader.tool(),
        },
        kind: FunctionKind::Curve,
    })
}

/// A value with 7 significant digits (cpfg's floats).
pub(super) fn short(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return "0".into();
    }
    let digits = (6 - maths::log10(v.abs()).floor() as i32).clamp(0, 12) as usize;
    let text = format!("{v:.digits$}");
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    };
    if text == "-0" {
        "0".into()
    } else {
        text
    }
}
