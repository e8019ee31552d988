// End-to-end: what a lecturer needs to teach a derivation (issue 17). The view follows the plant
// (stepping, the growth timeline in either camera, a typed grammar, the Refit hint after the camera was moved);
// the derivation view links each module of a step to what it became and lights it up in the plant;
// Stages draws iterations side by side and downloads them as PNG and SVG; a click on the plant and
// the cursor on its production report the same count. Pixels are read from the real canvas.
import { readFileSync, writeFileSync } from 'node:fs';
import { describe, expect, inject, it } from 'vitest';
import { colourShare, decodePng, foregroundExtent, foregroundMask, foregroundOverlap, foregroundShare, type Picture } from './pictures';
import { browser, page, problems, useStudio } from './session';
import { canvasPicture, findPixel, RESULTS, generation, HIGHLIGHT_PIXELS, loseAndRestoreContext, nextBuild, openExample, PHONE, replaceTextByTouch, savePage, twoFrames, openTimelineMenu, VIEW_CANVAS } from './studio-page';

useStudio();

/** Puts the cursor at the end of the first line of the editor that starts with `start`. */
async function cursorOn(start: string): Promise<void> {
  await page.getByTestId('editor').locator('.cm-line', { hasText: new RegExp(`^${start.replace(/[()]/g, '\\$&')}`) }).first().click();
  await page.keyboard.press('End');
}

/** The plant's extent on the 3D canvas (shares of its width and height), with the grid off. */
async function plantExtent(name: string): Promise<{ width: number; height: number }> {
  return foregroundExtent(await canvasPicture(page, name));
}

/**
 * The middle of the run of pixels passing `test` through `spot` along its row: a click there hits a
 * two-pixel line that a click on the run's edge, half a pixel off, may miss.
 */
async function acrossTheMiddle(p: typeof page, spot: { x: number; y: number }, test: (r: number, g: number, b: number) => boolean): Promise<{ x: number; y: number }> {
  const picture = await canvasPicture(p, 'across-the-middle.png');
  const box = (await p.locator(VIEW_CANVAS).boundingBox())!;
  const scale = picture.width / box.width;
  const y = Math.floor((spot.y - box.y) * scale);
  const passes = (x: number) => {
    const i = 4 * (y * picture.width + x);
    return x >= 0 && x < picture.width && test(picture.data[i], picture.data[i + 1], picture.data[i + 2]);
  };
  let [left, right] = [Math.floor((spot.x - box.x) * scale), Math.floor((spot.x - box.x) * scale)];
  while (passes(left - 1)) left--;
  while (passes(right + 1)) right++;
  return { x: box.x + (left + right + 1) / 2 / scale, y: spot.y };
}

/** Chooses the timeline's camera: on the final plant, or following the growth. */
async function chooseGrowthCamera(kind: 'final' | 'follow'): Promise<void> {
  await openTimelineMenu(page);
  await page.getByTestId('timeline-camera').selectOption(kind);
  await page.keyboard.press('Escape');
}

/** Scrubs the timeline to `t` and waits for the plant at that time on screen (growth arrays built first). */
async function scrubTo(t: number): Promise<void> {
  await page.getByTestId('timeline-slider').fill(String(t));
  await page.waitForFunction((want) => {
    const { t, span } = window.__meristem!.growth!();
    return span !== null && (t === want || (t === null && want >= span)) && window.__meristem?.preview?.settled === true;
  }, t, { timeout: 60_000 });
  await twoFrames(page);
}

/** Decodes a download started by clicking `testId`. */
async function download(testId: string): Promise<{ name: string; bytes: Buffer }> {
  const [file] = await Promise.all([page.waitForEvent('download'), page.getByTestId(testId).click()]);
  return { name: file.suggestedFilename(), bytes: readFileSync((await file.path())!) };
}

describe('the view follows the plant', () => {
  it('fills the view after stepping ABOP 1.24d down to two iterations', async () => {
    expect(await openExample(page, 'abop-1.24d.lsys')).toBe('ok');
    await page.getByTestId('grid').click(); // only the plant differs from the background
    for (let n = 6; n >= 2; n--) {
      const before = await generation(page);
      await page.getByTestId('step-back').click();
      await nextBuild(page, before);
    }
    expect(await page.getByTestId('iterations').inputValue()).toBe('2');
    const extent = await plantExtent('follow-1.24d-n2.png');
    expect(extent.height, 'the two-step plant is framed, not a speck at the bottom').toBeGreaterThan(0.7);
    expect(await page.getByTestId('refit').isHidden()).toBe(true);
    expect(problems).toEqual([]);
  });

  it('frames the growth as it grows when the timeline’s camera follows it', async () => {
    await page.getByTestId('iterations').fill(''); // the grammar's 7
    await page.getByTestId('timeline-slider').waitFor();
    await chooseGrowthCamera('follow');
    for (const t of [1, 3.5, 6]) {
      await scrubTo(t);
      const extent = await plantExtent(`follow-growth-t${t}.png`);
      expect(extent.height, `t = ${t} fills the view`).toBeGreaterThan(0.6);
    }
    expect(problems).toEqual([]);
  });

  it("shows the growth in the final plant's frame, by default", async () => {
    await chooseGrowthCamera('final');
    await scrubTo(2);
    const early = await plantExtent('final-frame-t2.png');
    await scrubTo(6.9);
    const late = await plantExtent('final-frame-t7.png');
    expect(late.height, 'the grown plant fills the frame').toBeGreaterThan(0.7);
    expect(early.height, 'an early time is small inside that frame').toBeLessThan(0.3 * late.height);
    await scrubTo(7);
    expect(problems).toEqual([]);
  });

  it('frames a newly typed grammar, and hints at a refit once the camera was moved', async () => {
    let before = await generation(page);
    await page.getByTestId('editor').locator('.cm-content').click();
    await page.keyboard.press('Control+A');
    await page.keyboard.insertText('#angle 90\naxiom: F\nF -> F+F-F-F+F\n#iterations 3\n');
    await nextBuild(page, before);
    const typed = await plantExtent('follow-typed.png');
    expect(Math.max(typed.width, typed.height), 'the Koch curve fills the view').toBeGreaterThan(0.7);

    // Zoom in with the wheel: the user moved the camera.
    const box = (await page.getByTestId('viewport').boundingBox())!;
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.wheel(0, -600);
    await twoFrames(page);
    const moved = await page.evaluate(() => window.__meristem!.cameraPose!());
    before = await generation(page);
    await page.getByTestId('step-back').click();
    await nextBuild(page, before);
    await twoFrames(page);
    expect(await page.evaluate(() => window.__meristem!.cameraPose!()), 'the camera stays where the user put it').toEqual(moved);
    await expect.poll(() => page.getByTestId('refit').isVisible()).toBe(true);
    await savePage(page, 'follow-refit-hint.png');
    await page.getByTestId('refit').click();
    expect(await page.getByTestId('refit').isHidden()).toBe(true);
    const refitted = await plantExtent('follow-refitted.png');
    expect(Math.max(refitted.width, refitted.height)).toBeGreaterThan(0.7);
    await page.getByTestId('grid').click();
    expect(problems).toEqual([]);
  });
});

describe('the derivation view', () => {
  it("links each module of eq. 1.7's first step to what it became, and lights it up in the plant", async () => {
    expect(await openExample(page, 'abop-eq-1.7.lsys')).toBe('ok');
    await page.getByTestId('tab-derivation').click();
    const view = page.getByTestId('derivation');
    const rows = view.locator('.dv-row');
    await expect.poll(() => rows.count()).toBe(5);
    const bands = (step: number) => view.locator(`.dv-row[data-step="${step}"] .dv-group`).allTextContents();
    expect(await bands(0)).toEqual(['B(2)', 'A(4,4)']);
    expect(await bands(1), 'B(2) became B(1); A(4,4) became B(4)A(1,0)').toEqual(['B(1)', 'B(4)A(1,0)']);
    expect(await bands(4)).toEqual(['C', 'B(1)', 'A(8,7)']);
    expect(await view.locator('.dv-tree').count(), 'a derivation tree for a short derivation').toBe(1);

    // Hover A(4,4) of step 0: the two modules it became are marked, and said in words.
    await view.locator('.dv-row .dv-m[data-step="0"][data-i="1"]').hover();
    await expect.poll(() => view.locator('.dv-row .dv-child').allTextContents()).toEqual(['B(4)', 'A(1,0)']);
    expect(await view.locator('.dv-tree .dv-child').allTextContents(), 'and in the tree').toEqual(['B(4)', 'A(1,0)']);
    // Hover B(4) of step 1: where it came from, the rule with its condition, marked in the editor.
    await view.locator('.dv-row .dv-m[data-step="1"][data-i="1"]').hover();
    const status = page.getByTestId('derivation-status');
    await expect.poll(() => status.textContent()).toBe('Step 1: B(4) is one of the 2 modules A(4,4) became, by rule 2 (line 12: A(x,y): y>3 -> B(x)A(x/y,0)); y>3 held.');
    await expect.poll(() => page.locator('.cm-picked-production').textContent()).toBe('A(x,y): y>3 -> B(x)A(x/y,0)');
    expect(await view.locator('.dv-row .dv-parent').textContent()).toBe('A(4,4)');
    const lit = await canvasPicture(page, 'derivation-hover.png');
    expect(colourShare(lit, HIGHLIGHT_PIXELS.produced), 'what grew from B(4) is lit up in the plant').toBeGreaterThan(0.02);
    await savePage(page, 'derivation-view.png');
    await page.mouse.move(0, 0);
    await expect.poll(() => page.locator('.cm-picked-production').count()).toBe(0);
    expect(problems).toEqual([]);
  });

  it('shows the last step module by module, virtualised, when the derivation is long', async () => {
    expect(await openExample(page, 'abop-1.24d.lsys')).toBe('ok');
    const view = page.getByTestId('derivation');
    await expect.poll(() => view.locator('.dv-pair').count()).toBeGreaterThan(5);
    expect(await view.locator('.dv-pair').count(), 'only the rows in view are in the page').toBeLessThan(100);
    const first = view.locator('.dv-pair').first();
    expect(await first.locator('.dv-m').textContent()).toBe('F');
    expect(await first.locator('.dv-group').textContent()).toBe('FF');
    await first.hover();
    await expect.poll(() => page.getByTestId('derivation-status').textContent()).toBe('F (module 0 of step 6) became 2 modules of step 7, by rule 2 (line 8: F -> FF).');
    await view.evaluate((element) => (element.scrollTop = element.scrollHeight));
    await expect.poll(async () => Number(await view.locator('.dv-pair').last().getAttribute('data-j'))).toBeGreaterThan(4000);
    await page.getByTestId('tab-string').click();
    expect(problems).toEqual([]);
  });
});

describe('the derivation view on a touch screen', () => {
  it('keeps a tapped module lit up in the plant once the finger is lifted (touch has no hover to keep)', async () => {
    const context = await browser.newContext(PHONE);
    const phone = await context.newPage();
    const phoneProblems: string[] = [];
    phone.on('pageerror', (e) => phoneProblems.push(`page error: ${e.message}`));
    phone.on('console', (m) => m.type() === 'error' && phoneProblems.push(`console error: ${m.text()}`));
    await phone.goto(inject('studioUrl'));
    await phone.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
    await phone.evaluate(() => window.__meristem?.ready);
    // Eq. 1.7, typed in the grammar's pane; then the plant's, with the Derivation tab under it.
    await phone.getByTestId('pane-toggle').tap();
    expect(await replaceTextByTouch(phone, readFileSync(new URL('../../public/examples/abop-eq-1.7.lsys', import.meta.url), 'utf8'))).toBe('ok');
    await phone.getByTestId('pane-toggle').tap();
    await phone.getByTestId('tab-derivation').tap();
    const view = phone.getByTestId('derivation');
    const chip = view.locator('.dv-row .dv-m[data-step="1"][data-i="1"]');
    await chip.scrollIntoViewIfNeeded();
    const box = (await chip.boundingBox())!;
    await phone.touchscreen.tap(box.x + box.width / 2, box.y + box.height / 2);
    await expect.poll(() => phone.getByTestId('derivation-status').textContent()).toMatch(/^Step 1: B\(4\) is one of the 2 modules A\(4,4\) became/);
    expect(await chip.getAttribute('class'), 'still marked after the tap').toContain('dv-hover');
    const lit = await canvasPicture(phone, 'derivation-tap-phone.png');
    expect(colourShare(lit, HIGHLIGHT_PIXELS.produced), 'what grew from B(4) stays lit up in the plant').toBeGreaterThan(0.02);
    expect(phoneProblems).toEqual([]);
    await context.close();
  });
});

describe('the context panel', () => {
  it("reports the same count for a click on one of 1.24d's F segments as for the cursor on F -> FF", async () => {
    const before = await generation(page);
    await page.getByTestId('iterations').fill('4'); // segments wide enough on screen to click
    await nextBuild(page, before);
    await cursorOn('F ->');
    const summary = page.getByTestId('explain-summary');
    await expect.poll(() => summary.getAttribute('data-fired')).not.toBeNull();
    const fired = await summary.getAttribute('data-fired');
    expect(Number(fired), 'every F of step 3 was rewritten').toBeGreaterThan(10);
    await expect.poll(async () => (await findPixel(page, HIGHLIGHT_PIXELS.produced)) !== null).toBe(true);
    const spot = await acrossTheMiddle(page, (await findPixel(page, HIGHLIGHT_PIXELS.produced))!, HIGHLIGHT_PIXELS.produced);
    await cursorOn('axiom');
    await page.mouse.click(spot.x, spot.y);
    await expect.poll(() => summary.textContent()).toMatch(/^This F \(module \d+ of the derived string\) was written by rule 2 \(line 8: F -> FF\) from F \(module \d+ of the step before\)\./);
    expect(await summary.getAttribute('data-fired'), 'the same count as the cursor on the production').toBe(fired);
    expect(await page.getByTestId('highlight-legend').isVisible(), 'the colours are explained').toBe(true);
    expect(await page.getByTestId('highlight-legend').locator('li').allTextContents()).toEqual(['written', 'left context', 'right context', 'picked']);
    expect(problems).toEqual([]);
  });
});

describe('Stages', () => {
  it('draws 1.24d at n = 1 … 5 side by side and downloads them as one PNG and one SVG', async () => {
    expect(await openExample(page, 'abop-1.24d.lsys')).toBe('ok');
    await page.getByTestId('stages-toggle').click();
    await page.getByTestId('stages-from').fill('1');
    await page.getByTestId('stages-to').fill('5');
    const status = page.getByTestId('stages-status');
    const captions = page.getByTestId('stages-figure').locator('.stage-caption');
    await expect.poll(() => captions.allTextContents(), { timeout: 60_000 }).toEqual(['n = 1', 'n = 2', 'n = 3', 'n = 4', 'n = 5']);
    expect(await status.textContent()).toBe('5 plants at one scale');
    await savePage(page, 'stages.png');

    const png = await download('stages-png');
    expect(png.name).toBe('abop-1.24d-stages.png');
    writeFileSync(new URL('stages-download.png', RESULTS), png.bytes);
    const picture = decodePng(png.bytes);
    expect(picture.width).toBe(5 * 420);
    // Each column holds a plant (above its caption), and the plants grow from left to right.
    const heights: number[] = [];
    for (let c = 0; c < 5; c++) {
      const column = crop(picture, Math.round((c * picture.width) / 5), Math.round(picture.width / 5), Math.round(picture.height * 0.9));
      expect(foregroundShare(column) * column.width * column.height, `column ${c + 1} holds a plant`).toBeGreaterThan(10);
      heights.push(foregroundExtent(column).height);
    }
    for (let c = 1; c < 5; c++) expect(heights[c], `n = ${c + 1} is taller than n = ${c}`).toBeGreaterThan(heights[c - 1]);

    const svg = (await download('stages-svg')).bytes.toString('utf8');
    expect(svg.match(/<g transform="translate/g)).toHaveLength(5);
    expect([...svg.matchAll(/<text [^>]*>([^<]*)<\/text>/g)].map((m) => m[1])).toEqual(['n = 1', 'n = 2', 'n = 3', 'n = 4', 'n = 5']);
    expect(await status.textContent()).toBe('Saved the figure as an SVG');

    // The browser takes the figure's WebGL context away and gives it back: the plants come back.
    const figureCanvas = page.getByTestId('stages-figure').locator('canvas');
    const shown = decodePng(await figureCanvas.screenshot());
    await loseAndRestoreContext(figureCanvas);
    const restored = decodePng(await figureCanvas.screenshot());
    expect(foregroundOverlap(shown, restored), 'the stages drawn again').toBeGreaterThan(0.9);

    // A range too wide is refused in words; closing Stages brings the 3D view back.
    await page.getByTestId('stages-to').fill('20');
    await expect.poll(() => status.textContent()).toMatch(/^At most 10 iterations side by side/);
    await page.getByTestId('stages-toggle').click();
    expect(await page.getByTestId('stages').isHidden()).toBe(true);
    expect(problems).toEqual([]);
  });
});

describe('Stages on a phone', () => {
  it('lays out the tiles in CSS pixels on a dense screen', async () => {
    const phone = await browser.newPage({ viewport: { width: 390, height: 844 }, deviceScaleFactor: 3 });
    await phone.goto(inject('studioUrl'));
    await phone.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
    await phone.getByTestId('stages-toggle').click();
    await expect.poll(() => phone.getByTestId('stages-status').getAttribute('data-state'), { timeout: 60_000 }).toBe('done');
    await twoFrames(phone);
    const figure = phone.getByTestId('stages-figure');
    const png = await figure.locator('canvas').screenshot();
    writeFileSync(new URL('stages-phone.png', RESULTS), png);
    const picture = decodePng(png);
    const columns = await figure.locator('.stage-caption').count();
    expect(columns).toBe(5);
    for (let c = 0; c < columns; c++) {
      const column = crop(picture, Math.round((c * picture.width) / columns), Math.floor(picture.width / columns), Math.round(picture.height * 0.9));
      const mask = foregroundMask(column);
      const xs = [...mask.keys()].filter((p) => mask[p]).map((p) => p % column.width);
      expect(xs.length, `column ${c + 1} holds a plant`).toBeGreaterThan(10);
      const centre = (Math.min(...xs) + Math.max(...xs)) / 2 / column.width;
      expect(centre, `the plant of column ${c + 1} stands in its middle`).toBeGreaterThan(0.35);
      expect(centre).toBeLessThan(0.65);
    }
    await phone.close();
  });
});

/** The part of `picture` from column `x`, `width` wide, from the top down to row `height`. */
function crop(picture: Picture, x: number, width: number, height: number): Picture {
  const data = new Uint8Array(width * height * 4);
  for (let row = 0; row < height; row++) data.set(picture.data.subarray(4 * (row * picture.width + x), 4 * (row * picture.width + x + width)), 4 * row * width);
  return { width, height, data };
}
