// The language reference in the studio: docs/LANGUAGE.md, rendered to HTML when the site is built
// (scripts/reference-plugin.ts), where the page finds it, and the ids of its rows of modules and
// directives, which the plugin writes and the hover docs and the Help panel link to.

/** Where the rendered reference is, relative to the page. */
export const REFERENCE_PATH = 'reference.html';

/** The id of the reference's row of a module or directive as written: `F` → `ref-F`, `#angle` → `ref-angle`. */
export function referenceAnchor(written: string): string {
  return `ref-${written.replace(/^#/, '')}`;
}
