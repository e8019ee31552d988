// The text of a curve function's points (`#curve NAME x y, …`, `#table NAME x y …`): the points
// as written, a number written in the line's own style, and the changes that add or remove a
// point with the line's own separators. Only the numbers a change is about are rewritten: the
// rest of the line (its separators, its comment, the other numbers) stays as the user wrote it.
// Pure: the tests read it without a page.
import type { CurveDeclaration, WrittenNumber } from '../../editor/curve-lines';
import type { TextChange } from '../../editor/growth-directives';
import type { Point2 } from './curve-function';

/** A point of a declaration: its value and where its x and its y are written. */
export interface WrittenPoint {
  value: Point2;
  x: WrittenNumber;
  y: WrittenNumber;
}

/** The points of a declaration whose numbers are pairs. */
export function writtenPoints(d: CurveDeclaration): WrittenPoint[] {
  const out: WrittenPoint[] = [];
  for (let k = 0; k + 1 < d.numbers.length; k += 2) {
    const [x, y] = [d.numbers[k], d.numbers[k + 1]];
    out.push({ value: [x.value, y.value], x, y });
  }
  return out;
}

/** The decimals of a number as written (`0.50`: 2, `3`: 0), and whether it shows a trailing zero. */
function decimalsOf(text: string): { decimals: number; trailingZero: boolean } {
  const mantissa = text.split(/[eE]/)[0];
  const dot = mantissa.indexOf('.');
  const decimals = dot < 0 ? 0 : mantissa.length - dot - 1;
  return { decimals, trailingZero: decimals > 0 && mantissa.endsWith('0') };
}

/**
 * The fixed count of decimals the line writes its numbers with (`0.50 1.00 …`: every number with a
 * point has that many, one at least ending in 0), or null: numbers as short as they go.
 */
export function fixedDecimals(d: CurveDeclaration): number | null {
  const written = d.numbers.map((n) => decimalsOf(n.text)).filter((n) => n.decimals > 0);
  if (written.length === 0 || !written.some((n) => n.trailingZero)) return null;
  return written.every((n) => n.decimals === written[0].decimals) ? written[0].decimals : null;
}

/** The decimals that resolve a thousandth of `span` (3 for a span of 1, 1 for 100), 0 to 6. */
export function decimalsFor(span: number): number {
  if (!(span > 0) || !Number.isFinite(span)) return 3;
  return Math.min(6, Math.max(0, Math.ceil(3 - Math.log10(span))));
}

/** `value` written with `decimals` decimals: all of them when `fixed`, else without trailing zeros; never `-0`. */
export function numberText(value: number, decimals: number, fixed = false): string {
  const text = (Number.isFinite(value) ? value : 0).toFixed(decimals);
  if (Number(text) === 0) return fixed ? (0).toFixed(decimals) : '0';
  return fixed || !text.includes('.') ? text : text.replace(/\.?0+$/, '');
}

/** The text between two spans. */
function between(text: string, a: WrittenNumber, b: WrittenNumber): string {
  return text.slice(a.to, b.from);
}

/**
 * The change that adds `inserts` (its x and y as written) as point `k` of the declaration in `text`
 * (1 ≤ k ≤ the number of points: never before the first), after point k − 1, with the line's own
 * separators: the one between x and y, and the one between points.
 */
export function addPointChange(text: string, d: CurveDeclaration, k: number, inserts: readonly [string, string]): TextChange {
  const points = writtenPoints(d);
  const before = points[k - 1];
  const pairSeparator = between(text, before.x, before.y) || ' ';
  const [a, b] = k < points.length ? [before, points[k]] : [points[k - 2] ?? before, before];
  const separator = (a === b ? '' : between(text, a.y, b.x)) || (pairSeparator.includes(',') ? pairSeparator : ', ');
  return { from: before.y.to, to: before.y.to, insert: `${separator}${inserts[0]}${pairSeparator}${inserts[1]}` };
}

/** The change that removes point `k` of the declaration and its separator (the one before it; the first's, the one after it). */
export function removePointChange(d: CurveDeclaration, k: number): TextChange {
  const points = writtenPoints(d);
  if (k === 0) return { from: points[0].x.from, to: points[1]?.x.from ?? points[0].y.to, insert: '' };
  return { from: points[k - 1].y.to, to: points[k].y.to, insert: '' };
}
