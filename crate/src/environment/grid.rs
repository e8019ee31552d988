//! [`SegmentGrid`]: a uniform hash grid of segments (a point is a segment of length 0), for the
//! questions "which segments come within `cell` of this point" that `space` and `attractors` ask.
//!
//! Each segment is cut into pieces no longer than a cell and filed under every cell a piece's
//! bounding box touches (at most 8 a piece), so a segment that comes within one cell of a point
//! is filed in one of the 27 cells around the point's own. The cells are kept as one sorted list
//! of (cell, segment) entries: no hash map, the same order on every run.

use super::{Exceeded, MAX_ENVIRONMENT_BYTES};

/// One entry: a cell's integer coordinates and a segment's index.
type Entry = ([i64; 3], u32);

/// Segments filed by the cells they pass through.
#[derive(Clone, Debug, Default)]
pub struct SegmentGrid {
    cell: f64,
    /// Sorted by cell, then by segment; no repeats.
    entries: Vec<Entry>,
}

/// The cell of `p` for cells of edge `cell` (saturating far away: a cell there holds more, and
/// the distances the callers measure stay exact).
fn cell_of(p: [f64; 3], cell: f64) -> [i64; 3] {
    p.map(|x| (x / cell).floor() as i64)
}

/// How many pieces of length at most `cell` a segment from `a` to `b` is cut into.
fn pieces(a: [f64; 3], b: [f64; 3], cell: f64) -> f64 {
    let length = distance(a, b);
    (length / cell).ceil().max(1.0)
}

impl SegmentGrid {
    /// Files `segments` (each `[from, to]`) in cells of edge `cell` (> 0), or says what it would
    /// take when that is more than `budget` bytes (`what` names the grid in the message).
    pub fn build(
        segments: &[[[f64; 3]; 2]],
        cell: f64,
        budget: usize,
        what: &str,
    ) -> Result<SegmentGrid, Exceeded> {
        let budget = budget.min(MAX_ENVIRONMENT_BYTES);
        let size = std::mem::size_of::<Entry>();
        let exceeded = |bytes: f64| Exceeded {
            what: format!("{what} of {} parts in cells of {cell}", segments.len()),
            bytes: bytes.min(usize::MAX as f64) as usize,
        };
        let most: f64 = segments
            .iter()
            .map(|&[a, b]| 8.0 * pieces(a, b, cell))
            .sum();
        if most * size as f64 > budget as f64 {
            return Err(exceeded(most * size as f64));
        }
        let mut entries = Vec::with_capacity(most as usize);
        for (index, &[a, b]) in segments.iter().enumerate() {
            // Rounding far from the origin can put a piece in 3 cells of an axis: held to the
            // budget all the same.
            if entries.len() * size > budget {
                return Err(exceeded((entries.len() * size) as f64));
            }
            let n = pieces(a, b, cell) as usize;
            for k in 0..n {
                let p = lerp(a, b, k as f64 / n as f64);
                let q = lerp(a, b, (k + 1) as f64 / n as f64);
                let (lo, hi) = (cell_of(min(p, q), cell), cell_of(max(p, q), cell));
                for i in lo[0]..=hi[0] {
                    for j in lo[1]..=hi[1] {
                        for l in lo[2]..=hi[2] {
                            entries.push(([i, j, l], index as u32));
                        }
                    }
                }
            }
        }
        entries.sort_unstable();
        entries.dedup();
        Ok(SegmentGrid { cell, entries })
    }

    /// Points (segments of length 0) filed in cells of edge `cell` (> 0): one entry each, no
    /// more than the points themselves take, so no budget.
    pub fn of_points(points: &[[[f64; 3]; 2]], cell: f64) -> SegmentGrid {
        let mut entries: Vec<Entry> = points
            .iter()
            .enumerate()
            .map(|(i, p)| (cell_of(p[0], cell), i as u32))
            .collect();
        entries.sort_unstable();
        SegmentGrid { cell, entries }
    }

    /// The indices of the segments filed in the 27 cells around `p` (each once, ascending):
    /// every segment that comes within one cell's edge of `p` is among them.
    pub fn near(&self, p: [f64; 3], out: &mut Vec<u32>) {
        out.clear();
        if self.entries.is_empty() {
            return;
        }
        let c = cell_of(p, self.cell);
        for i in [-1, 0, 1] {
            for j in [-1, 0, 1] {
                for l in [-1, 0, 1] {
                    let key = [
                        c[0].saturating_add(i),
                        c[1].saturating_add(j),
                        c[2].saturating_add(l),
                    ];
                    let start = self.entries.partition_point(|e| e.0 < key);
                    let end = start + self.entries[start..].partition_point(|e| e.0 == key);
                    out.extend(self.entries[start..end].iter().map(|e| e.1));
                }
            }
        }
        out.sort_unstable();
        out.dedup();
    }

    /// Bytes it holds.
    pub fn bytes(&self) -> usize {
        self.entries.capacity() * std::mem::size_of::<Entry>()
    }
}

/// The point of the segment `a`–`b` nearest to `p`.
pub fn nearest_on_segment(p: [f64; 3], a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    let ab = sub(b, a);
    let length2 = dot(ab, ab);
    if length2 == 0.0 || !length2.is_finite() {
        return a;
    }
    let t = (dot(sub(p, a), ab) / length2).clamp(0.0, 1.0);
    lerp(a, b, t)
}

pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    let d = sub(a, b);
    dot(d, d).sqrt()
}

/// `v` scaled to length 1, or (0, 0, 0) when it has no direction.
pub fn unit(v: [f64; 3]) -> [f64; 3] {
    let length = dot(v, v).sqrt();
    if length > 0.0 && length.is_finite() {
        v.map(|x| x / length)
    } else {
        [0.0; 3]
    }
}

fn lerp(a: [f64; 3], b: [f64; 3], t: f64) -> [f64; 3] {
    [
        a[0] + (b[0] - a[0]) * t,
        a[1] + (b[1] - a[1]) * t,
        a[2] + (b[2] - a[2]) * t,
    ]
}

fn min(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0].min(b[0]), a[1].min(b[1]), a[2].min(b[2])]
}

fn max(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0].max(b[0]), a[1].max(b[1]), a[2].max(b[2])]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_segment_is_found_along_its_whole_length() {
        let grid =
            SegmentGrid::build(&[[[0.0; 3], [10.0, 10.0, 0.0]]], 1.0, 1 << 20, "a grid").unwrap();
        let mut out = Vec::new();
        for k in 0..=20 {
            let t = k as f64 / 2.0;
            grid.near([t, t, 0.5], &mut out);
            assert_eq!(out, vec![0], "at {t}");
        }
        grid.near([2.0, 8.0, 0.0], &mut out);
        assert!(out.is_empty(), "4 cells away");
    }

    #[test]
    fn a_grid_past_its_budget_is_refused_before_it_is_made() {
        let e = SegmentGrid::build(&[[[0.0; 3], [1e6, 0.0, 0.0]]], 1e-3, 1 << 20, "a grid")
            .unwrap_err();
        assert!(e.bytes > 1 << 20);
        assert!(e.what.starts_with("a grid of 1 parts"), "{}", e.what);
    }

    #[test]
    fn far_points_saturate_without_overflow() {
        let grid = SegmentGrid::build(&[[[1e30, -1e30, 0.0]; 2]], 1e-9, 1 << 20, "a grid").unwrap();
        let mut out = Vec::new();
        grid.near([1e30, -1e30, 0.0], &mut out);
        assert_eq!(out, vec![0]);
    }
}
