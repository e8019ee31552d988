// The curve editor's plot: an SVG with the axes and their ticks, the function's line, the control
// polygon of a `#curve`, the points (the chosen one marked) and the value under the pointer. It
// maps between the function's x y and the SVG's pixels, over a frame that holds every point.
import type { CurveFunctionKind } from '../../editor/curve-lines';
import { curveOutline, type Point2 } from './curve-function';

const SVG = 'http://www.w3.org/2000/svg';

/** The x and y ranges the plot shows. */
export interface Frame {
  x: [number, number];
  y: [number, number];
}

/** Room for the tick labels (left, bottom) and the plot's other sides, in pixels. */
const MARGIN = { left: 44, right: 12, top: 10, bottom: 24 };

/** About `count` round values in `[low, high]` (1, 2 or 5 times a power of ten apart). */
export function ticks(low: number, high: number, count = 5): number[] {
  const span = high - low;
  if (!(span > 0) || !Number.isFinite(span)) return [low];
  const raw = span / count;
  const power = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw) ?? 10 * power;
  const out: number[] = [];
  for (let k = Math.ceil(low / step); k * step <= high + step * 1e-9; k++) out.push(Number((k * step).toPrecision(12)));
  return out;
}

/**
 * The frame that holds `points` and the line between them, with room around them to drag into;
 * y = 0 stays in sight when the values keep one sign (a length, an angle), as funcedit shows its
 * functions from 0: the frame does not magnify a small change into a steep one.
 */
export function frameOf(points: readonly Point2[], outline: readonly Point2[]): Frame {
  const range = (values: number[], pad: number, withZero: boolean): [number, number] => {
    let [low, high] = [Math.min(...values), Math.max(...values)];
    if (!Number.isFinite(low) || !Number.isFinite(high)) return [0, 1];
    // A level line sampled off a spline differs from its level by rounding only: level, then.
    if (high - low <= 1e-9 * Math.max(Math.abs(low), Math.abs(high))) low = high;
    if (withZero && low >= 0) low = 0;
    else if (withZero && high <= 0) high = 0;
    const span = high - low || Math.max(1, Math.abs(low));
    return [low - span * pad, high + span * pad];
  };
  const all = [...points, ...outline];
  return { x: range(all.map((p) => p[0]), 0.04, false), y: range(all.map((p) => p[1]), 0.2, true) };
}

function svg<K extends keyof SVGElementTagNameMap>(tag: K, attributes: Record<string, string | number> = {}): SVGElementTagNameMap[K] {
  const element = document.createElementNS(SVG, tag);
  for (const [name, value] of Object.entries(attributes)) element.setAttribute(name, String(value));
  return element;
}

/** The plot in an `<svg>`: drawn again by {@link draw}; maps pixels and values both ways. */
export class CurvePlot {
  readonly element = svg('svg', { class: 'curve-plot' });
  frame: Frame = { x: [0, 1], y: [0, 1] };
  private width = 400;
  private height = 220;

  /** The pixel of value `p` in the SVG. */
  pixelOf(p: Point2): Point2 {
    const { x, y } = this.frame;
    const w = this.width - MARGIN.left - MARGIN.right;
    const h = this.height - MARGIN.top - MARGIN.bottom;
    return [MARGIN.left + ((p[0] - x[0]) / (x[1] - x[0])) * w, MARGIN.top + (1 - (p[1] - y[0]) / (y[1] - y[0])) * h];
  }

  /** The value at the page's point (clientX, clientY); `inside`: kept inside the frame (else a drag may go past it). */
  valueAt(clientX: number, clientY: number, inside = true): Point2 {
    const box = this.element.getBoundingClientRect();
    const { x, y } = this.frame;
    const w = this.width - MARGIN.left - MARGIN.right;
    const h = this.height - MARGIN.top - MARGIN.bottom;
    const keep = (t: number) => (inside ? Math.min(1, Math.max(0, t)) : t);
    const u = keep((clientX - box.left - MARGIN.left) / w);
    const v = keep((clientY - box.top - MARGIN.top) / h);
    return [x[0] + u * (x[1] - x[0]), y[0] + (1 - v) * (y[1] - y[0])];
  }

  /** Point `p` on the page (CSS pixels). */
  pageOf(p: Point2): { x: number; y: number } {
    const box = this.element.getBoundingClientRect();
    const [u, v] = this.pixelOf(p);
    return { x: box.left + u, y: box.top + v };
  }

  /** The index of the point nearest the page's point, within `reach` pixels, or null. */
  pointAt(points: readonly Point2[], clientX: number, clientY: number, reach: number): number | null {
    let best: number | null = null;
    let distance = reach;
    points.forEach((p, k) => {
      const q = this.pageOf(p);
      const d = Math.hypot(q.x - clientX, q.y - clientY);
      if (d <= distance) [best, distance] = [k, d];
    });
    return best;
  }

  /** Draws the function of `kind` through `points`, the chosen point and the value under the pointer (null: none). */
  draw(kind: CurveFunctionKind, points: readonly Point2[], chosen: number | null, under: Point2 | null): void {
    const box = this.element.getBoundingClientRect();
    this.width = Math.max(120, box.width || 400);
    this.height = Math.max(100, box.height || 220);
    this.element.setAttribute('viewBox', `0 0 ${this.width} ${this.height}`);
    const path = (line: readonly Point2[], className: string) =>
      svg('path', { class: className, d: line.map((p, k) => `${k ? 'L' : 'M'}${this.pixelOf(p).map((v) => v.toFixed(1)).join(' ')}`).join('') });
    const parts: SVGElement[] = [...this.axes()];
    if (kind === 'curve') parts.push(path(points, 'curve-polygon'));
    parts.push(path(this.levelEnds(kind, points), 'curve-line'));
    const dense = points.length > 40;
    points.forEach((p, k) => {
      const [cx, cy] = this.pixelOf(p);
      const r = k === chosen ? 7 : dense ? 2.5 : 5;
      parts.push(svg('circle', { class: k === chosen ? 'curve-point chosen' : 'curve-point', cx, cy, r }));
    });
    if (under) parts.push(...this.readout(under));
    this.element.replaceChildren(...parts);
  }

  /** The line of the function, level before the first point and after the last as `name(x)` reads it. */
  private levelEnds(kind: CurveFunctionKind, points: readonly Point2[]): Point2[] {
    if (points.length === 0) return [];
    const line = curveOutline(kind, points);
    const [first, last] = [line[0], line[line.length - 1]];
    return [[Math.min(this.frame.x[0], first[0]), first[1]], ...line, [Math.max(this.frame.x[1], last[0]), last[1]]];
  }

  /** The grid, the axes' ticks and their labels. */
  private axes(): SVGElement[] {
    const out: SVGElement[] = [];
    const [left, top] = this.pixelOf([this.frame.x[0], this.frame.y[1]]);
    const [right, bottom] = this.pixelOf([this.frame.x[1], this.frame.y[0]]);
    out.push(svg('rect', { class: 'curve-area', x: left, y: top, width: right - left, height: bottom - top }));
    for (const x of ticks(...this.frame.x)) {
      const [u] = this.pixelOf([x, 0]);
      out.push(svg('line', { class: x === 0 ? 'curve-zero' : 'curve-grid', x1: u, x2: u, y1: top, y2: bottom }));
      out.push(Object.assign(svg('text', { class: 'curve-tick', x: u, y: bottom + 16, 'text-anchor': 'middle' }), { textContent: label(x) }));
    }
    for (const y of ticks(...this.frame.y, Math.max(3, Math.round(this.height / 45)))) {
      const [, v] = this.pixelOf([0, y]);
      out.push(svg('line', { class: y === 0 ? 'curve-zero' : 'curve-grid', x1: left, x2: right, y1: v, y2: v }));
      out.push(Object.assign(svg('text', { class: 'curve-tick', x: left - 6, y: v + 4, 'text-anchor': 'end' }), { textContent: label(y) }));
    }
    return out;
  }

  /** A cross-hair at `p` on the line. */
  private readout(p: Point2): SVGElement[] {
    const [u, v] = this.pixelOf(p);
    return [svg('circle', { class: 'curve-under', cx: u, cy: v, r: 3.5 })];
  }
}

/** A tick's label: short (`0.25`, `1e+6` only when huge). */
function label(value: number): string {
  return Math.abs(value) >= 1e5 ? value.toExponential(0) : String(Number(value.toPrecision(6)));
}
