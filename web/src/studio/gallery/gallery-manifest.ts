// The gallery's manifest: what the header comment of each example says. Read at build time by the
// vite plugin (scripts/gallery-plugin.ts, in node) and by the page (which fetches the result), so
// the format is defined once, here.
//
// An example starts with comment lines: the title on line 1, then `// Source: …` (one line), then
// the description (any further comment lines up to the first line that is not a comment). The
// gallery groups examples by where they come from, read off the source (see `exampleGroup`).
import { abopChapterHeading } from './chapters.ts'; // with its extension: the vite config's plugins load this file in node

/** One example of the gallery. */
export interface GalleryEntry {
  /** File name in `examples/`, e.g. `abop-1.24d.lsys`. */
  file: string;
  title: string;
  /** Where the grammar comes from (the text after `Source:`), or empty. */
  source: string;
  /** The description, its comment lines joined with spaces, or empty. */
  description: string;
  /** The gallery's group: an ABOP chapter, a paper or program, or "Other" (see {@link exampleGroup}). */
  group: string;
}

/** The groups that are not ABOP chapters, in the gallery's order after the chapters, each with the words of a source that puts an example in it. */
const OTHER_GROUPS: readonly (readonly [string, RegExp])[] = [
  ["Green's RL-systems", /\bGreen\b/],
  ['Jou, Park and Bahng: particle attributes', /\bJou\b/],
  ['Lparser', /\bLparser\b/],
  ['Open L-systems: plants and their environment', /\b(?:Měch|Palubicki|Runions)\b/],
  ['Other', /(?:)/],
];

/**
 * The group of an example, from its source: a source naming *The Algorithmic Beauty of Plants*
 * is in the chapter of its first figure, equation or section number ("Fig. 2.6a" → "ABOP chapter 2:
 * modeling of trees"); then Green, Jou, Park and Bahng, Lparser, the open L-systems of issue 47 (Měch,
 * Palubicki, Runions); anything else is "Other".
 */
export function exampleGroup(source: string): string {
  if (/Algorithmic Beauty of Plants/i.test(source)) {
    const number = /\b(?:fig|eq|equation|section|sec)\.?\s*(\d+)\./i.exec(source);
    if (number) return abopChapterHeading(Number(number[1]));
  }
  return OTHER_GROUPS.find(([, words]) => words.test(source))![0];
}

/** Where a group stands in the gallery: ABOP chapters by number, then {@link OTHER_GROUPS} in order. */
function groupRank(group: string): number {
  const chapter = /^ABOP chapter (\d+)/.exec(group);
  return chapter ? Number(chapter[1]) : 1000 + OTHER_GROUPS.findIndex(([name]) => name === group);
}

/** Reads the header comment of one example. The title falls back to the file name. */
export function parseExampleHeader(file: string, text: string): GalleryEntry {
  const comments: string[] = [];
  for (const line of text.split(/\r?\n/)) {
    const match = /^\s*\/\/\s?(.*)$/.exec(line);
    if (!match) break;
    comments.push(match[1].trim());
  }
  const title = comments.shift() || file.replace(/\.lsys$/, '');
  let source = '';
  if (comments.length > 0 && /^source:/i.test(comments[0])) source = comments.shift()!.replace(/^source:\s*/i, '');
  const description = comments.filter((line) => line !== '').join(' ');
  return { file, title, source, description, group: exampleGroup(source) };
}

/** The manifest of a set of examples (`[file name, text]`), in the gallery's order: by group, then by file name. */
export function galleryManifest(examples: Iterable<readonly [string, string]>): GalleryEntry[] {
  return [...examples]
    .filter(([file]) => file.endsWith('.lsys'))
    .map(([file, text]) => parseExampleHeader(file, text))
    .sort((a, b) => groupRank(a.group) - groupRank(b.group) || (a.file < b.file ? -1 : a.file > b.file ? 1 : 0));
}

/** Checks that fetched JSON is a manifest (the page trusts nothing it fetched). */
export function isGalleryManifest(value: unknown): value is GalleryEntry[] {
  return (
    Array.isArray(value) &&
    value.every(
      (e) =>
        typeof e === 'object' &&
        e !== null &&
        ['file', 'title', 'source', 'description', 'group'].every((key) => typeof (e as Record<string, unknown>)[key] === 'string'),
    )
  );
}
