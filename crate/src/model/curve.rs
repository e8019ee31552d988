//! Functions of one variable given by points (`#curve`, `#table`): what cpfg's function files
//! (`.func`, edited with vlab's funcedit) hold, and the tables cpfg samples them into.

/// How a curve reads its points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CurveKind {
    /// cpfg's function: the control points of a clamped uniform cubic B-spline (x, y), read at x
    /// (the curve starts at the first point and ends at the last; in between it is pulled
    /// towards the others).
    Spline,
    /// Straight lines between the points, level beyond the first and the last.
    Table,
}

/// A function of one variable: `name(x)` in expressions.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    kind: CurveKind,
    points: Vec<(f64, f64)>,
}

/// How many bisection steps find the spline's parameter at x (2^-60 of the parameter range).
const BISECTIONS: usize = 60;

impl Curve {
    /// A curve of `kind` through `numbers` read as pairs x y; why not when they are not pairs,
    /// too few (a spline needs 4 points, a table 2), or not finite; a table's x must not
    /// decrease.
    pub fn new(kind: CurveKind, numbers: &[f64]) -> Result<Curve, String> {
        if !numbers.len().is_multiple_of(2) {
            return Err(format!(
                "{} numbers are not pairs x y: one is missing or extra",
                numbers.len()
            ));
        }
        if numbers.iter().any(|v| !v.is_finite()) {
            return Err("every point must be finite numbers".into());
        }
        let points: Vec<(f64, f64)> = numbers.chunks(2).map(|p| (p[0], p[1])).collect();
        let least = match kind {
            CurveKind::Spline => 4,
            CurveKind::Table => 2,
        };
        if points.len() < least {
            return Err(format!(
                "it needs at least {least} points, not {}",
                points.len()
            ));
        }
        if kind == CurveKind::Table && points.windows(2).any(|w| w[1].0 < w[0].0) {
            return Err("the points' x must not decrease".into());
        }
        Ok(Curve { kind, points })
    }

    /// The value at `x` (clamped to the first and the last point's x).
    pub fn value(&self, x: f64) -> f64 {
        match self.kind {
            CurveKind::Table => self.table_value(x),
            CurveKind::Spline => self.spline_value(x),
        }
    }

    fn table_value(&self, x: f64) -> f64 {
        let p = &self.points;
        let (first, last) = (p[0], p[p.len() - 1]);
        if x.is_nan() || x <= first.0 {
            return first.1;
        }
        if x >= last.0 {
            return last.1;
        }
        let k = p.partition_point(|q| q.0 <= x).clamp(1, p.len() - 1);
        let (a, b) = (p[k - 1], p[k]);
        if b.0 == a.0 {
            return b.1;
        }
        a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0)
    }

    /// cpfg's `SplineFunction::_Value` without sampling: the parameter where the curve's x is
    /// `x`, found by bisection (x grows along the curve, as funcedit keeps it), and y there.
    fn spline_value(&self, x: f64) -> f64 {
        let first = self.point(0.0).0;
        let last = self.point(1.0).0;
        let target = if x.is_nan() {
            first
        } else {
            crate::maths::clamp(x, first.min(last), first.max(last))
        };
        let (mut low, mut high) = (0.0, 1.0);
        let mut at = self.point(0.5);
        for _ in 0..BISECTIONS {
            let middle = (low + high) / 2.0;
            at = self.point(middle);
            if at.0 > target {
                high = middle;
            } else {
                low = middle;
            }
        }
        at.1
    }

    /// The spline's point at parameter `d` in 0 … 1 (cpfg's `SplineFunction::P`: order 4,
    /// knots 0 0 0 0 1 2 … n−2 n−2 n−2 n−2).
    fn point(&self, d: f64) -> (f64, f64) {
        let n = self.points.len() - 1;
        if d >= 1.0 {
            return self.points[n];
        }
        let u = d.max(0.0) * (n as f64 - 2.0);
        let knot = |j: usize| -> f64 {
            if j < 4 {
                0.0
            } else if j > n {
                n as f64 - 2.0
            } else {
                j as f64 - 3.0
            }
        };
        // Cox–de Boor, order by order: basis[k] is N(k, order, u).
        let mut basis: Vec<f64> = (0..n + 4)
            .map(|k| f64::from(u8::from(knot(k) <= u && u < knot(k + 1))))
            .collect();
        for order in 2..=4 {
            for k in 0..n + 4 - order + 1 {
                let mut sum = 0.0;
                let div = knot(k + order - 1) - knot(k);
                if div != 0.0 {
                    sum = (u - knot(k)) / div * basis[k];
                }
                let div = knot(k + order) - knot(k + 1);
                if div != 0.0 {
                    sum += (knot(k + order) - u) / div * basis[k + 1];
                }
                basis[k] = sum;
            }
        }
        self.points
            .iter()
            .zip(&basis)
            .fold((0.0, 0.0), |(x, y), (p, b)| (x + p.0 * b, y + p.1 * b))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_table_joins_its_points_with_straight_lines() {
        let t = Curve::new(CurveKind::Table, &[0.0, 0.0, 1.0, 2.0, 3.0, 2.0]).expect("table");
        assert_eq!(t.value(-1.0), 0.0);
        assert_eq!(t.value(0.5), 1.0);
        assert_eq!(t.value(2.0), 2.0);
        assert_eq!(t.value(9.0), 2.0);
        assert!(Curve::new(CurveKind::Table, &[1.0, 0.0, 0.0, 1.0]).is_err());
        assert!(Curve::new(CurveKind::Table, &[1.0, 0.0, 0.0]).is_err());
    }

    #[test]
    fn a_spline_starts_and_ends_at_its_end_points_and_is_straight_on_a_line() {
        // Control points on the line y = 2x: the spline is that line.
        let s = Curve::new(
            CurveKind::Spline,
            &[0.0, 0.0, 0.25, 0.5, 0.5, 1.0, 0.75, 1.5, 1.0, 2.0],
        )
        .expect("spline");
        for x in [0.0, 0.1, 0.33, 0.5, 0.9, 1.0] {
            assert!((s.value(x) - 2.0 * x).abs() < 1e-9, "{x}: {}", s.value(x));
        }
        assert!((s.value(-3.0)).abs() < 1e-9);
        assert!((s.value(7.0) - 2.0).abs() < 1e-9);
        assert!(Curve::new(CurveKind::Spline, &[0.0, 0.0, 1.0, 1.0, 2.0, 2.0]).is_err());
    }

    #[test]
    fn a_spline_is_pulled_towards_its_middle_points() {
        // vlab's internode.func (05-monopodial): a slow start, then a steep rise to 1.
        let s = Curve::new(
            CurveKind::Spline,
            &[
                0.0, 0.0, 0.426413, 0.004555, 0.717629, 0.997195, 1.0, 1.003176,
            ],
        )
        .expect("spline");
        assert!(s.value(0.2) < 0.1 && s.value(0.2) > 0.0);
        assert!(s.value(0.8) > 0.8 && s.value(0.8) < 1.0);
        assert!((s.value(1.0) - 1.003176).abs() < 1e-9);
        // Monotone here.
        let mut last = s.value(0.0);
        for k in 1..=100 {
            let v = s.value(k as f64 / 100.0);
            assert!(v >= last - 1e-12);
            last = v;
        }
    }
}
