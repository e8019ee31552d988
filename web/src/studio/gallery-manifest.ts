// The gallery's manifest: what the header comment of each example says. Read at build time by the
// vite plugin (scripts/gallery-plugin.ts, in node) and by the page (which fetches the result), so
// the format is defined once, here.
//
// An example starts with comment lines: the title on line 1, then `// Source: …` (one line), then
// the description (any further comment lines up to the first line that is not a comment).

/** One example of the gallery. */
export interface GalleryEntry {
  /** File name in `examples/`, e.g. `abop-1.24d.lsys`. */
  file: string;
  title: string;
  /** Where the grammar comes from (the text after `Source:`), or empty. */
  source: string;
  /** The description, its comment lines joined with spaces, or empty. */
  description: string;
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
  return { file, title, source, description };
}

/** The manifest of a set of examples (`[file name, text]`), sorted by file name. */
export function galleryManifest(examples: Iterable<readonly [string, string]>): GalleryEntry[] {
  return [...examples]
    .filter(([file]) => file.endsWith('.lsys'))
    .map(([file, text]) => parseExampleHeader(file, text))
    .sort((a, b) => (a.file < b.file ? -1 : a.file > b.file ? 1 : 0));
}

/** Checks that fetched JSON is a manifest (the page trusts nothing it fetched). */
export function isGalleryManifest(value: unknown): value is GalleryEntry[] {
  return (
    Array.isArray(value) &&
    value.every(
      (e) =>
        typeof e === 'object' &&
        e !== null &&
        ['file', 'title', 'source', 'description'].every((key) => typeof (e as Record<string, unknown>)[key] === 'string'),
    )
  );
}
