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
    let mut newell = DVec3::ZERO;
    for (i, a) in points.iter().enumerate() {
        let b = points[(i + 1) % points.len()];
        newell += a.cross(b);
    }
    let size = points
        .iter()
        .fold(0.0f64, |m, p| m.max((*p - points[0]).length()));
    if size <= 0.0 || newell.length() <= EPSILON * size * size {
        return empty;
    }
    let normal = newell.normalize();
    // A right-handed basis of the plane, so counter-clockwise about `normal` is counter-clockwise in 2D.
    let u = normal.any_orthonormal_vector();
    let v = normal.cross(u);
    let flat: Vec<DVec2> = points
        .iter()
        .map(|p| DVec2::new(p.dot(u), p.dot(v)))
        .collect();

    // Drop repeated points (including the last equal to the first).
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
    while ring.len() > 1 && (flat[ring[0]] - flat[*ring.last().unwrap()]).length() <= tolerance {
        ring.pop();
    }

    let area_tolerance = EPSILON * size * size;
    let cross = |a: DVec2, b: DVec2, c: DVec2| (b - a).perp_dot(c - a);
    let mut triangles = Vec::with_capacity(points.len().saturating_sub(2));
    let mut guard = 0usize;
    while ring.len() >= 3 {
        let n = ring.len();
        // Remove collinear vertices: they make zero-area ears.
        if let Some(k) = (0..n).find(|&k| {
            let (a, b, c) = (
                flat[ring[(k + n - 1) % n]],
                flat[ring[k]],
                flat[ring[(k + 1) % n]],
            );
            cross(a, b, c).abs() <= area_tolerance
        }) {
            ring.remove(k);
            continue;
        }
        let is_ear = |k: usize| {
            let (ia, ib, ic) = (ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n]);
            let (a, b, c) = (flat[ia], flat[ib], flat[ic]);
            if cross(a, b, c) <= 0.0 {
                return false;
            }
            ring.iter().all(|&j| {
                if j == ia || j == ib || j == ic {
                    return true;
                }
                let p = flat[j];
                // Strictly outside the triangle, or on it: points on an edge do not block an ear.
                !(cross(a, b, p) > area_tolerance
                    && cross(b, c, p) > area_tolerance
                    && cross(c, a, p) > area_tolerance)
            })
        };
        let ear = (0..n).find(|&k| is_ear(k));
        // A self-intersecting loop may have no ear; cut the most convex corner so that every
        // input still gives a closed surface instead of a hole.
        let k = ear.unwrap_or_else(|| {
            (0..n)
                .max_by(|&x, &y| {
                    let turn = |k: usize| {
                        cross(
                            flat[ring[(k + n - 1) % n]],
                            flat[ring[k]],
                            flat[ring[(k + 1) % n]],
                        )
                    };
                    turn(x).total_cmp(&turn(y))
                })
                .unwrap()
        });
        let (a, b, c) = (ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n]);
        if cross(flat[a], flat[b], flat[c]) > 0.0 {
            triangles.push([a as u32, b as u32, c as u32]);
        }
        ring.remove(k);
        guard += 1;
        if guard > points.len() * 2 {
            break;
        }
    }
    Triangulation { normal, triangles }
}

#[cfg(test)]
mod tests {
    use super::*;

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
