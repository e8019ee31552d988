//! cpfg's contours (the view file's `curve: file.con` lines, vlab's cuspy files), which an
//! L-system reads with `curveX(id, t)`, `curveY(id, t)`, `curveZ(id, t)` and `curveGAL(id)`
//! (cpfg manual 5.5; `curveXYZc.cpp`): the point at the fraction t of the contour's length
//! (t clamped to 0…1), and the length.
//!
//! A contour file gives control points `x y z multiplicity` (`type: bspline`, the default): a
//! uniform cubic B-spline over the points, each repeated as often as its multiplicity (three
//! times at the ends: the curve starts and ends at them). Meristem has no curves of
//! several coordinates, so each coordinate becomes a `#table` of [`SAMPLES`] values at equal
//! steps of length along the curve (measured on [`FINE`] points of the spline), and the length a
//! number.

use crate::import::number;
use crate::vocabulary::DirectiveKind;

/// Values of each coordinate's table, and points the length is measured on.
const SAMPLES: usize = 101;
const FINE: usize = 2000;

/// One contour in Meristem's terms.
#[derive(Clone, Debug)]
pub(in crate::import) struct Contour {
    /// The names of its coordinates' tables (x, y, z).
    pub names: [String; 3],
    /// Its length (`curveGAL`).
    pub length: f64,
    /// The lines that declare the tables.
    pub lines: Vec<String>,
}

/// The control points of a contour file, each repeated by its multiplicity; `None` when it
/// has fewer than two or is not a B-spline.
fn control_points(text: &str) -> Option<Vec<[f64; 3]>> {
    let mut points = Vec::new();
    let mut reading = false;
    for line in text.lines() {
        let line = line.trim();
        if let Some(kind) = line.strip_prefix("type:") {
            if !kind.trim().eq_ignore_ascii_case("bspline") {
                return None;
            }
            reading = true;
            continue;
        }
        if line.starts_with("points:") {
            continue;
        }
        let values: Vec<f64> = line
            .split_whitespace()
            .map_while(|w| w.parse().ok())
            .collect();
        // The points follow the header (`type:`, or the last `name: value` line).
        if line.contains(':') {
            continue;
        }
        if let [x, y, rest @ ..] = values.as_slice() {
            let z = rest.first().copied().unwrap_or(0.0);
            let times = rest.get(1).map_or(1, |m| (*m as usize).clamp(1, 16));
            for _ in 0..times {
                points.push([*x, *y, z]);
            }
            reading = true;
        }
    }
    (reading && points.len() >= 2 && points.len() <= 10_000).then_some(points)
}

/// The uniform cubic B-spline over `p` at `u` from 0 to 1 (fewer than four points: the polyline).
fn spline(p: &[[f64; 3]], u: f64) -> [f64; 3] {
    if p.len() < 4 {
        let span = u.clamp(0.0, 1.0) * (p.len() - 1) as f64;
        let i = (span.floor() as usize).min(p.len() - 2);
        let f = span - i as f64;
        return [0, 1, 2].map(|k| p[i][k] + (p[i + 1][k] - p[i][k]) * f);
    }
    let pieces = p.len() - 3;
    let span = u.clamp(0.0, 1.0) * pieces as f64;
    let i = (span.floor() as usize).min(pieces - 1);
    let t = span - i as f64;
    let b = [
        (1.0 - t).powi(3) / 6.0,
        (3.0 * t.powi(3) - 6.0 * t * t + 4.0) / 6.0,
        (-3.0 * t.powi(3) + 3.0 * t * t + 3.0 * t + 1.0) / 6.0,
        t.powi(3) / 6.0,
    ];
    [0, 1, 2].map(|k| (0..4).map(|j| b[j] * p[i + j][k]).sum())
}

/// Reads contour `id` (from 1) of `file`; the names start with `base`.
pub(in crate::import) fn read(text: &str, base: &str) -> Option<Contour> {
    let p = control_points(text)?;
    let fine: Vec<[f64; 3]> = (0..FINE)
        .map(|i| spline(&p, i as f64 / (FINE - 1) as f64))
        .collect();
    let mut along = vec![0.0];
    for w in fine.windows(2) {
        let d = ((w[1][0] - w[0][0]).powi(2)
            + (w[1][1] - w[0][1]).powi(2)
            + (w[1][2] - w[0][2]).powi(2))
        .sqrt();
        along.push(along.last().copied().unwrap_or(0.0) + d);
    }
    let length = along.last().copied().unwrap_or(0.0);
    if !(length.is_finite() && length > 0.0) {
        return None;
    }
    // The point at each fraction of the length: found on the fine points, interpolated.
    let mut at = Vec::with_capacity(SAMPLES);
    let mut k = 0;
    for s in 0..SAMPLES {
        let target = length * s as f64 / (SAMPLES - 1) as f64;
        while k + 2 < along.len() && along[k + 1] < target {
            k += 1;
        }
        let span = along[k + 1] - along[k];
        let f = if span > 0.0 {
            ((target - along[k]) / span).clamp(0.0, 1.0)
        } else {
            0.0
        };
        at.push([0, 1, 2].map(|c| fine[k][c] + (fine[k + 1][c] - fine[k][c]) * f));
    }
    let names = ["x", "y", "z"].map(|c| format!("{base}_{c}"));
    let mut lines = vec![format!(
        "// {base}: the contour's x, y and z at each fraction of its length ({}), {SAMPLES} samples joined by straight lines",
        number(length)
    )];
    for (c, name) in names.iter().enumerate() {
        let values: Vec<String> = at
            .iter()
            .enumerate()
            .map(|(s, point)| {
                let t = s as f64 / (SAMPLES - 1) as f64;
                format!("{} {}", number(t), number((point[c] * 1e6).round() / 1e6))
            })
            .collect();
        lines.push(format!(
            "{} {name} {}",
            DirectiveKind::Table.written(),
            values.join(" ")
        ));
    }
    Some(Contour {
        names,
        length,
        lines,
    })
}

#[cfg(test)]
mod tests {
    use super::read;

    #[test]
    fn a_straight_contour_is_read_by_its_length() {
        // Four points on a line of length 3, the ends of multiplicity 3 (as cuspy writes them).
        let text = "points: 4\nrange: 0.0 1.0\ndimension: 4\ntype: bspline\n\
            0 0 0 3\n1 0 0 1\n2 0 0 1\n3 0 0 3\n";
        let c = read(text, "profile").unwrap();
        assert!((c.length - 3.0).abs() < 1e-6, "{}", c.length);
        assert_eq!(c.names[0], "profile_x");
        // At half the length, x is 1.5: equal steps of length, not of the spline's parameter.
        let x = &c.lines[1];
        assert!(x.contains(" 0.5 1.5 "), "{x}");
        assert!(x.ends_with(" 1 3"), "{x}");
    }

    #[test]
    fn a_file_that_is_no_bspline_is_not_read() {
        assert!(read("type: bezier\n0 0 0 1\n1 1 0 1\n", "c").is_none());
        assert!(read("", "c").is_none());
    }
}
