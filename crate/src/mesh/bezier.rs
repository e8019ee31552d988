//! Bicubic Bézier patches (declared surfaces, `#patch`) as grids of points with smooth normals,
//! as cpfg draws a `.s` surface (vlab `cpfg/patches.c`: `calculate_surface`, its normals from
//! the s and t tangents, averaged where neighbouring patches meet).
//!
//! A patch is evaluated at `precision` quads along s (its rows, index `i` of the 4 × 4 grid) and
//! t (its columns, `j`); the front of a patch is ∂P/∂s × ∂P/∂t. The control points are placed in
//! the world first (a Bézier patch is affine invariant), so positions and tangents come out in
//! the world, whatever the surface's scale along each axis.

use crate::model::{Patch, SurfaceShape};
use crate::turtle::Surface;
use glam::DVec3;

/// One patch tessellated: `rows × cols` points row by row (rows along s) and their unit normals
/// (the front).
#[derive(Clone, Debug, PartialEq)]
pub struct Grid {
    pub points: Vec<DVec3>,
    pub normals: Vec<DVec3>,
    pub rows: usize,
    pub cols: usize,
}

impl Grid {
    /// The triangles of its quads as indices into its points, each facing the front, leaving
    /// out those with no area (a patch's collapsed edge, the disk's centre).
    pub fn triangles(&self) -> Vec<[u32; 3]> {
        let mut out = Vec::with_capacity(2 * (self.rows - 1) * (self.cols - 1));
        let extent = self
            .points
            .iter()
            .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
        let least = (extent * 1e-9).powi(2);
        for i in 0..self.rows - 1 {
            for j in 0..self.cols - 1 {
                let a = (i * self.cols + j) as u32;
                let (b, c) = (a + 1, a + self.cols as u32);
                for tri in [[a, c, b], [b, c, c + 1]] {
                    let [p, q, r] = tri.map(|k| self.points[k as usize]);
                    if (q - p).cross(r - p).length_squared() > least {
                        out.push(tri);
                    }
                }
            }
        }
        out
    }
}

/// The cubic Bernstein polynomials at `u` and their derivatives.
fn bernstein(u: f64) -> ([f64; 4], [f64; 4]) {
    let v = 1.0 - u;
    (
        [v * v * v, 3.0 * u * v * v, 3.0 * u * u * v, u * u * u],
        [
            -3.0 * v * v,
            3.0 * v * (v - 2.0 * u),
            3.0 * u * (2.0 * v - u),
            3.0 * u * u,
        ],
    )
}

/// The point of `patch` at (s, t) and its tangents ∂P/∂s, ∂P/∂t.
pub fn evaluate(patch: &Patch, s: f64, t: f64) -> [DVec3; 3] {
    let (bs, ds) = bernstein(s);
    let (bt, dt) = bernstein(t);
    let mut out = [DVec3::ZERO; 3];
    for i in 0..4 {
        for j in 0..4 {
            let p = patch[4 * i + j];
            out[0] += p * (bs[i] * bt[j]);
            out[1] += p * (ds[i] * bt[j]);
            out[2] += p * (bs[i] * dt[j]);
        }
    }
    out
}

/// The unit normal of `patch` at (s, t). Where the tangents vanish or are parallel (a collapsed
/// edge or corner) it is the normal just inside the patch, as the limit from within; failing
/// that, the normal of the corners' quad, or `fallback`.
fn normal(patch: &Patch, s: f64, t: f64, fallback: DVec3) -> DVec3 {
    for nudge in [0.0, 1e-4, 1e-2, 0.1] {
        let [_, ds, dt] = evaluate(patch, s + (0.5 - s) * nudge, t + (0.5 - t) * nudge);
        let n = ds.cross(dt);
        if n.length_squared() > 1e-24 * ds.length_squared().max(dt.length_squared()).max(1e-300) {
            if let Some(n) = n.try_normalize() {
                return n;
            }
        }
    }
    let [a, b, c, d] = [patch[0], patch[3], patch[15], patch[12]];
    (c - a).cross(b - d).try_normalize().unwrap_or(fallback)
}

/// The patches of a declared surface placed as `surface` places it, tessellated at the shape's
/// precision, normals averaged where patches meet (the same point, normals on the same side).
pub fn tessellate(surface: &Surface, shape: &SurfaceShape) -> Vec<Grid> {
    let [sn, tn] = shape.precision.map(|n| n.max(1) as usize);
    let fallback = surface.up * surface.scale.z.signum();
    let mut grids: Vec<Grid> = shape
        .patches
        .iter()
        .map(|local| {
            let patch: Patch = local.map(|p| surface.place(p));
            let mut grid = Grid {
                points: Vec::with_capacity((sn + 1) * (tn + 1)),
                normals: Vec::with_capacity((sn + 1) * (tn + 1)),
                rows: sn + 1,
                cols: tn + 1,
            };
            for i in 0..=sn {
                let s = i as f64 / sn as f64;
                for j in 0..=tn {
                    let t = j as f64 / tn as f64;
                    grid.points.push(evaluate(&patch, s, t)[0]);
                    grid.normals.push(normal(&patch, s, t, fallback));
                }
            }
            grid
        })
        .collect();
    if grids.len() > 1 {
        smooth_seams(&mut grids);
    }
    grids
}

/// Averages the normals of points that patches share (within a millionth of the surface's size),
/// among those on the same side as the first: cpfg's `calculate_neighbouring_vertex_normals`
/// without its neighbour names.
fn smooth_seams(grids: &mut [Grid]) {
    let extent = grids
        .iter()
        .flat_map(|g| &g.points)
        .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    let cell = (extent * 1e-6).max(f64::MIN_POSITIVE);
    // Every point with its cell, sorted by cell (the core's one sort: no hash map in the first
    // plant's core), then each run of one cell averaged.
    let mut keyed: Vec<([i64; 3], usize, usize)> = Vec::new();
    for (g, grid) in grids.iter().enumerate() {
        for (k, p) in grid.points.iter().enumerate() {
            keyed.push(((*p / cell).round().as_i64vec3().to_array(), g, k));
        }
    }
    crate::sort::sort_by_key(&mut keyed, |e| e.0);
    for run in keyed.chunk_by(|a, b| a.0 == b.0).filter(|r| r.len() > 1) {
        let first = grids[run[0].1].normals[run[0].2];
        let same: Vec<(usize, usize)> = run
            .iter()
            .map(|&(_, g, k)| (g, k))
            .filter(|&(g, k)| grids[g].normals[k].dot(first) > 0.0)
            .collect();
        let sum: DVec3 = same.iter().map(|&(g, k)| grids[g].normals[k]).sum();
        if let Some(n) = sum.try_normalize() {
            for (g, k) in same {
                grids[g].normals[k] = n;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::organ_patches;
    use crate::turtle::SurfaceKind;
    use crate::vocabulary::Organ;

    fn at_turtle(scale: DVec3) -> Surface {
        Surface {
            kind: SurfaceKind::Declared(0),
            origin: DVec3::new(1.0, 2.0, 3.0),
            heading: DVec3::Y,
            left: DVec3::NEG_X,
            up: DVec3::Z,
            scale,
            color: 0,
            module: 0,
            anchor: None,
        }
    }

    fn shape(organ: Organ, precision: u32) -> SurfaceShape {
        SurfaceShape {
            letter: 'x',
            patches: organ_patches(organ),
            precision: [precision; 2],
            end: None,
            organ: Some(organ),
            frame: Default::default(),
            written: Vec::new(),
            colors: Vec::new(),
        }
    }

    #[test]
    fn a_flat_patch_is_its_control_square_with_normals_along_the_front() {
        // Control points on a 3 × 3 square in the L–H plane: the patch is the square itself.
        let patch: Patch = std::array::from_fn(|k| DVec3::new((k % 4) as f64, (k / 4) as f64, 0.0));
        let mut s = shape(Organ::Leaf, 3);
        s.patches = vec![patch];
        let g = &tessellate(&at_turtle(DVec3::ONE), &s)[0];
        assert_eq!((g.rows, g.cols, g.points.len()), (4, 4, 16));
        // Point (s, t) = (1/3, 2/3): 1 along H, 2 along L (= −X) from the turtle.
        assert!((g.points[4 + 2] - DVec3::new(-1.0, 3.0, 3.0)).length() < 1e-12);
        // Rows along H, columns along L: the front is H × L = U.
        for n in &g.normals {
            assert!((*n - DVec3::Z).length() < 1e-12);
        }
        assert_eq!(g.triangles().len(), 18);
    }

    #[test]
    fn the_disk_s_collapsed_centre_has_finite_normals_and_no_empty_triangles() {
        let grids = tessellate(&at_turtle(DVec3::splat(2.0)), &shape(Organ::Disk, 4));
        for g in &grids {
            for n in &g.normals {
                assert!(n.is_finite() && (n.length() - 1.0).abs() < 1e-9);
                // The disk faces U everywhere (domed a little).
                assert!(n.z > 0.8, "{n}");
            }
            // A row of quads at the centre loses one triangle each.
            assert_eq!(g.triangles().len(), 2 * 16 - 4);
        }
        // The centre is shared by the four quarters: one normal, U.
        let centre = grids[0].normals[0];
        assert!((centre - DVec3::Z).length() < 1e-9, "{centre}");
    }

    #[test]
    fn scales_stretch_each_axis_and_seams_share_normals() {
        let grids = tessellate(
            &at_turtle(DVec3::new(2.0, 3.0, 1.0)),
            &shape(Organ::Leaf, 6),
        );
        let tip = grids[0].points[6 * 7];
        // The leaf's tip: 1 along H at scale 3, curved down 0.08 along U.
        assert!((tip - DVec3::new(1.0, 5.0, 2.92)).length() < 1e-12, "{tip}");
        // The midrib: column 0 of the left half is the last column of the right half.
        for i in 0..7 {
            let (l, r) = (7 * i, 7 * i + 6);
            assert!((grids[0].points[l] - grids[1].points[r]).length() < 1e-12);
            assert!((grids[0].normals[l] - grids[1].normals[r]).length() < 1e-12);
        }
    }
}
