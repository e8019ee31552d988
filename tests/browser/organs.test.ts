// End-to-end: ABOP chapter 5's organs in the view. The cordate leaf (a developmental surface of
// forty thin polygons, no colour in its grammar) shows as a green blade, whole: its polygons keep
// their corners (the leaf image's cut-out no longer trims them) and they are leaf green, not the
// bark brown of the starting colour; the same grammar with ;(0) on its path turns them brown, so
// the count of green pixels can fail. Screenshots of the compound leaf, the cordate leaf and the
// lily at laptop and phone size land in test-results/.
import { writeFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { decodePng, foregroundMask, type Picture } from './pictures';
import { canvasPicture, example, openExample, pasteText, PHONE, PLANT_ONLY, RESULTS, savePage, studioIn, twoFrames, VIEW_CANVAS } from './studio-page';
import { browser, page, problems, useStudio } from './session';

useStudio();

/** Leaf green on screen: green clearly above red and blue (the palette's entry 5, lit and textured). */
const green = (r: number, g: number, b: number) => g > 60 && g > 1.25 * r && g > 1.25 * b;
/** Bark brown: red above green above blue (the palette's entry 0 under the leaf image's pale grain). */
const brown = (r: number, g: number, b: number) => r > 40 && r > 1.03 * g && g > 1.1 * b;

/** Shares of the plant's pixels (not background) that are green and brown. */
function colours(picture: Picture): { plant: number; green: number; brown: number } {
  const mask = foregroundMask(picture);
  let plant = 0;
  let g = 0;
  let b = 0;
  for (let p = 0; p < mask.length; p++) {
    if (!mask[p]) continue;
    plant++;
    const [r, gg, bb] = picture.data.slice(4 * p, 4 * p + 3);
    if (green(r, gg, bb)) g++;
    if (brown(r, gg, bb)) b++;
  }
  return { plant: plant / mask.length, green: g / Math.max(plant, 1), brown: b / Math.max(plant, 1) };
}

/** Scrubs the timeline to `t` and waits for the plant derived to step ⌊t⌋ (a stepwise grammar). */
async function scrubToStep(t: number): Promise<void> {
  await page.getByTestId('timeline-slider').fill(String(t));
  await page.waitForFunction((want) => window.__meristem!.lastStats?.iterations === want, Math.floor(t), { timeout: 60_000 });
  await twoFrames(page);
}

describe('organs of ABOP chapter 5', () => {
  it('draws the cordate leaf as a whole green blade, and brown once the grammar chooses entry 0', async () => {
    expect(await openExample(page, 'abop-5.05-cordate-leaf.lsys')).toBe('ok');
    await page.getByTestId('grid').click();
    const leaf = colours(await canvasPicture(page, 'organs-cordate-leaf-canvas.png'));
    // The heart fills a good part of the view, and nearly all of it is green: the polygons' corners
    // are not cut out (a cut-out fan of 40 thin triangles left about a tenth of the blade).
    expect(leaf.plant).toBeGreaterThan(0.08);
    expect(leaf.green).toBeGreaterThan(0.8);
    const chosen = example('abop-5.05-cordate-leaf.lsys').replace('axiom: F(2)[A][B]', 'axiom: F(2);(0)[A][B]');
    expect(await pasteText(page, chosen)).toBe('ok');
    const brownLeaf = colours(await canvasPicture(page, 'organs-cordate-leaf-brown-canvas.png'));
    expect(brownLeaf.plant).toBeGreaterThan(0.08);
    expect(brownLeaf.green).toBeLessThan(0.05);
    expect(brownLeaf.brown).toBeGreaterThan(0.5);
    await page.getByTestId('grid').click();
    expect(problems).toEqual([]);
  });

  it('plays the cordate leaf as its developmental sequence: at t = 8 the leaf of step 8, smaller, on the same camera', async () => {
    expect(await openExample(page, 'abop-5.05-cordate-leaf.lsys')).toBe('ok');
    await page.getByTestId('grid').click();
    const whole = colours(await canvasPicture(page, 'organs-cordate-leaf-t20-canvas.png'));
    // #dt 1 makes the grammar stepwise: the timeline derives it to step 8, whose rays are at most
    // 7 long, not 19 (the whole plant's mesh grown in would show full-size polygons appearing).
    await scrubToStep(8);
    const young = colours(await canvasPicture(page, 'organs-cordate-leaf-t8-canvas.png'));
    expect(young.plant).toBeGreaterThan(0.005);
    expect(young.plant).toBeLessThan(0.4 * whole.plant);
    expect(young.green).toBeGreaterThan(0.8);
    await scrubToStep(20);
    await page.getByTestId('grid').click();
    expect(problems).toEqual([]);
  });

  it('shows the compound leaf, the cordate leaf and the lily at laptop and phone size', async () => {
    for (const file of ['abop-5.11b-compound-leaf.lsys', 'abop-5.05-cordate-leaf.lsys', 'abop-sec-5.1-lily.lsys', 'abop-sec-5.1-campanula.lsys']) {
      expect(await openExample(page, file)).toBe('ok');
      const name = file.replace('.lsys', '');
      const picture = await canvasPicture(page, `organs-${name}-laptop-canvas.png`);
      await savePage(page, `organs-${name}-laptop.png`);
      expect(colours(picture).green, file).toBeGreaterThan(0.1);
    }
    const phone = await browser.newContext(PHONE);
    try {
      const { page: small, problems: smallProblems } = await studioIn(await phone.newPage());
      for (const file of ['abop-5.11b-compound-leaf.lsys', 'abop-5.05-cordate-leaf.lsys', 'abop-sec-5.1-lily.lsys']) {
        expect(await openExample(small, file)).toBe('ok');
        const name = file.replace('.lsys', '');
        const png = await small.locator(VIEW_CANVAS).screenshot({ style: PLANT_ONLY });
        writeFileSync(new URL(`organs-${name}-phone-canvas.png`, RESULTS), png);
        writeFileSync(new URL(`organs-${name}-phone.png`, RESULTS), await small.screenshot());
        expect(colours(decodePng(png)).green, file).toBeGreaterThan(0.1);
      }
      expect(smallProblems).toEqual([]);
    } finally {
      await phone.close();
    }
  });
});
