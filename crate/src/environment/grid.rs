//! [`SegmentGrid`]: a uniform hash grid of segments (a point is a segment of length 0), for the
//! questions "which segments come within `reach` of this point" that `space` and `attractors`
//! ask.
//!
//! Each segment is cut into pieces no longer than `reach` and each piece is filed once, under the
//! cell of its middle; cells are 1.5 × `reach` wide. A point of a piece is within `reach` / 2 of
//! its middle, so a segment that comes within `reach` of a point has a piece whose middle is
//! within 1.5 × `reach`, in one of the 27 cells around the point's own. A cell's segments are one
//! run of a list sorted by cell, found by a hash map with a fixed hash (its order never shows:
//! runs are read by key, the 27 cells in one order).

use super::{Exceeded, MAX_ENVIRONMENT_BYTES};
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// FxHash's step (rustc's hasher): a cell's three words mixed by a rotation, a xor and a
/// multiplication, the same on every run and several times faster than the default hasher.
#[derive(Clone, Copy, Debug, Default)]
struct CellHasher(u64);

impl CellHasher {
    fn add(&mut self, word: u64) {
        self.0 = (self.0.rotate_left(5) ^ word).wrapping_mul(0x517c_c1b7_2722_0a95);
    }
}

impl Hasher for CellHasher {
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            self.add(u64::from_le_bytes(word));
        }
    }

    fn write_i64(&mut self, x: i64) {
        self.add(x as u64);
    }

    fn write_usize(&mut self, x: usize) {
        self.add(x as u64);
    }

    fn finish(&self) -> u64 {
        self.0
    }
}

/// What one query found (each segment once, in the order of the cells), and the marks that keep
/// a segment of several pieces from being found twice: one `Near` serves many queries.
#[derive(Clone, Debug, Default)]
pub struct Near {
    pub found: Vec<u32>,
    /// The entries of the cells read, over all its queries (a segment of several pieces once a
    /// piece): the work they cost.
    pub scanned: u64,
    marks: Vec<u32>,
    round: u32,
}

/// Cells are this many times the reach wide.
const CELL_PER_REACH: f64 = 1.5;

/// Bytes a piece may take while the grid is built (its cell and index, sorted) and after (its
/// index, and at most one cell of the map with its run).
const BYTES_PER_PIECE: usize = 32 + 4 + 48;

/// Segments filed by the cells of their pieces.
#[derive(Clone, Debug, Default)]
pub struct SegmentGrid {
    cell: f64,
    /// Each cell's run of `indices`.
    cells: HashMap<[i64; 3], (u32, u32), BuildHasherDefault<CellHasher>>,
    /// How many segments it files (one above the largest index).
    segments: usize,
    /// Segment indices, cell after cell, ascending within a cell.
    indices: Vec<u32>,
}

/// The cell of `p` for cells of edge `cell` (saturating far away: a cell there holds more, and
/// the distances the callers measure stay exact).
fn cell_of(p: [f64; 3], cell: f64) -> [i64; 3] {
    p.map(|x| (x / cell).floor() as i64)
}

/// How many pieces of length at most `reach` a segment from `a` to `b` is cut into.
fn pieces(a: [f64; 3], b: [f64; 3], reach: f64) -> f64 {
    let length = distance(a, b);
    (length / reach).ceil().max(1.0)
}

impl SegmentGrid {
    /// Files `segments` (each `[from, to]`) to be found within `reach` (> 0), or says what it
    /// would take when that is more than `budget` bytes (`what` names the grid in the message).
    pub fn build(
        segments: &[[[f64; 3]; 2]],
        reach: f64,
        budget: usize,
        what: &str,
    ) -> Result<SegmentGrid, Exceeded> {
        let budget = budget.min(MAX_ENVIRONMENT_BYTES);
        let count: f64 = segments.iter().map(|&[a, b]| pieces(a, b, reach)).sum();
        let bytes = count * BYTES_PER_PIECE as f64;
        if bytes > budget as f64 {
            return Err(Exceeded {
                what: format!(
                    "{what} of {} parts within {}",
                    segments.len(),
                    super::settings::shown(reach)
                ),
                bytes: bytes.min(usize::MAX as f64) as usize,
            });
        }
        let cell = CELL_PER_REACH * reach;
        let mut entries: Vec<([i64; 3], u32)> = Vec::with_capacity(count as usize);
        for (index, &[a, b]) in segments.iter().enumerate() {
            let n = pieces(a, b, reach) as usize;
            for k in 0..n {
                let middle = lerp(a, b, (k as f64 + 0.5) / n as f64);
                entries.push((cell_of(middle, cell), index as u32));
            }
        }
        Ok(SegmentGrid::of_entries(entries, cell, segments.len()))
    }

    /// Points (segments of length 0) to be found within `reach` (> 0): one entry each, no more
    /// than the points themselves take, so no budget.
    pub fn of_points(points: &[[[f64; 3]; 2]], reach: f64) -> SegmentGrid {
        let cell = CELL_PER_REACH * reach;
        let entries = points
            .iter()
            .enumerate()
            .map(|(i, p)| (cell_of(p[0], cell), i as u32))
            .collect();
        SegmentGrid::of_entries(entries, cell, points.len())
    }

    /// The grid of (cell, index) entries.
    fn of_entries(mut entries: Vec<([i64; 3], u32)>, cell: f64, segments: usize) -> SegmentGrid {
        entries.sort_unstable();
        entries.dedup();
        let mut cells = HashMap::default();
        let mut start = 0;
        for (k, e) in entries.iter().enumerate() {
            if entries.get(k + 1).is_none_or(|next| next.0 != e.0) {
                cells.insert(e.0, (start as u32, k as u32 + 1));
                start = k + 1;
            }
        }
        let indices = entries.into_iter().map(|e| e.1).collect();
        SegmentGrid {
            cell,
            cells,
            segments,
            indices,
        }
    }

    /// The segments filed in the 27 cells around `p`, into `near.found` (each once, in the order
    /// of the cells, ascending within one): every segment that comes within the grid's reach of
    /// `p` is among them.
    pub fn near(&self, p: [f64; 3], near: &mut Near) {
        near.found.clear();
        if self.indices.is_empty() {
            return;
        }
        if near.marks.len() < self.segments {
            near.marks.resize(self.segments, 0);
        }
        near.round = near.round.wrapping_add(1);
        if near.round == 0 {
            near.marks.fill(0);
            near.round = 1;
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
                    let Some(&(start, end)) = self.cells.get(&key) else {
                        continue;
                    };
                    near.scanned += u64::from(end - start);
                    for &index in &self.indices[start as usize..end as usize] {
                        let mark = &mut near.marks[index as usize];
                        if *mark != near.round {
                            *mark = near.round;
                            near.found.push(index);
                        }
                    }
                }
            }
        }
    }

    /// Bytes it holds.
    pub fn bytes(&self) -> usize {
        self.indices.capacity() * 4 + self.cells.capacity() * (24 + 8 + 8) + 4 * self.segments
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_segment_is_found_along_its_whole_length() {
        let grid =
            SegmentGrid::build(&[[[0.0; 3], [10.0, 10.0, 0.0]]], 1.0, 1 << 20, "a grid").unwrap();
        let mut near = Near::default();
        for k in 0..=20 {
            let t = k as f64 / 2.0;
            grid.near([t, t, 0.5], &mut near);
            assert_eq!(near.found, vec![0], "at {t}");
        }
        grid.near([2.0, 8.0, 0.0], &mut near);
        assert!(near.found.is_empty(), "4.2 away");
    }

    #[test]
    fn every_segment_within_reach_is_found() {
        use crate::derive::Generator;
        use rand::{RngExt, SeedableRng};
        let mut rng = Generator::seed_from_u64(47);
        let mut draw = |scale: f64| [0; 3].map(|_| scale * (2.0 * rng.random::<f64>() - 1.0));
        let segments: Vec<[[f64; 3]; 2]> = (0..300)
            .map(|i| {
                let a = draw(5.0);
                let d = draw([0.0, 0.2, 1.0, 4.0][i % 4]);
                [a, [a[0] + d[0], a[1] + d[1], a[2] + d[2]]]
            })
            .collect();
        let reach = 0.7;
        let grid = SegmentGrid::build(&segments, reach, 1 << 24, "a grid").unwrap();
        let mut near = Near::default();
        let mut found = 0;
        for _ in 0..300 {
            let p = draw(5.0);
            grid.near(p, &mut near);
            let mut once = near.found.clone();
            once.sort_unstable();
            once.dedup();
            assert_eq!(once.len(), near.found.len(), "each segment once");
            for (i, &[a, b]) in segments.iter().enumerate() {
                if distance(nearest_on_segment(p, a, b), p) <= reach {
                    found += 1;
                    assert!(near.found.contains(&(i as u32)), "segment {i} near {p:?}");
                }
            }
        }
        assert!(found > 100, "{found}");
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
        let mut near = Near::default();
        grid.near([1e30, -1e30, 0.0], &mut near);
        assert_eq!(near.found, vec![0]);
    }
}
