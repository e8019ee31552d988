// The chapters of The Algorithmic Beauty of Plants (Prusinkiewicz and Lindenmayer, 1990), which
// head the gallery's groups and the course's lessons: one table, so both say the same words.

/** ABOP's chapter titles, by chapter number. */
export const ABOP_CHAPTERS: Readonly<Record<number, string>> = {
  1: 'graphical modeling using L-systems',
  2: 'modeling of trees',
  3: 'developmental models of herbaceous plants',
  4: 'phyllotaxis',
  5: 'models of plant organs',
  6: 'animation of plant development',
  7: 'modeling of cellular layers',
  8: 'fractal properties of plants',
};

/** "ABOP chapter 2: modeling of trees" (or "ABOP chapter 9" for a number the table lacks). */
export function abopChapterHeading(chapter: number): string {
  const title = ABOP_CHAPTERS[chapter];
  return title ? `ABOP chapter ${chapter}: ${title}` : `ABOP chapter ${chapter}`;
}
