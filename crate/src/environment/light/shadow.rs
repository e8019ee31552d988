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
//! The layer's shadow is the running sum of the four planes together. Cost: about 20 passes over
//! a plane a layer, O(voxels), and exact but for rounding (a relative 1e-6; with b a power of 2
//! the fading and the ending cancel exactly). The grid's margin of `depth` voxels beside the
//! parts keeps every corner inside the grid until its pyramid ends.

use super::grid::{shifted_add, PlaneOf};

/// The shape of one part's shadow.
#[derive(Clone, Copy, Debug)]
pub struct Pyramid {
    /// The shadow of one part on its own voxel (a).
    pub shadow: f32,
    /// How much it fades a layer down: 1/b.
    pub fade: f32,
    pub depth: usize,
}

/// The planes the propagation works in, kept from one update to the next.
#[derive(Debug, Default)]
pub struct ShadowPlanes {
    layer: Vec<f32>,
    ended: Vec<f32>,
    sum: Vec<f32>,
    corners: [Vec<f32>; 4],
    next: [Vec<f32>; 4],
}

impl ShadowPlanes {
    /// Bytes of planes for a grid of `dims`.
    pub fn bytes_for(dims: [usize; 3]) -> usize {
        11 * dims[0] * dims[2] * std::mem::size_of::<f32>()
    }

    pub fn bytes(&self) -> usize {
        let planes = [&self.layer, &self.ended, &self.sum];
        let all = planes.into_iter().chain(&self.corners).chain(&self.next);
        all.map(|p| p.capacity() * std::mem::size_of::<f32>()).sum()
    }

    fn reset(&mut self, plane: usize) {
        let all = [&mut self.layer, &mut self.ended, &mut self.sum];
        for p in all
            .into_iter()
            .chain(&mut self.corners)
            .chain(&mut self.next)
        {
            p.clear();
            p.resize(plane, 0.0);
        }
    }
}

/// Writes into `shadow` the shadow of every voxel of a grid of `dims` whose parts per voxel are
/// `parts` (the sum of the pyramids of all parts).
pub fn propagate(
    parts: &[f32],
    dims: [usize; 3],
    pyramid: Pyramid,
    shadow: &mut [f32],
    planes: &mut ShadowPlanes,
) {
    let [nx, ny, nz] = dims;
    planes.reset(nx * nz);
    let depth = pyramid.depth;
    let a = pyramid.shadow;
    let ended_weight = -a * pyramid.fade.powi(depth as i32 + 1);
    for j in (0..ny).rev() {
        PlaneOf::new(dims, 1, j).gather(parts, &mut planes.layer);
        let ended = j + depth + 1 < ny;
        if ended {
            PlaneOf::new(dims, 1, j + depth + 1).gather(parts, &mut planes.ended);
        }
        for c in 0..4 {
            // Corner c: (oi, ok) = 0 for the low side (moving to −1), 1 for the high side (+1).
            let (oi, ok) = ((c & 1) as isize, (c >> 1) as isize);
            let (di, dk) = (2 * oi - 1, 2 * ok - 1);
            let next = &mut planes.next[c];
            next.fill(0.0);
            shifted_add(next, &planes.layer, nx, a, [oi, ok]);
            shifted_add(next, &planes.corners[c], nx, pyramid.fade, [di, dk]);
            if ended {
                let far = depth as isize + 1;
                shifted_add(
                    next,
                    &planes.ended,
                    nx,
                    ended_weight,
                    [oi + far * di, ok + far * dk],
                );
            }
        }
        std::mem::swap(&mut planes.corners, &mut planes.next);
        corners_to_shadow(&planes.corners, nx, &mut planes.sum);
        PlaneOf::new(dims, 1, j).scatter(&planes.sum, shadow, |s| s);
    }
}

/// The layer's shadow: the corner planes with their signs, summed along i and then along k.
fn corners_to_shadow(corners: &[Vec<f32>; 4], nx: usize, sum: &mut [f32]) {
    let [low, high_i, high_k, high] = corners;
    for (s, (((a, b), c), d)) in sum
        .iter_mut()
        .zip(low.iter().zip(high_i).zip(high_k).zip(high))
    {
        *s = (a - b) - (c - d);
    }
    for row in sum.chunks_exact_mut(nx) {
        let mut running = 0.0;
        for x in row {
            running += *x;
            *x = running;
        }
    }
    for k in 1..sum.len() / nx.max(1) {
        let (before, rest) = sum.split_at_mut(k * nx);
        for (x, &y) in rest[..nx].iter_mut().zip(&before[(k - 1) * nx..]) {
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
