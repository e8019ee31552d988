// What the curve editor edits on a `#curve`/`#table` line, and how each edit is written: the line's
// own points (a move rewrites that point's x and y), or, for a table the vlab importer sampled from
// a cpfg/lpfg function file (`.func`: the comment above the table keeps its control points, as
// `meristem import` writes it), the function's control points: a move rewrites them in the comment
// and the table's samples with them, as funcedit edits the function and cpfg samples it.
// Pure: the tests read it without a page.
import type { CurveDeclaration, CurveFunctionKind, WrittenNumber } from '../../editor/curve-lines';
import type { TextChange } from '../../editor/growth-directives';
import type { PointSpan } from '../surfaces/point-text';
import { curveValue, type Point2 } from './curve-function';
import { addPointChange, removePointChange, writtenPoints, type WrittenPoint } from './curve-text';

/** The points of a line and how an edit of them is written. */
export interface CurveSource {
  declaration: CurveDeclaration;
  /** How the points draw and read: a B-spline's control points, or a table's corners. */
  kind: CurveFunctionKind;
  points: WrittenPoint[];
  /** What the points are, for the status line. */
  description: string;
  /** The spans a move of point `k` rewrites. */
  spansOf(k: number): PointSpan[];
  /** What a move of point `k` writes at {@link spansOf}, given its x and y as written. */
  insertsOf(k: number, texts: readonly [string, string]): string[];
  /** The changes that add a point (its x and y as written) as point `k`. */
  addChanges(text: string, k: number, texts: readonly [string, string]): TextChange[];
  /** The changes that remove point `k`. */
  removeChanges(k: number): TextChange[];
}

/** The source of a declaration whose numbers are pairs: the importer's sampled function, else its own points. */
export function curveSource(text: string, declaration: CurveDeclaration): CurveSource {
  return sampledSource(text, declaration) ?? ownSource(declaration);
}

/** The line's own points: the first and the last keep their x (their y alone is written). */
function ownSource(declaration: CurveDeclaration): CurveSource {
  const points = writtenPoints(declaration);
  const end = (k: number) => k === 0 || k === points.length - 1;
  const what = declaration.kind === 'curve' ? 'control points of a B-spline' : 'points joined by straight lines';
  return {
    declaration,
    kind: declaration.kind,
    points,
    description: `${points.length} ${what}`,
    spansOf: (k) => (end(k) ? [points[k].y] : [points[k].x, points[k].y]),
    insertsOf: (k, texts) => (end(k) ? [texts[1]] : [...texts]),
    addChanges: (text, k, texts) => [addPointChange(text, declaration, k, texts)],
    removeChanges: (k) => [removePointChange(declaration, k)],
  };
}

/** The importer's comment above a sampled table: its name, its control points (group 2) and its sample count. */
const SAMPLED = /^[ \t]*\/\/ ([A-Za-z_][A-Za-z0-9_]*): [^\n]*?, control points ([-+0-9.eE ]+); \w+ reads it through (\d+) samples, as here[ \t]*$/d;

/** A number as the importer writes a sample's x: 12 significant digits, as short as they go. */
function sampleX(value: number): string {
  return value === 0 ? '0' : String(Number(value.toPrecision(12)));
}

/** A sample's y as the importer writes it: 7 significant digits (cpfg's floats), no trailing zeros, never `-0`. */
export function sampleY(value: number): string {
  if (value === 0 || !Number.isFinite(value)) return '0';
  const digits = Math.min(12, Math.max(0, 6 - Math.floor(Math.log10(Math.abs(value)))));
  const text = value.toFixed(digits).replace(/(\.\d*?)0+$/, '$1').replace(/\.$/, '');
  return text === '-0' ? '0' : text;
}

/** The table's numbers: `samples` samples of the spline of `points` at x = 0, 1/(n − 1), … 1, as the importer writes them. */
export function samplesText(points: readonly Point2[], samples: number): string {
  return Array.from({ length: samples }, (_, i) => {
    const x = i / (samples - 1);
    return `${sampleX(x)} ${sampleY(curveValue('curve', points, x))}`;
  }).join(' ');
}

/** The control points of a sampled function, when the comment on the line above the table holds them. */
function sampledSource(text: string, declaration: CurveDeclaration): CurveSource | null {
  if (declaration.kind !== 'table' || declaration.lineFrom === 0) return null;
  const lineFrom = text.lastIndexOf('\n', declaration.lineFrom - 2) + 1;
  const match = SAMPLED.exec(text.slice(lineFrom, declaration.lineFrom - 1));
  const samples = Number(match?.[3]);
  const group = match?.indices?.[2];
  if (!match || !group || match[1] !== declaration.name || samples !== declaration.numbers.length / 2 || samples < 3) return null;
  const numbersFrom = lineFrom + group[0];
  const numbers: WrittenNumber[] = [...match[2].matchAll(/\S+/g)].map((w) => ({ value: Number(w[0]), text: w[0], from: numbersFrom + w.index, to: numbersFrom + w.index + w[0].length }));
  if (numbers.length % 2 === 1 || numbers.length < 8 || numbers.some((n) => !Number.isFinite(n.value))) return null;
  const controls: CurveDeclaration = { ...declaration, kind: 'curve', numbers, problem: null };
  const points = writtenPoints(controls);
  const spans = [
    { from: numbersFrom, to: numbersFrom + match[2].trimEnd().length },
    { from: declaration.numbers[0].from, to: declaration.numbers[declaration.numbers.length - 1].to },
  ];
  /** The texts of both spans for these points (each as written). */
  const write = (texts: string[][], values: Point2[]) => [texts.map((t) => t.join(' ')).join(' '), samplesText(values, samples)];
  const texts = points.map((p) => [p.x.text, p.y.text]);
  const values = points.map((p) => p.value);
  const change = (inserts: string[]) => spans.map((s, k) => ({ ...s, insert: inserts[k] }));
  const value = (written: readonly [string, string]): Point2 => [Number(written[0]), Number(written[1])];
  return {
    declaration: controls,
    kind: 'curve',
    points,
    description: `${points.length} control points of a function file's B-spline, written as the table's ${samples} samples`,
    spansOf: () => spans,
    insertsOf: (k, moved) => write(spliced(texts, k, 1, [...moved]), spliced(values, k, 1, value(moved))),
    addChanges: (_, k, added) => change(write(spliced(texts, k, 0, [...added]), spliced(values, k, 0, value(added)))),
    removeChanges: (k) => change(write(spliced(texts, k, 1), spliced(values, k, 1))),
  };
}

/** A copy of `items` with `count` items from `k` replaced by `inserted`. */
function spliced<T>(items: readonly T[], k: number, count: number, ...inserted: T[]): T[] {
  const copy = [...items];
  copy.splice(k, count, ...inserted);
  return copy;
}
