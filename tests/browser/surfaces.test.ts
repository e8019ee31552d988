// End-to-end: bicubic surfaces (`#surface`, `#patch`, `~X`) in the view. The organ library laid
// out side by side shows each organ in its colour; a vlab object with cpfg `.s` surfaces (Lychnis),
// picked as a folder's files, imports with `#surface`/`#patch` lines and shows its petals.
// Screenshots land in test-results/ for a person to look at.
import { readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { foregroundShare, type Picture } from './pictures';
import { canvasPicture, editorText, pasteText, savePage, twoFrames } from './studio-page';
import { page, problems, useStudio } from './session';

useStudio();

/** Pixels of `picture` that pass `test`. */
function count(picture: Picture, test: (r: number, g: number, b: number) => boolean): number {
  let n = 0;
  for (let i = 0; i < picture.data.length; i += 4) if (test(picture.data[i], picture.data[i + 1], picture.data[i + 2])) n++;
  return n;
}

/** Pink, as the leaf texture shades the pink petal: red above green, blue not below it (no bark, leaf or orange is). */
const pink = (r: number, g: number, b: number) => r > 130 && r - g > 25 && r - b > 20 && b >= g - 5;
/** Yellow: red and green alike, well above blue (the disk; not the orange ray floret). */
const yellow = (r: number, g: number, b: number) => r > 140 && Math.abs(r - g) < 25 && r - b > 60;

// The library's organs side by side, each in a colour of the default palette: leaf green (5),
// sepal olive (3), petal pink (11), disk yellow (8), ray floret orange (9), facing the camera.
const LIBRARY = `#surface a leaf
#surface b sepal
#surface c petal
#surface d disk
#surface e ray_floret
axiom: ;(5)~a(2)f(0)[-(90)f(1.4)+(90);(3)~b(2)][-(90)f(2.8)+(90);(11)~c(2)][-(90)f(4.2)+(90)f(0.6)^(90);(8)~d(1.4)][-(90)f(5.6)+(90);(9)~e(2)]
`;

describe('surfaces', () => {
  it('draws the organ library: every organ in its colour, shaded', async () => {
    expect(await pasteText(page, LIBRARY)).toBe('ok');
    const picture = await canvasPicture(page, 'surfaces-library-canvas.png');
    await savePage(page, 'surfaces-library.png');
    expect(foregroundShare(picture)).toBeGreaterThan(0.02);
    expect(count(picture, pink), 'petal pixels').toBeGreaterThan(200);
    expect(count(picture, yellow), 'disk pixels').toBeGreaterThan(200);
    expect(problems).toEqual([]);
  });

  it("imports Lychnis with its .s surfaces and shows its pink petals", async () => {
    const dir = new URL('../../crate/tests/import-corpus/vlab/01-Lychnis/', import.meta.url);
    await page.getByTestId('file-input').setInputFiles(readdirSync(dir).map((f) => new URL(f, dir).pathname));
    // The studio asks before it replaces the text typed above: answer until the import is shown.
    const replace = page.getByTestId('confirm-replace-button');
    const imported = () => [...document.querySelectorAll('[data-testid=editor] .cm-line')].some((l) => l.textContent?.startsWith('#surface p contact'));
    for (let tries = 0; !(await page.evaluate(imported)); tries++) {
      if (tries > 600) throw new Error('Lychnis was not imported within 30 s');
      if (await replace.isVisible()) await replace.click();
      await page.waitForTimeout(50);
    }
    await page.waitForFunction(() => window.__meristem?.preview?.lastResult?.source?.includes('#patch l '), undefined, { timeout: 60_000 });
    await twoFrames(page);
    const text = await editorText(page);
    expect(text).toMatch(/^#surface p contact 23.44 4.08 -9.23 /m);
    expect(text).toMatch(/^#patch l /m);
    const picture = await canvasPicture(page, 'surfaces-lychnis-canvas.png');
    await savePage(page, 'surfaces-lychnis.png');
    expect(count(picture, pink), 'petal pixels').toBeGreaterThan(100);
    expect(problems).toEqual([]);
  }, 120_000);
});
