// The `#define` constants of a grammar text, read by the page (not the core) for the sliders and
// for completion. A constant whose value is a plain number gets a slider: its range comes from a
// `// [min, max]` or `// [min, max, step]` comment on its line, else from its value (see
// `defaultRange`); dragging rewrites the number in place (`formatNumber`).
import { directiveOfKind, languageVocabulary, writtenDirective } from '../core';

/** A `#define NAME VALUE` line: any value (an expression too), for completion. */
export interface DefineName {
  name: string;
  /** The value as written, comment stripped. */
  value: string;
  /** 1-based line. */
  line: number;
}

/** A `#define` whose value is a plain number: what one slider shows and edits. */
export interface DefineConstant {
  name: string;
  value: number;
  /** The number as written. */
  text: string;
  /** Where the number is in the text (UTF-16 offsets, `to` exclusive). */
  from: number;
  to: number;
  /** 1-based line. */
  line: number;
  min: number;
  max: number;
  step: number;
  /** The range was written in a `// [min, max]` comment (not derived from the value). */
  ranged: boolean;
}

const NUMBER = String.raw`-?(?:\d+(?:\.\d*)?|\.\d+)`;

let defineLine: RegExp | undefined;

/** A `#define NAME VALUE // comment` line, the directive spelled as the core's vocabulary does. */
export function definePattern(): RegExp {
  defineLine ??= new RegExp(String.raw`^([ \t]*${escapeRegExp(defineDirective())}[ \t]+)([A-Za-z_]\w*)([ \t]+)(.*?)[ \t]*(?:\/\/(.*))?$`);
  return defineLine;
}

/** `#define` as the vocabulary writes it. */
export function defineDirective(): string {
  return writtenDirective(directiveOfKind(languageVocabulary(), 'Define'));
}

function escapeRegExp(text: string): string {
  return text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
}
const PLAIN_NUMBER = new RegExp(`^${NUMBER}$`);
const RANGE = new RegExp(String.raw`\[\s*(${NUMBER})\s*,\s*(${NUMBER})\s*(?:,\s*(${NUMBER})\s*)?\]`);

/** The lines of `text` with their start offsets. */
function* lines(text: string): Generator<{ text: string; from: number; number: number }> {
  let from = 0;
  let number = 1;
  for (const line of text.split('\n')) {
    yield { text: line.endsWith('\r') ? line.slice(0, -1) : line, from, number };
    from += line.length + 1;
    number++;
  }
}

/** Every `#define` of `text`, in order (a `//` inside the value starts the comment). */
export function defineNames(text: string): DefineName[] {
  const names: DefineName[] = [];
  for (const line of lines(text)) {
    const match = definePattern().exec(line.text);
    if (match && match[4] !== '') names.push({ name: match[2], value: match[4], line: line.number });
  }
  return names;
}

/**
 * The slider range of a value without a range comment: [0, 2·value] for a positive value,
 * [2·value, 0] for a negative one, [−10, 10] for 0.
 */
export function defaultRange(value: number): [number, number] {
  if (value > 0) return [0, 2 * value];
  if (value < 0) return [2 * value, 0];
  return [-10, 10];
}

/** Digits after the decimal point of a number as written (`18.95` → 2, `45` → 0). */
function decimalsOf(text: string): number {
  const point = text.indexOf('.');
  return point < 0 ? 0 : text.length - point - 1;
}

/** The largest power of ten ≤ x (x > 0). */
function powerOfTenBelow(x: number): number {
  return 10 ** Math.floor(Math.log10(x) + 1e-9);
}

/**
 * The slider step: fine enough for the precision the number was written with (`18.95` → 0.01)
 * and for at least 20 positions across the range (a power of ten).
 */
export function defaultStep(text: string, min: number, max: number): number {
  const written = 10 ** -decimalsOf(text);
  const span = max - min;
  return span > 0 ? Math.min(written, powerOfTenBelow(span / 20)) : written;
}

/** Decimals needed to write multiples of `step` exactly (0.01 → 2, 0.5 → 1, 5 → 0). */
export function decimalsForStep(step: number): number {
  for (let decimals = 0; decimals < 12; decimals++) {
    const scaled = step * 10 ** decimals;
    if (Math.abs(scaled - Math.round(scaled)) < 1e-9 * Math.max(1, scaled)) return decimals;
  }
  return 12;
}

/** `value` rounded to a multiple of `step` and written with the step's decimals (never `-0`). */
export function formatNumber(value: number, step: number): string {
  const decimals = decimalsForStep(step);
  const rounded = Math.round(value / step) * step;
  const text = rounded.toFixed(decimals);
  return /^-0(\.0*)?$/.test(text) ? text.slice(1) : text;
}

/** The `#define`s of `text` whose value is a plain number, with their slider ranges. */
export function defineConstants(text: string): DefineConstant[] {
  const constants: DefineConstant[] = [];
  for (const line of lines(text)) {
    const match = definePattern().exec(line.text);
    if (!match || !PLAIN_NUMBER.test(match[4])) continue;
    const numberText = match[4];
    const value = Number(numberText);
    if (!Number.isFinite(value)) continue;
    const from = line.from + match[1].length + match[2].length + match[3].length;
    const range = match[5] === undefined ? null : RANGE.exec(match[5]);
    let min: number;
    let max: number;
    let step: number | undefined;
    let ranged = false;
    if (range && Number(range[1]) < Number(range[2])) {
      [min, max] = [Number(range[1]), Number(range[2])];
      if (range[3] !== undefined && Number(range[3]) > 0) step = Number(range[3]);
      ranged = true;
      // A value outside its written range widens it: the slider must show where the value is.
      min = Math.min(min, value);
      max = Math.max(max, value);
    } else {
      [min, max] = defaultRange(value);
    }
    constants.push({
      name: match[2],
      value,
      text: numberText,
      from,
      to: from + numberText.length,
      line: line.number,
      min,
      max,
      step: step ?? defaultStep(numberText, min, max),
      ranged,
    });
  }
  return constants;
}
