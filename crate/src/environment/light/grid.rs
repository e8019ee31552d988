//! The light grid's box and its planes: which voxels the plants' parts and their shadows need,
//! where a point falls, and the plane operations the two propagations are made of (a plane
//! gathered out of the grid, shifted and added, scattered back), written as loops over
//! contiguous slices that the compiler vectorises.
//!
//! Layout (as [`crate::environment::Field`]'s): voxel (i, j, k) is `i + nx × (j + ny × k)`, x
//! fastest, y (up) the layers. A plane is a slice of `nu × nv` values, u fastest.

use crate::environment::Part;

/// The voxels of the grid: voxel (i, j, k) spans `cell × (lo + (i, j, k))` to one cell more.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Extent {
    /// The lowest voxel's integer coordinates (whole numbers, as floats: far from the origin
    /// they stay exact where integers would overflow).
    pub lo: [f64; 3],
    pub dims: [usize; 3],
    pub cell: f64,
}

/// The whole numbers of cells the parts' box spans, before margins: (lowest, highest) on each axis.
pub fn parts_box(parts: &[Part], cell: f64) -> Option<([f64; 3], [f64; 3])> {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for part in parts.iter().filter(|p| finite(p)) {
        for p in [part.from, part.to] {
            for a in 0..3 {
                let c = (p[a] / cell).floor();
                lo[a] = lo[a].min(c);
                hi[a] = hi[a].max(c);
            }
        }
    }
    (lo[0] <= hi[0]).then_some((lo, hi))
}

/// True when a part can be placed: its points and area are finite.
pub fn finite(part: &Part) -> bool {
    part.from.iter().chain(&part.to).all(|x| x.is_finite()) && part.area.is_finite()
}

impl Extent {
    /// The box from `lo` to `hi` (whole cells) with `below`/`around` cells of margin under and
    /// beside it and `above` over it. The dimensions as floats: the caller checks them against
    /// its budget before it takes them as sizes.
    pub fn with_margins(
        lo: [f64; 3],
        hi: [f64; 3],
        around: f64,
        below: f64,
        above: f64,
    ) -> ([f64; 3], [f64; 3]) {
        let lo = [lo[0] - around, lo[1] - below, lo[2] - around];
        let hi = [hi[0] + around, hi[1] + above, hi[2] + around];
        (lo, [0, 1, 2].map(|a| hi[a] - lo[a] + 1.0))
    }

    pub fn voxels(&self) -> usize {
        self.dims[0] * self.dims[1] * self.dims[2]
    }

    pub fn index(&self, [i, j, k]: [usize; 3]) -> usize {
        i + self.dims[0] * (j + self.dims[1] * k)
    }

    /// The corner of the grid in the model's coordinates.
    pub fn origin(&self) -> [f64; 3] {
        self.lo.map(|c| c * self.cell)
    }

    /// The voxel of `p` (fractional voxel coordinates), if it is in the grid.
    pub fn voxel_of(&self, p: [f64; 3]) -> Option<[usize; 3]> {
        let mut v = [0; 3];
        for a in 0..3 {
            let r = (p[a] / self.cell).floor() - self.lo[a];
            if !(r >= 0.0 && r < self.dims[a] as f64) {
                return None;
            }
            v[a] = r as usize;
        }
        Some(v)
    }

    /// The voxel of `p`, moved into the grid when rounding put it just outside.
    pub fn voxel_clamped(&self, p: [f64; 3]) -> [usize; 3] {
        [0, 1, 2].map(|a| {
            let r = (p[a] / self.cell).floor() - self.lo[a];
            r.clamp(0.0, (self.dims[a] - 1) as f64) as usize
        })
    }
}

/// One plane of the grid: the voxels whose coordinate on `axis` is `at`, the other two axes in
/// order (u the lower).
#[derive(Clone, Copy, Debug)]
pub struct PlaneOf {
    pub base: usize,
    pub nu: usize,
    pub su: usize,
    pub sv: usize,
}

impl PlaneOf {
    pub fn new(dims: [usize; 3], axis: usize, at: usize) -> PlaneOf {
        let strides = [1, dims[0], dims[0] * dims[1]];
        let (u, v) = match axis {
            0 => (1, 2),
            1 => (0, 2),
            _ => (0, 1),
        };
        PlaneOf {
            base: at * strides[axis],
            nu: dims[u],
            su: strides[u],
            sv: strides[v],
        }
    }

    /// Copies the plane out of `grid` into `plane`.
    pub fn gather(&self, grid: &[f32], plane: &mut [f32]) {
        for (v, row) in plane.chunks_exact_mut(self.nu).enumerate() {
            let start = self.base + v * self.sv;
            if self.su == 1 {
                row.copy_from_slice(&grid[start..start + self.nu]);
            } else {
                for (u, x) in row.iter_mut().enumerate() {
                    *x = grid[start + u * self.su];
                }
            }
        }
    }

    /// Copies `plane` into the grid, each value through `f`.
    pub fn scatter(&self, plane: &[f32], grid: &mut [f32], f: impl Fn(f32) -> f32) {
        for (v, row) in plane.chunks_exact(self.nu).enumerate() {
            let start = self.base + v * self.sv;
            if self.su == 1 {
                for (g, &x) in grid[start..start + self.nu].iter_mut().zip(row) {
                    *g = f(x);
                }
            } else {
                for (u, &x) in row.iter().enumerate() {
                    grid[start + u * self.su] = f(x);
                }
            }
        }
    }
}

/// `dst(u, v) += w × src(u − su, v − sv)` where both are in the planes of `nu × nv` values: the
/// content of `src` moved by (su, sv); what moves out is dropped.
pub fn shifted_add(dst: &mut [f32], src: &[f32], nu: usize, w: f32, shift: [isize; 2]) {
    let nv = dst.len() / nu.max(1);
    let [su, sv] = shift;
    if su.unsigned_abs() >= nu || sv.unsigned_abs() >= nv || w == 0.0 {
        return;
    }
    let (u_from, u_to) = (su.max(0) as usize, (nu as isize + su.min(0)) as usize);
    let (v_from, v_to) = (sv.max(0) as usize, (nv as isize + sv.min(0)) as usize);
    for v in v_from..v_to {
        let d = &mut dst[v * nu + u_from..v * nu + u_to];
        let s_start = (v as isize - sv) as usize * nu + (u_from as isize - su) as usize;
        let s = &src[s_start..s_start + d.len()];
        for (x, &y) in d.iter_mut().zip(s) {
            *x += w * y;
        }
    }
}
