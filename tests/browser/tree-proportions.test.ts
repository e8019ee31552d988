// End-to-end: the trees of ABOP chapter 2 drawn with the book's proportions. Fig 2.8a gives its
// widths in the model's units (#width_unit 1): on screen its trunk must be as thin, against the
// tree's height, as the grammar says, not the baobab that widths in units of the picture's
// diagonal drew. Measured on the pixels of the 3D view; screenshots land in test-results/.
import { writeFileSync } from 'node:fs';
import { chromium, type Browser } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { decodePng, foregroundMask, type Picture } from './pictures';
import { example, openStudio, pasteText, PLANT_ONLY, RESULTS, twoFrames, VIEW_CANVAS, type StudioPage } from './studio-page';

let browser: Browser;
let studio: StudioPage;

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
  studio = await openStudio(browser, 'light', { width: 1280, height: 900 });
});

afterAll(async () => {
  await browser?.close();
});

/** Shows `source` framed in the view and returns its screenshot (also saved as `picture`). */
async function shown(source: string, picture: string): Promise<Picture> {
  const { page } = studio;
  expect(await pasteText(page, source)).toBe('ok');
  await page.getByTestId('frame').click();
  await twoFrames(page);
  const png = await page.locator(VIEW_CANVAS).screenshot({ style: PLANT_ONLY });
  writeFileSync(new URL(picture, RESULTS), png);
  return decodePng(png);
}

/**
 * The plant's drawn height (rows from its lowest to its highest pixel) and its trunk's drawn width:
 * the widest run of plant pixels in the rows between 5 % and 15 % of the height above the base,
 * where the tree is its trunk alone (2.8a's trunk is a third of its height), taking the median
 * row so that an edge's antialiasing does not count.
 */
function trunkAndHeight(picture: Picture): { trunk: number; height: number } {
  const mask = foregroundMask(picture);
  const { width } = picture;
  let top = Infinity;
  let bottom = -Infinity;
  for (let y = 0; y < picture.height; y++)
    for (let x = 0; x < width; x++)
      if (mask[y * width + x]) {
        top = Math.min(top, y);
        bottom = Math.max(bottom, y);
      }
  const height = bottom - top + 1;
  const runs: number[] = [];
  for (let y = Math.round(bottom - 0.15 * height); y <= Math.round(bottom - 0.05 * height); y++) {
    let longest = 0;
    let run = 0;
    for (let x = 0; x < width; x++) {
      run = mask[y * width + x] ? run + 1 : 0;
      longest = Math.max(longest, run);
    }
    runs.push(longest);
  }
  runs.sort((a, b) => a - b);
  return { trunk: runs[Math.floor(runs.length / 2)], height };
}

describe('the trees of chapter 2 on screen', () => {
  it('draws the trunk of Fig 2.8a as thin against its height as the grammar gives it', async () => {
    const tree = example('abop-2.08a-ternary-tree.lsys');
    const { trunk, height } = trunkAndHeight(await shown(tree, 'tree-2.08a-model-widths.png'));
    // By hand from the grammar (crate/tests/abop_chapter2.rs, `ternary_ratio`): after n = 6 steps
    // the trunk is vr⁶ = 1.732⁶ ≈ 27.0 wide; the main axis is 200 lr⁶ + 100 (lr⁶ − 1)/(lr − 1)
    // ≈ 1162.7 long with lr = 1.109: a ratio of about 0.0232 (1/43).
    const expected = 1.732 ** 6 / (200 * 1.109 ** 6 + (100 * (1.109 ** 6 - 1)) / 0.109);
    const ratio = trunk / height;
    expect(height, 'the tree fills the view').toBeGreaterThan(250);
    expect(Math.abs(ratio / expected - 1), `trunk ${trunk} px of ${height} px: ${ratio.toFixed(4)} vs ${expected.toFixed(4)}`).toBeLessThan(0.25);
    // The same grammar with widths in units of the picture's diagonal: the baobab of issue 46,
    // its trunk over a tenth of its height. The measure tells the two apart.
    const baobab = trunkAndHeight(await shown(tree.replace(/^#width_unit .*$/m, ''), 'tree-2.08a-relative-widths.png'));
    expect(baobab.trunk / baobab.height).toBeGreaterThan(0.1);
    expect(studio.problems).toEqual([]);
  });

  it('draws Honda’s tree of Fig 2.6a with its trunk in the grammar’s proportions', async () => {
    const tree = example('abop-2.06a-monopodial.lsys');
    const { trunk, height } = trunkAndHeight(await shown(tree, 'tree-2.06a.png'));
    // The trunk is 10 width units of 0.03 (the example's #width_unit) wide, the tree as high as
    // its trunk's ten internodes 1, 0.9, … 0.9⁹ end to end: (1 − 0.9¹⁰)/0.1 ≈ 6.51.
    const expected = (10 * 0.03) / ((1 - 0.9 ** 10) / 0.1);
    expect(Math.abs(trunk / height / expected - 1), `trunk ${trunk} px of ${height} px`).toBeLessThan(0.25);
    expect(studio.problems).toEqual([]);
  });
});
