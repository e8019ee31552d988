//! The organ library (`#surface X leaf`, `petal`, `sepal`, `disk`, `ray_floret`): a few
//! bicubic patches each, written for Meristem (not copied from any `.s` file), in the turtle's
//! frame at scale 1: x along L, y along H, z along U, the contact point at the origin.
//!
//! Organs but the disk are 1 long along H and made of two mirrored halves whose rows run from
//! the base to the tip and whose columns run along +L, so that every patch's front (rows' tangent
//! × columns' tangent) faces U. The disk is four quarters around the turtle, 1 across, each with
//! its rows from the centre (a degenerate corner) to the rim.

use super::Patch;
use crate::maths;
use crate::vocabulary::Organ;
use glam::DVec3;

/// Half an organ: 4 rows from base to tip, each 4 points from the midrib (x = 0) to the margin.
type Half = [[[f64; 3]; 4]; 4];

const LEAF: Half = [
    [
        [0.0, 0.0, 0.0],
        [0.01, 0.0, 0.0],
        [0.02, 0.0, 0.0],
        [0.03, 0.0, 0.0],
    ],
    [
        [0.0, 0.3, 0.0],
        [0.12, 0.3, 0.03],
        [0.24, 0.28, 0.05],
        [0.3, 0.25, 0.06],
    ],
    [
        [0.0, 0.7, 0.0],
        [0.1, 0.7, 0.02],
        [0.18, 0.68, 0.04],
        [0.22, 0.62, 0.05],
    ],
    [
        [0.0, 1.0, -0.08],
        [0.005, 0.99, -0.08],
        [0.01, 0.98, -0.08],
        [0.015, 0.97, -0.08],
    ],
];

const PETAL: Half = [
    [
        [0.0, 0.0, 0.0],
        [0.02, 0.0, 0.0],
        [0.04, 0.0, 0.0],
        [0.05, 0.0, 0.0],
    ],
    [
        [0.0, 0.35, 0.0],
        [0.1, 0.35, 0.02],
        [0.22, 0.33, 0.05],
        [0.28, 0.3, 0.08],
    ],
    [
        [0.0, 0.85, 0.02],
        [0.16, 0.85, 0.05],
        [0.34, 0.8, 0.1],
        [0.4, 0.7, 0.14],
    ],
    [
        [0.0, 1.0, 0.05],
        [0.12, 1.0, 0.07],
        [0.22, 0.98, 0.1],
        [0.3, 0.92, 0.14],
    ],
];

const SEPAL: Half = [
    [
        [0.0, 0.0, 0.0],
        [0.02, 0.0, 0.0],
        [0.04, 0.0, 0.0],
        [0.05, 0.0, 0.0],
    ],
    [
        [0.0, 0.35, 0.0],
        [0.06, 0.35, 0.02],
        [0.13, 0.33, 0.05],
        [0.16, 0.3, 0.08],
    ],
    [
        [0.0, 0.75, 0.0],
        [0.04, 0.75, 0.02],
        [0.08, 0.72, 0.04],
        [0.1, 0.68, 0.06],
    ],
    [
        [0.0, 1.0, 0.03],
        [0.003, 0.995, 0.03],
        [0.006, 0.99, 0.03],
        [0.01, 0.985, 0.03],
    ],
];

const RAY_FLORET: Half = [
    [
        [0.0, 0.0, 0.0],
        [0.01, 0.0, 0.0],
        [0.02, 0.0, 0.0],
        [0.03, 0.0, 0.0],
    ],
    [
        [0.0, 0.33, 0.0],
        [0.03, 0.33, 0.005],
        [0.06, 0.33, 0.01],
        [0.08, 0.33, 0.01],
    ],
    [
        [0.0, 0.67, -0.02],
        [0.03, 0.67, -0.015],
        [0.06, 0.67, -0.01],
        [0.085, 0.67, -0.01],
    ],
    [
        [0.0, 0.93, -0.06],
        [0.03, 0.96, -0.06],
        [0.06, 0.995, -0.06],
        [0.07, 1.0, -0.06],
    ],
];

/// The disk's radius and the height of its dome's centre above the rim.
const DISK_RADIUS: f64 = 0.5;
const DISK_DOME: f64 = 0.06;

/// The patches of a library shape (see the module's doc).
pub fn organ_patches(organ: Organ) -> Vec<Patch> {
    match organ {
        Organ::Leaf => halves(&LEAF),
        Organ::Petal => halves(&PETAL),
        Organ::Sepal => halves(&SEPAL),
        Organ::RayFloret => halves(&RAY_FLORET),
        Organ::Disk => (0..4).map(disk_quarter).collect(),
    }
}

/// The left half (x ≥ 0) as written and the right half, mirrored across the midrib with its
/// columns reversed so that they still run along +x (and its front still faces U).
fn halves(left: &Half) -> Vec<Patch> {
    let point = |[x, y, z]: [f64; 3]| DVec3::new(x, y, z);
    let left_patch: Patch = std::array::from_fn(|k| point(left[k / 4][k % 4]));
    let right_patch: Patch = std::array::from_fn(|k| {
        let [x, y, z] = left[k / 4][3 - k % 4];
        point([-x, y, z])
    });
    vec![left_patch, right_patch]
}

/// Quarter `k` of the disk, turned by k · 90° about U: rows from the centre to the rim, columns
/// clockwise seen from U along the rim (a cubic arc, k = 0.5523), so its front faces U.
fn disk_quarter(k: usize) -> Patch {
    let r = DISK_RADIUS;
    let c = 0.5523 * r;
    let arc = [(0.0, r), (c, r), (r, c), (r, 0.0)];
    let (sin, cos) = maths::sin_cos(k as f64 * std::f64::consts::FRAC_PI_2);
    std::array::from_fn(|n| {
        let (i, j) = (n / 4, n % 4);
        let f = i as f64 / 3.0;
        let (x, y) = (arc[j].0 * f, arc[j].1 * f);
        let z = DISK_DOME * (1.0 - f * f);
        DVec3::new(x * cos - y * sin, x * sin + y * cos, z)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vocabulary::SURFACE_SHAPES;

    #[test]
    fn organs_are_one_long_and_the_disk_one_across() {
        for info in SURFACE_SHAPES {
            let patches = organ_patches(info.organ);
            let points = patches.iter().flatten();
            let (lo, hi) = points.fold((DVec3::MAX, DVec3::MIN), |(lo, hi), p| {
                (lo.min(*p), hi.max(*p))
            });
            if info.organ == Organ::Disk {
                assert_eq!(patches.len(), 4);
                assert!((hi.x - lo.x - 1.0).abs() < 1e-9 && (hi.y - lo.y - 1.0).abs() < 1e-9);
            } else {
                assert_eq!(patches.len(), 2, "{}", info.name);
                // The base at the turtle, the tip 1 along H, symmetric across the midrib.
                assert!(
                    lo.y.abs() < 1e-12 && (hi.y - 1.0).abs() < 1e-12,
                    "{}",
                    info.name
                );
                assert!((hi.x + lo.x).abs() < 1e-12, "{}", info.name);
                assert_eq!(patches[0][0], DVec3::ZERO);
            }
        }
    }

    #[test]
    fn the_halves_share_their_midrib() {
        let p = organ_patches(Organ::Petal);
        for i in 0..4 {
            assert_eq!(p[0][4 * i], p[1][4 * i + 3]);
        }
    }
}
