//! Direct light: the sun's beam through the grid, by a sweep of planes. The grid is swept
//! across the axis along which the sun's direction is longest (y for a high sun, x or z for a
//! low one), from the sun's side: a voxel's count of parts on the beam is its own parts plus the
//! count of the point one plane towards the sun, read from the plane before by bilinear
//! interpolation. That point is at most one voxel aside (the axis is the longest), so the beam
//! samples every plane it crosses and misses no wall. The weights are the same for the whole
//! plane: four shifted adds a plane, row by row, O(voxels). Interpolation blurs a shadow's edge
//! by about a voxel per few planes (numerical diffusion); a voxel's count is exact along the
//! grid's axes and diagonals.
//!
//! Beer–Lambert: one part stops `absorb` of the beam, so n parts let through (1 − absorb)^n;
//! the count is kept and turned into light only where a probe or the studio reads it.

use super::grid::{shifted_add, PlaneOf};
use crate::maths;

/// The planes of the sweep, kept from one update to the next.
#[derive(Debug, Default)]
pub struct SunPlanes {
    before: Vec<f32>,
    plane: Vec<f32>,
}

impl SunPlanes {
    /// Bytes of planes for a grid of `dims`: two of its largest plane (as a float: the grid may
    /// be too large for a size).
    pub fn bytes_for(dims: [f64; 3]) -> f64 {
        let largest = (dims[0] * dims[1])
            .max(dims[1] * dims[2])
            .max(dims[0] * dims[2]);
        2.0 * largest * std::mem::size_of::<f32>() as f64
    }

    pub fn bytes(&self) -> usize {
        (self.before.capacity() + self.plane.capacity()) * std::mem::size_of::<f32>()
    }
}

/// Turns `grid`, the parts of each voxel, into the parts on the beam from the sun (in the unit
/// direction `toward`) up to and including each voxel.
pub fn propagate(grid: &mut [f32], dims: [usize; 3], toward: [f64; 3], planes: &mut SunPlanes) {
    let axis = longest_axis(toward);
    let (u, v) = match axis {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    };
    let (nu, nv) = (dims[u], dims[v]);
    let along = toward[axis].abs();
    let taps = bilinear(toward[u] / along, toward[v] / along);
    for p in [&mut planes.before, &mut planes.plane] {
        p.clear();
        p.resize(nu * nv, 0.0);
    }
    let n = dims[axis];
    for step in 0..n {
        // From the sun's side: the last plane first when the sun is towards +axis.
        let at = if toward[axis] > 0.0 {
            n - 1 - step
        } else {
            step
        };
        let of = PlaneOf::new(dims, axis, at);
        of.gather(grid, &mut planes.plane);
        if step > 0 {
            for &(shift, w) in &taps {
                shifted_add(&mut planes.plane, &planes.before, nu, w, shift);
            }
        }
        of.scatter(&planes.plane, grid, |x| x);
        std::mem::swap(&mut planes.before, &mut planes.plane);
    }
}

/// The axis along which `d` is longest (y first, then x, on a tie).
fn longest_axis(d: [f64; 3]) -> usize {
    let [x, y, z] = d.map(f64::abs);
    if y >= x && y >= z {
        1
    } else if x >= z {
        0
    } else {
        2
    }
}

/// The four shifts and weights that read a plane at the point (u + du, v + dv), |du|, |dv| ≤ 1,
/// by bilinear interpolation, as `shifted_add` takes them: a value read from (u + s) is moved
/// by −s.
fn bilinear(du: f64, dv: f64) -> [([isize; 2], f32); 4] {
    let (u0, v0) = (du.floor(), dv.floor());
    let (fu, fv) = (du - u0, dv - v0);
    let (u0, v0) = (u0 as isize, v0 as isize);
    [
        ([-u0, -v0], ((1.0 - fu) * (1.0 - fv)) as f32),
        ([-u0 - 1, -v0], (fu * (1.0 - fv)) as f32),
        ([-u0, -v0 - 1], ((1.0 - fu) * fv) as f32),
        ([-u0 - 1, -v0 - 1], (fu * fv) as f32),
    ]
}

/// The light let through by `parts` parts on the beam, one forgiven (the part a probe stands
/// at: Palubicki's "+ a" for the sun): (1 − absorb)^max(parts − 1, 0), given `kept` =
/// ln(1 − absorb) (−∞ when a part stops all).
pub fn transmitted(parts: f32, kept: f64) -> f64 {
    let crossed = f64::from(parts) - 1.0;
    if crossed <= 0.0 {
        1.0
    } else {
        maths::exp(crossed * kept)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One part in a 5 × 5 × 5 grid at (2, 4, 2): who is behind it, and how much.
    fn beam(toward: [f64; 3]) -> Vec<f32> {
        let dims = [5, 5, 5];
        let mut grid = vec![0.0; 125];
        grid[2 + 5 * (4 + 5 * 2)] = 1.0;
        propagate(&mut grid, dims, toward, &mut SunPlanes::default());
        grid
    }

    #[test]
    fn the_beam_carries_a_part_away_from_the_sun() {
        let overhead = beam([0.0, 1.0, 0.0]);
        for j in 0..5 {
            assert_eq!(overhead[2 + 5 * (j + 5 * 2)], 1.0, "under it, layer {j}");
            assert_eq!(overhead[3 + 5 * (j + 5 * 2)], 0.0, "beside it, layer {j}");
        }
        // The sun at 45° towards +x: the shadow goes down and to −x, one voxel a layer.
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let slanted = beam([s, s, 0.0]);
        for q in 0..3 {
            assert!(
                (slanted[(2 - q) + 5 * ((4 - q) + 5 * 2)] - 1.0).abs() < 1e-6,
                "{q}"
            );
        }
        assert_eq!(slanted[2 + 5 * (3 + 5 * 2)], 0.0);
        // A low sun towards −z (swept along z): the shadow runs to +z, dropping half a voxel a plane.
        let low = beam([0.0, 0.5, -1.0]);
        assert!((low[2 + 5 * (4 + 5 * 3)] - 0.5).abs() < 1e-6);
        assert!((low[2 + 5 * (3 + 5 * 3)] - 0.5).abs() < 1e-6);
        assert!((low[2 + 5 * (3 + 5 * 4)] - 0.5).abs() < 1e-6);
        assert!((low[2 + 5 * (2 + 5 * 4)] - 0.25).abs() < 1e-6);
        assert_eq!(low[2 + 5 * (4 + 5)], 0.0, "nothing towards the sun");
    }

    #[test]
    fn one_part_is_forgiven_and_the_rest_absorb() {
        let kept = |absorb: f64| maths::ln(1.0 - absorb);
        assert_eq!(transmitted(0.0, kept(0.5)), 1.0);
        assert_eq!(transmitted(1.0, kept(0.9)), 1.0);
        assert!((transmitted(3.0, kept(0.5)) - 0.25).abs() < 1e-12);
        assert_eq!(transmitted(2.0, kept(1.0)), 0.0);
        assert_eq!(transmitted(5.0, kept(0.0)), 1.0);
    }
}
