// The lines of the grammar text that declare surfaces (`#surface X …`, `#patch X …`,
// docs/LANGUAGE.md "Surfaces"): which letters the text declares, and the letter of a line. Small and
// on its own: the studio's Surfaces menu reads the text on every change from the first plant on;
// the editor's gutter marks these lines once CodeMirror has loaded. And the lines that declare
// curve functions (`#curve NAME …`, `#table NAME …`), which the gutter marks too: here, so that the
// gutter's chunk needs no other (the curve editor reads their numbers with ./curve-lines.ts).
import { directiveOfKind, vocabularyIfLoaded, writtenDirective } from '../core';

/** A surface the text declares: its letter and where its first line starts (UTF-16). */
export interface DeclaredSurface {
  letter: string;
  from: number;
}

let linePattern: RegExp | undefined;
/** The two directives as written, to skip a text that has neither without reading its lines. */
let written: string[] = [];

/**
 * A line that declares a surface: `#surface` or `#patch`, then its letter (group 2). Undefined
 * until the vocabulary has arrived.
 */
function surfaceLine(): RegExp | undefined {
  if (linePattern) return linePattern;
  const vocabulary = vocabularyIfLoaded();
  if (!vocabulary) return undefined;
  const names = ['Surface', 'Patch'].map((kind) => writtenDirective(directiveOfKind(vocabulary, kind)));
  written = names;
  linePattern = new RegExp(`^[ \\t]*(${names.join('|')})[ \\t]+([A-Za-z])(?![\\w])`);
  return linePattern;
}

/** The letter the line `line` declares a surface for, or null (also before the vocabulary has arrived). */
export function surfaceLetterOf(line: string): string | null {
  return surfaceLine()?.exec(line)?.[2] ?? null;
}

/** The surfaces `text` declares, in the order their letters first appear. */
export function declaredSurfaces(text: string): DeclaredSurface[] {
  const out: DeclaredSurface[] = [];
  if (!surfaceLine() || !written.some((name) => text.includes(name))) return out;
  let from = 0;
  for (const line of text.split('\n')) {
    const letter = surfaceLetterOf(line);
    if (letter !== null && !out.some((s) => s.letter === letter)) out.push({ letter, from });
    from += line.length + 1;
  }
  return out;
}

let curvePattern: RegExp | undefined;

/**
 * A line that declares a curve function: what comes before its name (group 1), the directive
 * (group 2) and the name (group 3). Undefined until the vocabulary has arrived.
 */
export function curveLinePattern(): RegExp | undefined {
  if (curvePattern) return curvePattern;
  const vocabulary = vocabularyIfLoaded();
  if (!vocabulary) return undefined;
  const names = ['Curve', 'Table'].map((kind) => writtenDirective(directiveOfKind(vocabulary, kind)));
  curvePattern = new RegExp(`^([ \\t]*(${names.join('|')})[ \\t]+)([A-Za-z_][A-Za-z0-9_]*)`);
  return curvePattern;
}

/** The name of the curve function the line `line` declares, or null (also before the vocabulary has arrived). */
export function curveNameOf(line: string): string | null {
  return curveLinePattern()?.exec(line)?.[3] ?? null;
}
