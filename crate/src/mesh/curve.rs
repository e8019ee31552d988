//! Smooth branch axes, after Rynkiewicz & Napieralski's Bézier branch skeleton: the joints of an
//! axis are interpolated by a C¹ chain of cubic Bézier pieces (Catmull–Rom tangents), and the
//! tube's cross-sections follow the curve with rotation-minimizing frames (Wang et al.'s double
//! reflection), so a smooth tube does not twist.

use glam::DVec3;

/// One cubic Bézier piece: its four control points.
pub type Piece = [DVec3; 4];

/// Cubic pieces through `points` (at least two), piece `k` from `points[k]` to `points[k + 1]`.
/// Interior tangents are Catmull–Rom's `(p[k+1] − p[k−1]) / 2`; the end tangents are the end chords.
pub fn bezier_through(points: &[DVec3]) -> Vec<Piece> {
    let n = points.len();
    if n < 2 {
        return Vec::new();
    }
    let tangent = |k: usize| {
        if k == 0 {
            points[1] - points[0]
        } else if k == n - 1 {
            points[n - 1] - points[n - 2]
        } else {
            (points[k + 1] - points[k - 1]) * 0.5
        }
    };
    (0..n - 1)
        .map(|k| {
            let (p0, p3) = (points[k], points[k + 1]);
            [p0, p0 + tangent(k) / 3.0, p3 - tangent(k + 1) / 3.0, p3]
        })
        .collect()
}

/// The point and unit tangent of a piece at `t` in 0..=1. Where the derivative vanishes, the
/// tangent is the chord's direction.
pub fn evaluate(piece: &Piece, t: f64) -> (DVec3, DVec3) {
    let [p0, p1, p2, p3] = *piece;
    let s = 1.0 - t;
    let point =
        p0 * (s * s * s) + p1 * (3.0 * s * s * t) + p2 * (3.0 * s * t * t) + p3 * (t * t * t);
    let derivative =
        (p1 - p0) * (3.0 * s * s) + (p2 - p1) * (6.0 * s * t) + (p3 - p2) * (3.0 * t * t);
    let tangent = derivative
        .try_normalize()
        .or_else(|| (p3 - p0).try_normalize())
        .unwrap_or(DVec3::Y);
    (point, tangent)
}

/// Rotation-minimizing normals along a polyline of (point, unit tangent) samples, starting from
/// `initial` projected onto the plane normal to the first tangent. Each normal is unit and
/// perpendicular to its tangent.
pub fn rotation_minimizing_normals(samples: &[(DVec3, DVec3)], initial: DVec3) -> Vec<DVec3> {
    let mut normals = Vec::with_capacity(samples.len());
    rotation_minimizing_normals_into(samples, initial, &mut normals);
    normals
}

/// [`rotation_minimizing_normals`] into `normals` (emptied first).
pub fn rotation_minimizing_normals_into(
    samples: &[(DVec3, DVec3)],
    initial: DVec3,
    normals: &mut Vec<DVec3>,
) {
    normals.clear();
    let Some(&(_, t0)) = samples.first() else {
        return;
    };
    let mut r = (initial - t0 * initial.dot(t0))
        .try_normalize()
        .unwrap_or_else(|| t0.any_orthonormal_vector());
    normals.push(r);
    for w in samples.windows(2) {
        let ((x0, t0), (x1, t1)) = (w[0], w[1]);
        let v1 = x1 - x0;
        let c1 = v1.dot(v1);
        let (r_l, t_l) = if c1 > 0.0 {
            (
                r - v1 * (2.0 / c1 * v1.dot(r)),
                t0 - v1 * (2.0 / c1 * v1.dot(t0)),
            )
        } else {
            (r, t0)
        };
        let v2 = t1 - t_l;
        let c2 = v2.dot(v2);
        let next = if c2 > 0.0 {
            r_l - v2 * (2.0 / c2 * v2.dot(r_l))
        } else {
            r_l
        };
        // Re-orthogonalize against rounding.
        r = (next - t1 * next.dot(t1))
            .try_normalize()
            .unwrap_or_else(|| t1.any_orthonormal_vector());
        normals.push(r);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pieces_interpolate_the_joints_with_continuous_tangents() {
        let points = [
            DVec3::ZERO,
            DVec3::Y,
            DVec3::new(1.0, 2.0, 0.0),
            DVec3::new(1.0, 3.0, 1.0),
        ];
        let pieces = bezier_through(&points);
        assert_eq!(pieces.len(), 3);
        for (k, piece) in pieces.iter().enumerate() {
            assert!((evaluate(piece, 0.0).0 - points[k]).length() < 1e-12);
            assert!((evaluate(piece, 1.0).0 - points[k + 1]).length() < 1e-12);
        }
        for k in 0..2 {
            let (_, end) = evaluate(&pieces[k], 1.0);
            let (_, start) = evaluate(&pieces[k + 1], 0.0);
            assert!((end - start).length() < 1e-12);
        }
        // A straight line stays straight.
        let line = bezier_through(&[DVec3::ZERO, DVec3::Y, DVec3::new(0.0, 2.0, 0.0)]);
        let (p, t) = evaluate(&line[0], 0.5);
        assert!(
            (p - DVec3::new(0.0, 0.5, 0.0)).length() < 1e-12 && (t - DVec3::Y).length() < 1e-12
        );
    }

    #[test]
    fn frames_do_not_twist_along_a_planar_curve() {
        // Along a curve in the XY plane, the rotation-minimizing normal that starts along Z stays Z.
        let pieces = bezier_through(&[
            DVec3::ZERO,
            DVec3::Y,
            DVec3::new(1.0, 2.0, 0.0),
            DVec3::new(3.0, 2.5, 0.0),
        ]);
        let samples: Vec<(DVec3, DVec3)> = pieces
            .iter()
            .flat_map(|p| (0..8).map(move |j| evaluate(p, j as f64 / 8.0)))
            .collect();
        let normals = rotation_minimizing_normals(&samples, DVec3::Z);
        for (n, (_, t)) in normals.iter().zip(&samples) {
            assert!((*n - DVec3::Z).length() < 1e-9);
            assert!(n.dot(*t).abs() < 1e-9);
        }
        // A start normal not perpendicular to the tangent is projected.
        let n = rotation_minimizing_normals(&[(DVec3::ZERO, DVec3::Y)], DVec3::new(1.0, 1.0, 0.0));
        assert!((n[0] - DVec3::X).length() < 1e-12);
    }
}
