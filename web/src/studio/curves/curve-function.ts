// What a curve function's points draw, as the core reads them (crate/src/model/curve.rs, whose
// tests these mirror): `#curve`'s clamped uniform cubic B-spline (cpfg's function, vlab's
// funcedit) and `#table`'s straight lines. The curve editor draws with it; the core alone
// computes the plant. Pure.
import type { CurveFunctionKind } from '../../editor/curve-lines';

/** A point x y. */
export type Point2 = readonly [number, number];

/** The least number of points of each kind (docs/LANGUAGE.md "Curve functions"). */
export const LEAST_POINTS: Record<CurveFunctionKind, number> = { curve: 4, table: 2 };

/** The spline's point at parameter `d` in 0 … 1 (cpfg's `SplineFunction::P`: order 4, knots 0 0 0 0 1 2 … n−2 n−2 n−2 n−2). */
export function splinePoint(points: readonly Point2[], d: number): Point2 {
  const n = points.length - 1;
  if (d >= 1) return points[n];
  const u = Math.max(d, 0) * (n - 2);
  const knot = (j: number) => (j < 4 ? 0 : j > n ? n - 2 : j - 3);
  // Cox–de Boor, order by order: basis[k] is N(k, order, u).
  const basis = Array.from({ length: n + 4 }, (_, k): number => (knot(k) <= u && u < knot(k + 1) ? 1 : 0));
  for (let order = 2; order <= 4; order++) {
    for (let k = 0; k < n + 4 - order + 1; k++) {
      let sum = 0;
      const left = knot(k + order - 1) - knot(k);
      if (left !== 0) sum = ((u - knot(k)) / left) * basis[k];
      const right = knot(k + order) - knot(k + 1);
      if (right !== 0) sum += ((knot(k + order) - u) / right) * basis[k + 1];
      basis[k] = sum;
    }
  }
  return points.reduce<Point2>(([x, y], p, k) => [x + p[0] * basis[k], y + p[1] * basis[k]], [0, 0]);
}

/** The value at `x` (clamped to the first and the last point's x), as `name(x)` reads it. */
export function curveValue(kind: CurveFunctionKind, points: readonly Point2[], x: number): number {
  return kind === 'table' ? tableValue(points, x) : splineValue(points, x);
}

function tableValue(p: readonly Point2[], x: number): number {
  const [first, last] = [p[0], p[p.length - 1]];
  if (Number.isNaN(x) || x <= first[0]) return first[1];
  if (x >= last[0]) return last[1];
  let k = p.findIndex((q) => q[0] > x);
  k = Math.min(Math.max(k < 0 ? p.length : k, 1), p.length - 1);
  const [a, b] = [p[k - 1], p[k]];
  return b[0] === a[0] ? b[1] : a[1] + ((b[1] - a[1]) * (x - a[0])) / (b[0] - a[0]);
}

/** The parameter where the spline's x is `x`, by bisection (x grows along the curve), and y there. */
function splineValue(points: readonly Point2[], x: number): number {
  const first = splinePoint(points, 0)[0];
  const last = splinePoint(points, 1)[0];
  const target = Number.isNaN(x) ? first : Math.min(Math.max(x, Math.min(first, last)), Math.max(first, last));
  let [low, high] = [0, 1];
  let at = splinePoint(points, 0.5);
  for (let k = 0; k < 60; k++) {
    const middle = (low + high) / 2;
    at = splinePoint(points, middle);
    if (at[0] > target) high = middle;
    else low = middle;
  }
  return at[1];
}

/** The line the function draws, as points: the spline sampled along its parameter, or the table's corners. */
export function curveOutline(kind: CurveFunctionKind, points: readonly Point2[], samples = 160): Point2[] {
  if (kind === 'table' || points.length < LEAST_POINTS.curve) return [...points];
  return Array.from({ length: samples + 1 }, (_, k) => splinePoint(points, k / samples));
}
