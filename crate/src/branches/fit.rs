//! The Bézier skeleton of one branch (Rynkiewicz & Napieralski): a cubic Bézier curve fitted to
//! the branch's joints, with each joint's parameter along it.
//!
//! - The parameters are by cumulative length: joint `i` sits at `t_i = (length of the segments
//!   before it) / (length of the branch)`, so `t_0 = 0` and `t_m = 1`.
//! - `P0` is the first joint (where the branch attaches) and `P3` the last; both are fixed.
//! - `P1` and `P2` are the least-squares fit: they minimise `Σ |B(t_i) − J_i|²` over the
//!   joints. A branch with fewer than two interior joints (one or two segments) leaves that
//!   system singular; its handles are then placed along the end tangents at a third of the chord
//!   (`P1 = P0 + T0·c/3`, `P2 = P3 − T1·c/3`). Either way a straight branch is reproduced exactly:
//!   `P1` and `P2` at its thirds and every joint on the curve.

use glam::DVec3;

/// A fitted cubic Bézier curve and the parameter of each joint on it.
#[derive(Clone, Debug, PartialEq)]
pub struct Fit {
    /// `P0 … P3`.
    pub control: [DVec3; 4],
    /// One parameter per joint, increasing from 0 to 1.
    pub params: Vec<f64>,
}

/// The Bernstein weights of a cubic at `t`.
pub fn bernstein(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t]
}

/// The point of the curve with control points `control` at `t`.
pub fn point(control: &[DVec3; 4], t: f64) -> DVec3 {
    let b = bernstein(t);
    control[0] * b[0] + control[1] * b[1] + control[2] * b[2] + control[3] * b[3]
}

/// Fits a cubic to `joints` (at least two points).
pub fn fit(joints: &[DVec3]) -> Fit {
    let m = joints.len().saturating_sub(1);
    let (p0, p3) = match (joints.first(), joints.last()) {
        (Some(&a), Some(&b)) => (a, b),
        _ => {
            return Fit {
                control: [DVec3::ZERO; 4],
                params: Vec::new(),
            }
        }
    };
    let mut params = Vec::with_capacity(joints.len());
    let mut total = 0.0;
    params.push(0.0);
    for w in joints.windows(2) {
        total += (w[1] - w[0]).length();
        params.push(total);
    }
    if total > 0.0 {
        params.iter_mut().for_each(|t| *t /= total);
    } else {
        // No length at all: spread the joints evenly.
        params = (0..=m).map(|i| i as f64 / m.max(1) as f64).collect();
    }
    if let Some(last) = params.last_mut() {
        *last = 1.0;
    }

    // Least squares for P1, P2 with P0, P3 fixed: the same 2×2 system for each coordinate.
    let (mut c11, mut c12, mut c22) = (0.0, 0.0, 0.0);
    let (mut x1, mut x2) = (DVec3::ZERO, DVec3::ZERO);
    for (j, &t) in joints.iter().zip(&params).take(m).skip(1) {
        let b = bernstein(t);
        let r = *j - p0 * b[0] - p3 * b[3];
        c11 += b[1] * b[1];
        c12 += b[1] * b[2];
        c22 += b[2] * b[2];
        x1 += r * b[1];
        x2 += r * b[2];
    }
    let det = c11 * c22 - c12 * c12;
    let control = if m >= 3 && det > 1e-9 * c11 * c22 {
        [
            p0,
            (x1 * c22 - x2 * c12) / det,
            (x2 * c11 - x1 * c12) / det,
            p3,
        ]
    } else {
        let chord = (p3 - p0).length();
        let c = if chord > 0.0 { chord } else { total };
        let t0 = (joints[1.min(m)] - p0)
            .try_normalize()
            .unwrap_or(DVec3::ZERO);
        let t1 = (p3 - joints[m.saturating_sub(1)])
            .try_normalize()
            .unwrap_or(DVec3::ZERO);
        [p0, p0 + t0 * (c / 3.0), p3 - t1 * (c / 3.0), p3]
    };
    Fit { control, params }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec3, b: DVec3, eps: f64) -> bool {
        (a - b).length() < eps
    }

    #[test]
    fn a_straight_branch_is_reproduced_exactly() {
        // Uneven joints along a line, with 1, 2 and 5 segments.
        let d = DVec3::new(0.3, 0.9, -0.2).normalize();
        let start = DVec3::new(1.0, 2.0, 3.0);
        for lengths in [vec![2.0], vec![0.5, 1.5], vec![0.3, 1.0, 0.2, 0.7, 0.8]] {
            let mut joints = vec![start];
            for l in &lengths {
                let last = *joints.last().unwrap();
                joints.push(last + d * *l);
            }
            let total: f64 = lengths.iter().sum();
            let f = fit(&joints);
            assert_eq!(f.control[0], start);
            assert_eq!(f.control[3], *joints.last().unwrap());
            assert!(close(f.control[1], start + d * (total / 3.0), 1e-12));
            assert!(close(f.control[2], start + d * (2.0 * total / 3.0), 1e-12));
            for (j, t) in joints.iter().zip(&f.params) {
                assert!(close(point(&f.control, *t), *j, 1e-12), "{lengths:?}");
            }
        }
    }

    #[test]
    fn parameters_are_by_cumulative_length() {
        let joints = [DVec3::ZERO, DVec3::Y, DVec3::new(0.0, 1.0, 3.0)];
        assert_eq!(fit(&joints).params, vec![0.0, 0.25, 1.0]);
    }

    #[test]
    fn a_bent_branch_is_fitted_by_least_squares() {
        // Joints sampled from a cubic at chord-length parameters are fitted closely.
        let control = [
            DVec3::ZERO,
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(1.0, 2.0, 0.5),
            DVec3::new(2.0, 2.0, 1.0),
        ];
        let joints: Vec<DVec3> = (0..=12).map(|i| point(&control, i as f64 / 12.0)).collect();
        let f = fit(&joints);
        let worst = joints
            .iter()
            .zip(&f.params)
            .map(|(j, t)| (point(&f.control, *t) - *j).length())
            .fold(0.0, f64::max);
        assert!(worst < 0.02, "worst residual {worst}");
        // The residual is no worse than that of the tangent construction.
        let c = (control[3] - control[0]).length() / 3.0;
        let t0 = (joints[1] - joints[0]).normalize();
        let t1 = (joints[12] - joints[11]).normalize();
        let tangents = [
            control[0],
            control[0] + t0 * c,
            control[3] - t1 * c,
            control[3],
        ];
        let residual = |k: &[DVec3; 4]| -> f64 {
            joints
                .iter()
                .zip(&f.params)
                .map(|(j, t)| (point(k, *t) - *j).length_squared())
                .sum()
        };
        assert!(residual(&f.control) <= residual(&tangents));
    }
}
