//! Diffuse light by shadow propagation (Palubicki et al. 2009, section 4.1): every part in voxel
//! (i, j, k) adds `a × b^−q` to the voxels (i ± p, j − q, k ± p), p ≤ q, for q = 0 to `depth`: a
//! pyramid of shadow under it, (2q + 1)² voxels wide q layers down.
//!
//! Summing the pyramids part by part costs parts × depth³. Here the sum is computed exactly in
//! one pass from the top layer down, whatever the depth. A layer of a pyramid is a square, and a
//! square is the 2D running sum (along i, then k) of four signed impulses at its corners
//! (+ at (i − q, k − q), − at (i + q + 1, k − q) and at (i − q, k + q + 1), + at
//! (i + q + 1, k + q + 1)). Each corner moves one voxel diagonally outwards and fades by 1/b a
//! layer down, so each of the four corner planes is the one above moved by one voxel, times
//! 1/b, plus the layer's own parts, minus the parts `depth + 1` layers up (whose pyramids end).
//! The layer's shadow is the running sum of the four planes together. Cost: about ten passes
//! over each row of x, O(voxels) whatever the depth, and exact but for rounding (a relative
//! 1e-6; with b a power of 2 the fading and the ending cancel exactly; tested against the sum of
//! the pyramids). The grid's margin of `depth` voxels beside the
//! parts keeps every corner inside the grid until its pyramid ends.

/// The shape of one part's shadow.
#[derive(Clone, Copy, Debug)]
pub struct Pyramid {
    /// The shadow of one part on its own voxel (a).
    pub shadow: f32,
    /// How much it fades a layer down: 1/b.
    pub fade: f32,
    pub depth: usize,
}

/// The planes of the propagation, kept from one update to the next: the layer's parts, the parts
/// whose pyramids end there, the corners of the layer above and of this layer. Each is padded
/// with `depth + 2` zeros all round, so that every shifted read lands in it: one pass a corner,
/// no bounds.
#[derive(Debug, Default)]
pub struct ShadowPlanes {
    layer: Vec<f32>,
    ended: Vec<f32>,
    corners: [Vec<f32>; 4],
    next: [Vec<f32>; 4],
}

impl ShadowPlanes {
    /// Bytes of planes for a grid of `dims` and shadows `depth` deep (as a float: the grid may
    /// be too large for a size).
    pub fn bytes_for(dims: [f64; 3], depth: usize) -> f64 {
        let pad = 2.0 * (depth as f64 + 2.0);
        10.0 * (dims[0] + pad) * (dims[2] + pad) * std::mem::size_of::<f32>() as f64
    }

    pub fn bytes(&self) -> usize {
        let all = [&self.layer, &self.ended]
            .into_iter()
            .chain(&self.corners)
            .chain(&self.next);
        all.map(|p| p.capacity() * std::mem::size_of::<f32>()).sum()
    }

    fn reset(&mut self, plane: usize) {
        let all = [&mut self.layer, &mut self.ended].into_iter();
        for p in all.chain(&mut self.corners).chain(&mut self.next) {
            p.clear();
            p.resize(plane, 0.0);
        }
    }
}

/// A padded plane: `width` values a row, the grid's row k at row `k + pad`, column i at `i + pad`.
#[derive(Clone, Copy)]
struct Padded {
    width: usize,
    pad: usize,
    nx: usize,
}

impl Padded {
    /// Where the grid's row `k` shifted by (si, sk) starts: the row that lands on row k.
    fn start(&self, k: usize, [si, sk]: [isize; 2]) -> usize {
        let row = (k + self.pad) as isize - sk;
        (row * self.width as isize + self.pad as isize - si) as usize
    }

    /// Copies the grid's layer `j` into the plane's inside.
    fn gather(&self, parts: &[f32], dims: [usize; 3], j: usize, plane: &mut [f32]) {
        for k in 0..dims[2] {
            let from = self.nx * (j + dims[1] * k);
            let at = self.start(k, [0, 0]);
            plane[at..at + self.nx].copy_from_slice(&parts[from..from + self.nx]);
        }
    }
}

/// Writes into `shadow` the shadow of every voxel of a grid of `dims` whose parts per voxel are
/// `parts` (the sum of the pyramids of all parts). Row by row (a row of x at one y and z), each
/// row's four corners in one pass each, then their sum and the shadow's row.
pub fn propagate(
    parts: &[f32],
    dims: [usize; 3],
    pyramid: Pyramid,
    shadow: &mut [f32],
    planes: &mut ShadowPlanes,
) {
    let [nx, ny, nz] = dims;
    let pad = pyramid.depth + 2;
    let padded = Padded {
        width: nx + 2 * pad,
        pad,
        nx,
    };
    planes.reset(padded.width * (nz + 2 * pad));
    let far = pyramid.depth as isize + 1;
    let ended_weight = -pyramid.shadow * pyramid.fade.powi(far as i32);
    for j in (0..ny).rev() {
        padded.gather(parts, dims, j, &mut planes.layer);
        let ended = j + pyramid.depth + 1 < ny;
        if ended {
            padded.gather(parts, dims, j + pyramid.depth + 1, &mut planes.ended);
        }
        for k in 0..nz {
            for c in 0..4 {
                // Corner c: (oi, ok) = 0 for the low side (moving to −1), 1 for the high side (+1).
                let (oi, ok) = ((c & 1) as isize, (c >> 1) as isize);
                let (di, dk) = (2 * oi - 1, 2 * ok - 1);
                let at = padded.start(k, [0, 0]);
                let next = &mut planes.next[c][at..at + nx];
                let own = &planes.layer[padded.start(k, [oi, ok])..][..nx];
                let above = &planes.corners[c][padded.start(k, [di, dk])..][..nx];
                let (a, fade) = (pyramid.shadow, pyramid.fade);
                for ((x, &o), &b) in next.iter_mut().zip(own).zip(above) {
                    *x = a * o + fade * b;
                }
                if ended {
                    let shift = [oi + far * di, ok + far * dk];
                    let gone = &planes.ended[padded.start(k, shift)..][..nx];
                    for (x, &g) in next.iter_mut().zip(gone) {
                        *x += ended_weight * g;
                    }
                }
            }
            let at = padded.start(k, [0, 0]);
            let rows = planes.next.each_ref().map(|c| &c[at..at + nx]);
            let row_of = |k: usize| nx * (j + ny * k);
            sum_row(rows, shadow, row_of(k), (k > 0).then(|| row_of(k - 1)));
        }
        std::mem::swap(&mut planes.corners, &mut planes.next);
    }
}

/// A row of the layer's shadow: the corner planes' rows with their signs, summed along the row,
/// plus the row before (at `before`): the corners summed along i and along k.
fn sum_row(corners: [&[f32]; 4], shadow: &mut [f32], at: usize, before: Option<usize>) {
    let [low, high_i, high_k, high] = corners;
    let nx = low.len();
    let (earlier, rest) = shadow.split_at_mut(at);
    let row = &mut rest[..nx];
    let mut running = 0.0;
    for i in 0..nx {
        running += (low[i] - high_i[i]) - (high_k[i] - high[i]);
        row[i] = running;
    }
    if let Some(b) = before {
        for (x, &y) in row.iter_mut().zip(&earlier[b..b + nx]) {
            *x += y;
        }
    }
}

/// The same shadow summed pyramid by pyramid, part by part: what [`propagate`] must equal (tests).
#[cfg(test)]
pub fn pyramids(parts: &[f32], dims: [usize; 3], pyramid: Pyramid) -> Vec<f32> {
    let [nx, ny, nz] = dims;
    let mut shadow = vec![0.0f64; parts.len()];
    let index = |i: usize, j: usize, k: usize| i + nx * (j + ny * k);
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let w = f64::from(parts[index(i, j, k)]);
                if w == 0.0 {
                    continue;
                }
                for q in 0..=pyramid.depth.min(j) {
                    let s = w * f64::from(pyramid.shadow) * f64::from(pyramid.fade).powi(q as i32);
                    for kk in k.saturating_sub(q)..=(k + q).min(nz - 1) {
                        for ii in i.saturating_sub(q)..=(i + q).min(nx - 1) {
                            shadow[index(ii, j - q, kk)] += s;
                        }
                    }
                }
            }
        }
    }
    shadow.into_iter().map(|s| s as f32).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small grid with parts scattered at least `depth` voxels from its sides (as the light
    /// grid's margins keep them), several in some voxels.
    fn scattered(dims: [usize; 3], depth: usize) -> Vec<f32> {
        let [nx, ny, nz] = dims;
        let mut parts = vec![0.0; nx * ny * nz];
        let mut state = 12345u32;
        for _ in 0..40 {
            let mut next = |n: usize| {
                state = state.wrapping_mul(1_103_515_245).wrapping_add(12345);
                (state >> 16) as usize % n
            };
            let i = depth + next(nx - 2 * depth);
            let j = next(ny);
            let k = depth + next(nz - 2 * depth);
            parts[i + nx * (j + ny * k)] += 1.0 + next(3) as f32;
        }
        parts
    }

    fn check(dims: [usize; 3], pyramid: Pyramid) {
        let parts = scattered(dims, pyramid.depth);
        let mut shadow = vec![0.0; parts.len()];
        propagate(
            &parts,
            dims,
            pyramid,
            &mut shadow,
            &mut ShadowPlanes::default(),
        );
        let expected = pyramids(&parts, dims, pyramid);
        let largest = expected.iter().fold(0.0f32, |m, &x| m.max(x));
        assert!(largest > 1.0, "the example casts shadows");
        for (v, (&got, &want)) in shadow.iter().zip(&expected).enumerate() {
            assert!(
                (got - want).abs() <= 1e-5 * largest,
                "voxel {v}: {got} != {want}"
            );
        }
    }

    #[test]
    fn the_propagated_shadow_is_the_sum_of_the_pyramids() {
        let halving = Pyramid {
            shadow: 1.0,
            fade: 0.5,
            depth: 3,
        };
        check([11, 9, 12], halving);
        // A fade that is no power of 2; a depth deeper than the grid is high.
        check(
            [13, 6, 14],
            Pyramid {
                shadow: 0.7,
                fade: 1.0 / 3.0,
                depth: 4,
            },
        );
        check(
            [17, 5, 16],
            Pyramid {
                shadow: 1.0,
                fade: 0.8,
                depth: 7,
            },
        );
        check(
            [9, 12, 9],
            Pyramid {
                shadow: 2.0,
                fade: 1.0,
                depth: 2,
            },
        );
    }
}
