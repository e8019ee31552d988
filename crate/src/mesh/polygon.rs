//! Triangulation of the turtle's polygons (`{ … }`) and of the predefined surfaces.
//!
//! A polygon recorded by the turtle is a closed loop of points that is usually planar but need not
//! be (a `{ … }` block may turn with `&` or `^`). Its normal is Newell's normal, which is exact for
//! planar loops and a least-squares plane for others; the loop is projected onto that plane and
//! cut into triangles by ear clipping, which handles concave outlines (a maple leaf, a petal with a
//! notch) that a fan would fold over. Repeated points and collinear runs are dropped first, so a
//! `{ . f . f . }` that records the same point twice still triangulates cleanly.

use glam::{DVec2, DVec3};

/// Triangles over the indices of the original point list, counter-clockwise seen from `normal`.
#[derive(Clone, Debug, PartialEq)]
pub struct Triangulation {
    /// Unit normal of the polygon (Newell's), or zero when the polygon has no area.
    pub normal: DVec3,
    pub triangles: Vec<[u32; 3]>,
}

/// Relative tolerance for "the same point" and "no turn", against the polygon's size.
const EPSILON: f64 = 1e-9;

/// Triangulates a closed loop of points. A loop with fewer than three distinct points, or with no
/// area, gives no triangles.
pub fn triangulate(points: &[DVec3]) -> Triangulation {
    let empty = Triangulation {
        normal: DVec3::ZERO,
        triangles: Vec::new(),
    };
    if points.len() < 3 || points.iter().any(|p| !p.is_finite()) {
        return empty;
    }
    let newell = newell_normal(points);
    let size = points
        .iter()
        .fold(0.0f64, |m, p| m.max((*p - points[0]).length()));
    if size <= 0.0 || newell.length() <= EPSILON * size * size {
        return empty;
    }
    let normal = newell.normalize();
    let triangles = if points.len() <= CLIP_EARS_UP_TO {
        Outline::new(points, normal, size).clip_ears()
    } else {
        let tolerance = EPSILON * size * size;
        if let Some(fan) = convex_fan(points, normal, tolerance) {
            keep_counter_clockwise(points, normal, fan, tolerance)
        } else if points.len() <= EARCUT_UP_TO {
            keep_counter_clockwise(points, normal, earcut(points, normal), tolerance)
        } else if let Some(triangles) = sweep(points, normal, tolerance) {
            // Checked already: thin triangles along a fine outline are part of its area (only
            // those of no area at all, between collinear points, go).
            keep_counter_clockwise(points, normal, triangles, 0.0)
        } else {
            // An outline that crosses itself: no triangulation is right; this one is linear.
            keep_counter_clockwise(points, normal, fan_from_first(points.len()), tolerance)
        }
    };
    Triangulation { normal, triangles }
}

/// The most points a polygon may have for our own ear clipping, whose cost grows with the square
/// of the points (or worse). Larger ones are a fan when convex (linear), else go to the `earcut`
/// crate, which indexes the points by z-order (up to [`EARCUT_UP_TO`] points).
const CLIP_EARS_UP_TO: usize = 256;

/// A fan from the first point, when the polygon turns left (or runs straight) at every point and
/// goes round once (`tolerance`: twice an area that counts as none): the common large polygon (a disc, a round leaf of many points), for which
/// earcut's thin ears cost it the square of the points.
fn convex_fan(points: &[DVec3], normal: DVec3, tolerance: f64) -> Option<Vec<[u32; 3]>> {
    let (u, v) = plane_basis(normal);
    let flat: Vec<DVec2> = points
        .iter()
        .map(|p| DVec2::new(p.dot(u), p.dot(v)))
        .collect();
    let n = flat.len();
    let mut winding = 0.0;
    for i in 0..n {
        let (a, b, c) = (flat[i], flat[(i + 1) % n], flat[(i + 2) % n]);
        if cross(a, b, c) < -tolerance {
            return None;
        }
        let (d, e) = (b - a, c - b);
        if d != DVec2::ZERO && e != DVec2::ZERO {
            winding += d.angle_to(e);
        }
    }
    // Once round, not a loop that winds twice over itself.
    if (winding - std::f64::consts::TAU).abs() > 0.1 {
        return None;
    }
    Some(fan_from_first(n))
}

/// The most points of a concave polygon `earcut` is given: on outlines close to a circle its ears
/// grow long and its cost goes with the square of the points (20,000 points: a third of a second,
/// 50,000: two seconds). A larger concave polygon is cut by a sweep into monotone pieces
/// ([`super::monotone`], O(n log n): 50,000 points in milliseconds), exactly, with no gap over a
/// notch; only an outline that crosses itself, which no triangulation covers rightly, is drawn as
/// a fan from its first point (without the triangles that fold back).
const EARCUT_UP_TO: usize = 20_000;

/// Triangles of a large polygon by the monotone sweep, counter-clockwise about `normal`, its
/// repeated points skipped; `None` when its outline crosses itself.
fn sweep(points: &[DVec3], normal: DVec3, tolerance: f64) -> Option<Vec<[u32; 3]>> {
    let (u, v) = plane_basis(normal);
    let mut kept: Vec<u32> = Vec::with_capacity(points.len());
    let mut flat: Vec<DVec2> = Vec::with_capacity(points.len());
    for (i, p) in points.iter().enumerate() {
        let q = DVec2::new(p.dot(u), p.dot(v));
        if flat.last() != Some(&q) {
            kept.push(i as u32);
            flat.push(q);
        }
    }
    while flat.len() > 1 && flat.first() == flat.last() {
        flat.pop();
        kept.pop();
    }
    let triangles = super::monotone::triangulate(&flat, tolerance)?;
    Some(
        triangles
            .into_iter()
            .map(|t| t.map(|k| kept[k as usize]))
            .collect(),
    )
}

/// The triangles that turn counter-clockwise about `normal` with more than `tolerance` (twice
/// their area): earcut's slivers between collinear points and a fan's folds over a notch go.
fn keep_counter_clockwise(
    points: &[DVec3],
    normal: DVec3,
    mut triangles: Vec<[u32; 3]>,
    tolerance: f64,
) -> Vec<[u32; 3]> {
    triangles.retain(|t| {
        let [a, b, c] = t.map(|i| points[i as usize]);
        (b - a).cross(c - a).dot(normal) > tolerance
    });
    triangles
}

/// Triangles `0 i i+1` over a loop of `n` points.
fn fan_from_first(n: usize) -> Vec<[u32; 3]> {
    (1..n as u32 - 1).map(|i| [0, i, i + 1]).collect()
}

/// Triangles of a large polygon by `earcut`, counter-clockwise about `normal`.
fn earcut(points: &[DVec3], normal: DVec3) -> Vec<[u32; 3]> {
    let (u, v) = plane_basis(normal);
    let flat: Vec<[f64; 2]> = points.iter().map(|p| [p.dot(u), p.dot(v)]).collect();
    let mut indices: Vec<u32> = Vec::new();
    earcut::Earcut::new().earcut(flat.iter().copied(), &[], &mut indices);
    indices
        .chunks_exact(3)
        .map(|t| {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| DVec2::from(flat[i as usize]));
            if cross(a, b, c) < 0.0 {
                [t[0], t[2], t[1]]
            } else {
                [t[0], t[1], t[2]]
            }
        })
        .collect()
}

/// A right-handed basis of the plane facing `normal`, so counter-clockwise about `normal` is
/// counter-clockwise in 2-D.
fn plane_basis(normal: DVec3) -> (DVec3, DVec3) {
    let u = normal.any_orthonormal_vector();
    (u, normal.cross(u))
}

/// Newell's normal of a closed loop, not normalized: twice its area along its normal.
fn newell_normal(points: &[DVec3]) -> DVec3 {
    let mut newell = DVec3::ZERO;
    for (i, a) in points.iter().enumerate() {
        let b = points[(i + 1) % points.len()];
        newell += a.cross(b);
    }
    newell
}

/// Twice the signed area of the triangle `a b c`: positive when it turns counter-clockwise.
#[inline]
fn cross(a: DVec2, b: DVec2, c: DVec2) -> f64 {
    (b - a).perp_dot(c - a)
}

/// A polygon projected onto its plane, and the loop of its points that ear clipping has not yet
/// cut off.
struct Outline {
    /// Each point of the polygon in 2-D coordinates of its plane (counter-clockwise about the
    /// normal is counter-clockwise here).
    flat: Vec<DVec2>,
    /// The indices of the points still on the loop, in order, none repeating the one before.
    ring: Vec<usize>,
    /// Twice an area this small or smaller counts as none.
    area_tolerance: f64,
    /// How many ears may be cut at most (a guard against an endless loop).
    max_cuts: usize,
}

impl Outline {
    /// `points` projected onto the plane through the origin facing `normal`, without repeated
    /// points (including the last equal to the first). `size` is the polygon's extent.
    fn new(points: &[DVec3], normal: DVec3, size: f64) -> Outline {
        let (u, v) = plane_basis(normal);
        let flat: Vec<DVec2> = points
            .iter()
            .map(|p| DVec2::new(p.dot(u), p.dot(v)))
            .collect();
        let tolerance = EPSILON * size;
        let mut ring: Vec<usize> = Vec::with_capacity(points.len());
        for i in 0..points.len() {
            if ring
                .last()
                .is_none_or(|&last| (flat[last] - flat[i]).length() > tolerance)
            {
                ring.push(i);
            }
        }
        while ring.len() > 1 && (flat[ring[0]] - flat[*ring.last().unwrap()]).length() <= tolerance
        {
            ring.pop();
        }
        Outline {
            flat,
            ring,
            area_tolerance: EPSILON * size * size,
            max_cuts: points.len() * 2,
        }
    }

    /// The point indices of the corner at position `k` of the loop: (before, at, after).
    #[inline]
    fn corner(&self, k: usize) -> (usize, usize, usize) {
        let n = self.ring.len();
        (
            self.ring[(k + n - 1) % n],
            self.ring[k],
            self.ring[(k + 1) % n],
        )
    }

    /// How the loop turns at position `k`: positive where it is convex.
    #[inline]
    fn turn(&self, k: usize) -> f64 {
        let (a, b, c) = self.corner(k);
        cross(self.flat[a], self.flat[b], self.flat[c])
    }

    /// Cuts ears off the loop until fewer than three points are left; returns the triangles.
    fn clip_ears(mut self) -> Vec<[u32; 3]> {
        let mut triangles = Vec::with_capacity(self.flat.len().saturating_sub(2));
        let mut cuts = 0usize;
        while self.ring.len() >= 3 {
            // Remove collinear vertices: they make zero-area ears.
            if let Some(k) = self.collinear_corner() {
                self.ring.remove(k);
                continue;
            }
            // A self-intersecting loop may have no ear; cut the most convex corner so that every
            // input still gives a closed surface instead of a hole.
            let k = self.ear().unwrap_or_else(|| self.most_convex_corner());
            if self.turn(k) > 0.0 {
                let (a, b, c) = self.corner(k);
                triangles.push([a as u32, b as u32, c as u32]);
            }
            self.ring.remove(k);
            cuts += 1;
            if cuts > self.max_cuts {
                break;
            }
        }
        triangles
    }

    /// The first position of the loop where it runs straight on.
    fn collinear_corner(&self) -> Option<usize> {
        (0..self.ring.len()).find(|&k| self.turn(k).abs() <= self.area_tolerance)
    }

    /// The first position of the loop that is an ear: convex, with no other point of the loop
    /// inside its triangle.
    fn ear(&self) -> Option<usize> {
        (0..self.ring.len()).find(|&k| self.is_ear(k))
    }

    /// Whether position `k` of the loop is an ear (see [`Outline::ear`]).
    fn is_ear(&self, k: usize) -> bool {
        let (ia, ib, ic) = self.corner(k);
        let (a, b, c) = (self.flat[ia], self.flat[ib], self.flat[ic]);
        if cross(a, b, c) <= 0.0 {
            return false;
        }
        let inside = self.area_tolerance;
        self.ring.iter().all(|&j| {
            if j == ia || j == ib || j == ic {
                return true;
            }
            let p = self.flat[j];
            // Strictly outside the triangle, or on it: points on an edge do not block an ear.
            !(cross(a, b, p) > inside && cross(b, c, p) > inside && cross(c, a, p) > inside)
        })
    }

    /// The position of the loop where it turns most to the left.
    fn most_convex_corner(&self) -> usize {
        (0..self.ring.len())
            .max_by(|&x, &y| self.turn(x).total_cmp(&self.turn(y)))
            .unwrap()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maths;

    fn area(points: &[DVec3], t: &Triangulation) -> f64 {
        t.triangles
            .iter()
            .map(|&[a, b, c]| {
                let (a, b, c) = (points[a as usize], points[b as usize], points[c as usize]);
                0.5 * (b - a).cross(c - a).dot(t.normal)
            })
            .sum()
    }

    #[test]
    fn a_square_is_two_triangles_facing_its_winding() {
        let square = [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
        let t = triangulate(&square);
        assert_eq!(t.normal, DVec3::Z);
        assert_eq!(t.triangles.len(), 2);
        assert!((area(&square, &t) - 1.0).abs() < 1e-12);
        let reversed: Vec<DVec3> = square.iter().rev().copied().collect();
        assert_eq!(triangulate(&reversed).normal, -DVec3::Z);
    }

    #[test]
    fn a_large_polygon_is_cut_by_earcut_with_its_whole_area_facing_its_winding() {
        // A star of 4,000 points (concave everywhere), far above what ear clipping is given.
        let n = 4000;
        let star: Vec<DVec3> = (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                let r = if i % 2 == 0 { 1.0 } else { 0.8 };
                DVec3::new(r * maths::cos(a), r * maths::sin(a), 0.0)
            })
            .collect();
        let t = triangulate(&star);
        assert_eq!(t.normal, DVec3::Z);
        assert_eq!(t.triangles.len(), n - 2);
        let shoelace: f64 = (0..n)
            .map(|i| {
                let (a, b) = (star[i], star[(i + 1) % n]);
                0.5 * (a.x * b.y - b.x * a.y)
            })
            .sum();
        assert!(
            (area(&star, &t) - shoelace).abs() < 1e-9,
            "{}",
            area(&star, &t)
        );
        for &[a, b, c] in &t.triangles {
            let (a, b, c) = (star[a as usize], star[b as usize], star[c as usize]);
            assert!((b - a).cross(c - a).z >= 0.0);
        }
    }

    /// Checks a triangulation of a large concave outline: every triangle counter-clockwise, as
    /// many as a triangulation has (n - 2, less any of no area), their areas summing to the
    /// outline's (shoelace), which a fan's gaps and overlaps would not.
    fn assert_covers_exactly(name: &str, outline: &[DVec3]) {
        let n = outline.len();
        let start = std::time::Instant::now();
        let t = triangulate(outline);
        let took = start.elapsed();
        let shoelace: f64 = (0..n)
            .map(|i| 0.5 * outline[i].cross(outline[(i + 1) % n]).z)
            .sum();
        assert_eq!(t.normal, DVec3::Z, "{name}");
        for &[a, b, c] in &t.triangles {
            let (a, b, c) = (
                outline[a as usize],
                outline[b as usize],
                outline[c as usize],
            );
            assert!(
                (b - a).cross(c - a).z > 0.0,
                "{name}: a triangle facing away"
            );
        }
        // Every triangle's absolute area, so an overlap cannot hide behind a gap.
        let covered: f64 = t
            .triangles
            .iter()
            .map(|&[a, b, c]| {
                let (a, b, c) = (
                    outline[a as usize],
                    outline[b as usize],
                    outline[c as usize],
                );
                0.5 * (b - a).cross(c - a).z.abs()
            })
            .sum();
        assert!(
            (covered - shoelace).abs() <= 1e-9 * shoelace.abs(),
            "{name}: triangles cover {covered}, the outline {shoelace}"
        );
        assert!(t.triangles.len() <= n - 2, "{name}");
        eprintln!(
            "{name}: {n} points, {} triangles in {took:?}",
            t.triangles.len()
        );
    }

    #[test]
    fn a_concave_polygon_of_50k_points_is_covered_exactly_without_gap_or_overlap() {
        let n = 50_000;
        let tau = std::f64::consts::TAU;
        // A circle with one deep notch (earcut's slow case: close to a circle), a star whose
        // points' radii vary irregularly (concave everywhere), and a comb of square teeth (whole
        // coordinates: equal heights and collinear runs everywhere).
        let notch: Vec<DVec3> = (0..n)
            .map(|i| {
                let a = tau * i as f64 / n as f64;
                let r = if (n / 2..n / 2 + 50).contains(&i) {
                    0.2
                } else {
                    1.0
                };
                DVec3::new(r * maths::cos(a), r * maths::sin(a), 0.0)
            })
            .collect();
        let mut seed = 0x2545_f491_u64;
        let star: Vec<DVec3> = (0..n)
            .map(|i| {
                seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
                let a = tau * i as f64 / n as f64;
                let r = 0.5 + 0.5 * ((seed >> 11) as f64 / (1u64 << 53) as f64);
                DVec3::new(r * maths::cos(a), r * maths::sin(a), 0.0)
            })
            .collect();
        let teeth = (n - 2) / 4;
        let mut comb = vec![DVec3::ZERO, DVec3::new(2.0 * teeth as f64, 0.0, 0.0)];
        for k in (0..teeth).rev() {
            let x = 2.0 * k as f64;
            comb.extend([
                DVec3::new(x + 2.0, 10.0, 0.0),
                DVec3::new(x + 1.0, 10.0, 0.0),
                DVec3::new(x + 1.0, 1.0, 0.0),
                DVec3::new(x, 1.0, 0.0),
            ]);
        }
        for (name, outline) in [("notched circle", notch), ("star", star), ("comb", comb)] {
            assert!(outline.len() > EARCUT_UP_TO, "{name}: past earcut's share");
            assert_covers_exactly(name, &outline);
        }
    }

    #[test]
    fn a_concave_outline_keeps_its_notch() {
        // An arrow head: the fan from point 0 would cover the notch at point 3.
        let arrow = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::new(0.0, 2.0, 0.0),
            DVec3::new(0.5, 1.0, 0.0),
        ];
        let t = triangulate(&arrow);
        assert_eq!(t.triangles.len(), 2);
        // Shoelace area: 1.5.
        assert!(
            (area(&arrow, &t) - 1.5).abs() < 1e-12,
            "{}",
            area(&arrow, &t)
        );
        for tri in &t.triangles {
            let (a, b, c) = (
                arrow[tri[0] as usize],
                arrow[tri[1] as usize],
                arrow[tri[2] as usize],
            );
            assert!((b - a).cross(c - a).z > 0.0);
        }
    }

    #[test]
    fn repeated_and_collinear_points_and_degenerate_loops() {
        let points = [
            DVec3::ZERO,
            DVec3::ZERO,
            DVec3::X,
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::ZERO,
        ];
        let t = triangulate(&points);
        assert_eq!(t.triangles.len(), 1);
        assert!((area(&points, &t) - 1.0).abs() < 1e-12);
        assert!(
            triangulate(&[DVec3::ZERO, DVec3::X, DVec3::new(2.0, 0.0, 0.0)])
                .triangles
                .is_empty()
        );
        assert!(triangulate(&[DVec3::ZERO, DVec3::X]).triangles.is_empty());
        assert!(
            triangulate(&[DVec3::ZERO, DVec3::X, DVec3::new(f64::NAN, 0.0, 0.0)])
                .triangles
                .is_empty()
        );
    }

    #[test]
    fn a_self_intersecting_bow_tie_still_terminates() {
        let bow = [DVec3::ZERO, DVec3::new(1.0, 1.0, 0.0), DVec3::X, DVec3::Y];
        let t = triangulate(&bow);
        assert!(t.triangles.len() <= 2);
    }
}
