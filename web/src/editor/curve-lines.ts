// The lines of the grammar text that declare curve functions (`#curve NAME x y …`, `#table NAME
// x y …`, docs/LANGUAGE.md "Curve functions"): the name a line declares, and a declaration's
// numbers with where each is written, read as the core's parser reads them (a name, then numbers
// separated by spaces or commas, up to a `//` comment). The editor's gutter marks these lines; the
// curve editor (studio/curves) reads and rewrites their numbers. Pure but for the vocabulary.
import { directiveOfKind, vocabularyIfLoaded, writtenDirective } from '../core';
import { curveLinePattern } from './surface-lines';

/** How a declaration reads its points: a B-spline's control points, or a table's corners. */
export type CurveFunctionKind = 'curve' | 'table';

/** A number of a declaration: its value, its text and where it is written (UTF-16). */
export interface WrittenNumber {
  value: number;
  text: string;
  from: number;
  to: number;
}

/** A `#curve` or `#table` line of the text. */
export interface CurveDeclaration {
  kind: CurveFunctionKind;
  name: string;
  /** The directive as written (`#curve`), for messages. */
  directive: string;
  /** Where the line starts, and where it ends before its newline (UTF-16). */
  lineFrom: number;
  lineTo: number;
  /** Where the numbers may be written: after the name, up to the comment or the line's end (UTF-16). */
  argsFrom: number;
  argsTo: number;
  /** The numbers, x y x y …, in the order written. */
  numbers: WrittenNumber[];
  /** Why the numbers cannot be edited as points (a word that is no number, a missing y), or null. */
  problem: string | null;
}

/** A number as the core reads one: decimal, with an optional sign and exponent. */
const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

/** The directives as written, and the kind each declares; empty until the vocabulary has arrived. */
function kinds(): Record<string, CurveFunctionKind> {
  const vocabulary = vocabularyIfLoaded();
  if (!vocabulary) return {};
  const [curve, table] = ['Curve', 'Table'].map((kind) => writtenDirective(directiveOfKind(vocabulary, kind)));
  return { [curve]: 'curve', [table]: 'table' };
}

/** Where a `//` comment starts in `rest` (after a blank, as the core's parser has it), or its length. */
function commentStart(rest: string): number {
  for (let i = rest.indexOf('//'); i >= 0; i = rest.indexOf('//', i + 1)) {
    const afterBlank = i === 0 || /\s/.test(rest[i - 1]);
    if (afterBlank && rest[i + 2] !== '/' && rest[i - 1] !== '/') return i;
  }
  return rest.length;
}

/** The declaration on the line `line` that starts at `lineFrom` in the text, or null when it declares none. */
export function curveDeclarationOn(line: string, lineFrom: number): CurveDeclaration | null {
  const match = curveLinePattern()?.exec(line);
  if (!match) return null;
  const directive = match[2];
  const argsFrom = match[0].length;
  const rest = line.slice(argsFrom);
  const argsTo = argsFrom + commentStart(rest);
  const numbers: WrittenNumber[] = [];
  let problem: string | null = null;
  const args = line.slice(argsFrom, argsTo);
  if (args.includes('/*')) problem = `a comment stands among its numbers`;
  for (const word of args.matchAll(/[^\s,]+/g)) {
    if (problem) break;
    const value = Number(word[0]);
    if (!NUMBER.test(word[0]) || !Number.isFinite(value)) problem = `'${word[0]}' is not a number`;
    const from = lineFrom + argsFrom + word.index;
    numbers.push({ value, text: word[0], from, to: from + word[0].length });
  }
  if (!problem && numbers.length % 2 === 1) problem = `its ${numbers.length} numbers are not pairs x y`;
  return { kind: kinds()[directive], name: match[3], directive, lineFrom, lineTo: lineFrom + line.length, argsFrom: lineFrom + argsFrom, argsTo: lineFrom + argsTo, numbers, problem };
}

/** Every curve function `text` declares, in the order written. */
export function curveDeclarations(text: string): CurveDeclaration[] {
  const out: CurveDeclaration[] = [];
  if (!curveLinePattern() || !Object.keys(kinds()).some((name) => text.includes(name))) return out;
  let from = 0;
  for (const line of text.split('\n')) {
    const found = line.includes('#') ? curveDeclarationOn(line, from) : null;
    if (found) out.push(found);
    from += line.length + 1;
  }
  return out;
}
