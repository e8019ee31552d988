// The lines of the grammar text that declare surfaces (`#surface X …`, `#patch X …`,
// docs/LANGUAGE.md "Surfaces"): which letters the text declares, and the letter of a line. Small and
// on its own: the studio's Surfaces menu reads the text on every change from the first plant on;
// the editor's gutter marks these lines once CodeMirror has loaded.
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
