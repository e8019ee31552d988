// A picked segment's `?E` and its reply in words (issue 47, "the reply of a picked ?E shown with
// the module"): the communication module of the branch at the picked module (the first after it on
// its branch, else the last before it), its values named by the programs' reply words, e.g.
// "?E(0.42, 0.1, 0.9, 0.4): exposure 0.42, towards (0.1, 0.9, 0.4)".

/** How far from the picked module the `?E` is looked for, each way (modules of the derived string). */
export const REPLY_REACH = 400;

/** A found `?E`: its module index, its text and its values. */
export interface PickedQuery {
  module: number;
  text: string;
  values: number[];
}

/**
 * The `?E` of the branch at `picked`, among `texts` (the module texts from index `first`): the first
 * after it on its own branch (nested branches skipped, up to the branch's end), else the last before
 * it on its branch. `query` is the module's name (from the vocabulary), `open` and `close` the
 * branch brackets.
 */
export function branchQuery(texts: readonly string[], first: number, picked: number, names: { query: string; open: string; close: string }): PickedQuery | null {
  const isQuery = (text: string) => text === names.query || text.startsWith(`${names.query}(`);
  const found = (i: number): PickedQuery => ({ module: first + i, text: texts[i], values: valuesOf(texts[i]) });
  // From `start` by `step`: a bracket `into` enters a nested branch, `outOf` leaves one (or, at
  // the picked module's own depth, ends the search).
  const scan = (start: number, step: 1 | -1, into: string, outOf: string): PickedQuery | null => {
    let depth = 0;
    for (let i = start; i >= 0 && i < texts.length; i += step) {
      const text = texts[i];
      if (text === into) depth++;
      else if (text === outOf) {
        if (depth === 0) return null;
        depth--;
      } else if (depth === 0 && isQuery(text)) return found(i);
    }
    return null;
  };
  const at = picked - first;
  return scan(at + 1, 1, names.open, names.close) ?? scan(at - 1, -1, names.close, names.open);
}

/** The numbers of a module's text `X(1, -2.5e-3)`. */
function valuesOf(text: string): number[] {
  const open = text.indexOf('(');
  if (open < 0 || !text.endsWith(')')) return [];
  return text
    .slice(open + 1, -1)
    .split(',')
    .map((part) => Number(part.trim()))
    .filter((n) => Number.isFinite(n));
}

/** A number as the reply shows it: at most 3 decimals. */
function shown(x: number): string {
  return String(Number(x.toFixed(3)));
}

/**
 * The reply in words: `?E(0.42, 0.1, 0.9, 0.4): exposure 0.42, towards (0.1, 0.9, 0.4)`. Each
 * program's direction (`dx dy dz`) is one "towards (…)"; the other values by their names.
 */
export function replyInWords(query: PickedQuery, replies: readonly string[], name: string): string {
  const { values } = query;
  const words: string[] = [];
  for (let i = 0; i < replies.length && i < values.length; i++) {
    if (replies[i] === 'dx' && replies[i + 1] === 'dy' && replies[i + 2] === 'dz' && i + 2 < values.length) {
      words.push(`towards (${values.slice(i, i + 3).map(shown).join(', ')})`);
      i += 2;
    } else {
      words.push(`${replies[i]} ${shown(values[i])}`);
    }
  }
  const head = `${name}(${values.map(shown).join(', ')})`;
  if (values.length < replies.length) words.push(`(${replies.slice(values.length).join(' ')} not kept: the module has ${values.length} parameters)`);
  return words.length > 0 ? `${head}: ${words.join(', ')}` : `${head}: no reply (no program answers)`;
}
