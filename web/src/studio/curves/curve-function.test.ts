// The curve editor draws what the core computes: crate/src/model/curve.rs's tests, on the
// TypeScript that mirrors it, and the plot's round ticks.
import { describe, expect, it } from 'vitest';
import { curveOutline, curveValue, splinePoint, type Point2 } from './curve-function';
import { frameOf, ticks } from './curve-plot';

describe('a table', () => {
  it('joins its points with straight lines, level beyond the first and the last', () => {
    const t: Point2[] = [[0, 0], [1, 2], [3, 2]];
    expect([-1, 0.5, 2, 9].map((x) => curveValue('table', t, x))).toEqual([0, 1, 2, 2]);
    expect(curveValue('table', [[0, 0], [1, 1], [1, 5], [2, 5]], 1)).toBe(5);
  });
});

describe('a curve (cpfg’s B-spline)', () => {
  it('starts and ends at its end points and is straight on a line', () => {
    const s: Point2[] = [[0, 0], [0.25, 0.5], [0.5, 1], [0.75, 1.5], [1, 2]];
    for (const x of [0, 0.1, 0.33, 0.5, 0.9, 1]) expect(Math.abs(curveValue('curve', s, x) - 2 * x)).toBeLessThan(1e-9);
    expect(Math.abs(curveValue('curve', s, -3))).toBeLessThan(1e-9);
    expect(Math.abs(curveValue('curve', s, 7) - 2)).toBeLessThan(1e-9);
    expect(splinePoint(s, 0)).toEqual([0, 0]);
    expect(splinePoint(s, 1)).toEqual([1, 2]);
  });

  it('is pulled towards its middle points (vlab’s internode.func)', () => {
    const s: Point2[] = [[0, 0], [0.426413, 0.004555], [0.717629, 0.997195], [1, 1.003176]];
    expect(curveValue('curve', s, 0.2)).toBeGreaterThan(0);
    expect(curveValue('curve', s, 0.2)).toBeLessThan(0.1);
    expect(curveValue('curve', s, 0.8)).toBeGreaterThan(0.8);
    expect(curveValue('curve', s, 0.8)).toBeLessThan(1);
    const outline = curveOutline('curve', s, 100);
    expect(outline.length).toBe(101);
    outline.slice(1).forEach((p, k) => expect(p[0]).toBeGreaterThanOrEqual(outline[k][0]));
  });
});

describe('the plot', () => {
  it('marks round values and frames every point with a margin', () => {
    expect(ticks(0, 1)).toEqual([0, 0.2, 0.4, 0.6, 0.8, 1]);
    expect(ticks(-0.05, 1.05, 4)).toEqual([0, 0.5, 1]);
    expect(ticks(0, 250, 5)).toEqual([0, 50, 100, 150, 200, 250]);
    const frame = frameOf([[0, 0], [1, 1]], []);
    expect(frame.x[0]).toBeLessThan(0);
    expect(frame.x[1]).toBeGreaterThan(1);
    expect(frame.y[0]).toBeLessThan(0);
    expect(frame.y[1]).toBeGreaterThan(1);
    expect(frameOf([[2, 3], [2, 3]], []).x[1]).toBeGreaterThan(2);
    // A level curve (its samples off by rounding) is framed with 0 in sight, not magnified.
    const level: Point2[] = [[0, 1], [0.33, 1], [0.66, 1], [1, 1]];
    const y = frameOf(level, curveOutline('curve', level)).y;
    expect(y[0]).toBeLessThan(0);
    expect(y[1]).toBeGreaterThan(1.1);
  });
});
