// The text of a surface's control points (`#patch X x y z, …`, docs/LANGUAGE.md "Surfaces"): a
// point written as the editor writes it, the changes that move points, and a library shape written
// out as `#patch` lines. Pure: the tests read it without a page.
import type { Point3, WrittenPoint } from '../../core';
import type { TextChange } from '../../editor/growth-directives';

/** Decimals the editor writes (a drag's pixel is far coarser; the core reads them back exactly). */
export const POINT_DECIMALS = 4;

/** The largest coordinate the editor writes (a drag toward the horizon stops there). */
export const MAX_COORDINATE = 1e6;

/** A coordinate as written: rounded to {@link POINT_DECIMALS} decimals, no trailing zeros, never `-0`. */
export function coordinateText(value: number): string {
  if (!Number.isFinite(value)) return '0';
  const clamped = Math.min(MAX_COORDINATE, Math.max(-MAX_COORDINATE, value));
  const scale = 10 ** POINT_DECIMALS;
  const rounded = Math.round(clamped * scale) / scale;
  return rounded === 0 ? '0' : String(rounded);
}

/** A point as written: `x y z`. */
export function pointText(point: Point3): string {
  return point.map(coordinateText).join(' ');
}

/** A span of the text: where a point's numbers are written. */
export interface PointSpan {
  from: number;
  to: number;
}

/**
 * The changes that write `inserts[k]` at `spans[k]`, and the spans after them, in the same order.
 * The spans must not overlap.
 */
export function replaceSpans(spans: readonly PointSpan[], inserts: readonly string[]): { changes: TextChange[]; spans: PointSpan[] } {
  const changes = spans.map(({ from, to }, k) => ({ from, to, insert: inserts[k] }));
  // Each change shifts the spans after it by its change of length.
  const order = spans.map((_, k) => k).sort((a, b) => spans[a].from - spans[b].from);
  const after: PointSpan[] = spans.map((s) => ({ ...s }));
  let shift = 0;
  for (const k of order) {
    const { from, to } = spans[k];
    after[k] = { from: from + shift, to: from + shift + inserts[k].length };
    shift += inserts[k].length - (to - from);
  }
  return { changes, spans: after };
}

/** The changes that write `point` at every span of `spans` (the written copies of one control point), and the spans after them. */
export function movePoints(spans: readonly PointSpan[], point: Point3): { changes: TextChange[]; spans: PointSpan[] } {
  const insert = pointText(point);
  return replaceSpans(spans, spans.map(() => insert));
}

/**
 * The written points that are the same control point as `written[k]`: the same numbers in every
 * patch that repeats them (where two patches meet), so that a seam stays closed when one moves.
 */
export function copiesOf(written: readonly WrittenPoint[], k: number): number[] {
  const p = written[k]?.value;
  if (!p) return [];
  const same = (q: Point3) => q.every((v, i) => Math.abs(v - p[i]) <= 1e-9 * Math.max(1, Math.abs(p[i])));
  return written.flatMap((w, j) => (same(w.value) ? [j] : []));
}

/** `#patch X x y z, …`: one line per patch (16 points each, row by row), as a library shape is written out. */
export function patchLines(patchDirective: string, letter: string, net: readonly Point3[]): string[] {
  const lines: string[] = [];
  for (let k = 0; k + 16 <= net.length; k += 16) {
    lines.push(`${patchDirective} ${letter} ${net.slice(k, k + 16).map(pointText).join(', ')}`);
  }
  return lines;
}
