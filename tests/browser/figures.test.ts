// End-to-end: figures as in the book. Plants drawn in one plane show as lines of constant width
// (the Lines mode, a toggle in the view toolbar with a width in pixels), 3D plants as tubes;
// highlighting and picking work on lines. Screenshots land in test-results/.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Browser, Page } from 'playwright-core';
import { chromium } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { backgroundColour, changedShare, decodePng, foregroundShare, strokeWidth, type Picture } from './pictures';
import { exportWithCli, removeScratch, scratchDir } from '../export/tools';
import { HIGHLIGHT_PIXELS, RESULTS, canvasPicture, example, findPixel, generation, nextBuild, openStudio, type StudioPage, VIEW_CANVAS } from './studio-page';

let browser: Browser;
let studio: StudioPage;
let page: Page;

/** Replaces the grammar as a paste would and frames the new plant. */
async function paste(source: string): Promise<void> {
  const before = await generation(page);
  await page.getByTestId('editor').locator('.cm-content').click();
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText(source);
  expect(await nextBuild(page, before)).toBe('ok');
  await page.getByTestId('frame').click();
}

function renderMode(): Promise<string | null> {
  return page.getByTestId('viewport').getAttribute('data-render');
}

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
  studio = await openStudio(browser);
  page = studio.page;
});

afterAll(async () => {
  await browser?.close();
  removeScratch(scratch);
});

const scratch = scratchDir('figures');

/** The width of the lines on screen, in CSS pixels, measured on a picture of the view saved as `name`. */
async function measuredLineWidth(name: string): Promise<number> {
  const picture = await canvasPicture(page, name);
  const scale = picture.width / (await page.locator(VIEW_CANVAS).boundingBox())!.width;
  return strokeWidth(picture) / scale;
}

/** Sets the Lines mode's width (CSS pixels) in its menu. */
async function setLineWidth(width: number): Promise<void> {
  await page.getByTestId('lines-menu').locator('summary').click();
  await page.getByTestId('line-width').fill(String(width));
  await page.getByTestId('line-width').press('Enter');
  await page.getByTestId('lines-menu').locator('summary').click();
}

describe('the Lines mode', () => {
  it('is the default for flat plants, tubes for 3D ones, and the toolbar toggle switches them', async () => {
    const toggle = page.getByRole('toolbar', { name: 'View' }).getByRole('button', { name: 'Lines' });
    await paste(example('abop-1.24a.lsys'));
    expect(await renderMode()).toBe('lines');
    expect(await toggle.getAttribute('aria-pressed')).toBe('true');
    const lines = await canvasPicture(page, 'figures-1.24a-lines.png');
    await toggle.click();
    await expect.poll(renderMode).toBe('tubes');
    expect(await toggle.getAttribute('aria-pressed')).toBe('false');
    const tubes = await canvasPicture(page, 'figures-1.24a-tubes.png');
    expect(changedShare(lines, tubes), 'the tubes replace the lines').toBeGreaterThan(0.005);
    await toggle.click();
    await expect.poll(renderMode).toBe('lines');
    // A 3D plant, on a page where the choice is still automatic, is drawn as tubes.
    const fresh = await openStudio(browser);
    await fresh.page.getByTestId('editor').locator('.cm-content').click();
    const before = await generation(fresh.page);
    await fresh.page.keyboard.press('Control+A');
    await fresh.page.keyboard.insertText(example('abop-1.25-bush.lsys'));
    expect(await nextBuild(fresh.page, before)).toBe('ok');
    expect(await fresh.page.getByTestId('viewport').getAttribute('data-render')).toBe('tubes');
    expect(fresh.problems).toEqual([]);
    await fresh.page.close();
    expect(studio.problems).toEqual([]);
  });

  it('draws every line with the width chosen, in pixels', async () => {
    await page.getByTestId('grid').click(); // a plain background
    await paste('#angle 35\naxiom: F[+F][-F]F[++F]\n');
    for (const width of [2, 6, 12]) {
      await setLineWidth(width);
      const measured = await measuredLineWidth(`figures-width-${width}.png`);
      expect(Math.abs(measured - width), `width ${width}: measured ${measured}`).toBeLessThanOrEqual(1);
    }
    // A width out of range is refused and the field shows the one in force.
    await page.getByTestId('lines-menu').locator('summary').click();
    await page.getByTestId('line-width').fill('500');
    await page.getByTestId('line-width').press('Enter');
    expect(await page.getByTestId('line-width').inputValue()).toBe('12');
    await page.getByTestId('line-width').fill('2');
    await page.getByTestId('line-width').press('Enter');
    await page.getByTestId('lines-menu').locator('summary').click();
    await page.getByTestId('grid').click();
    expect(studio.problems).toEqual([]);
  });

  it('draws the lines twice as wide in the Large mode (a projector)', async () => {
    await page.getByTestId('grid').click(); // a plain background
    await paste('#angle 30\naxiom: F[+F][-F]F[++F]\n');
    await setLineWidth(3);
    const normal = await measuredLineWidth('figures-width-3.png');
    expect(Math.abs(normal - 3), `measured ${normal}`).toBeLessThanOrEqual(1);
    await page.getByTestId('large').click();
    await expect.poll(() => page.evaluate(() => document.body.classList.contains('large'))).toBe(true);
    await page.getByTestId('frame').click();
    const large = await measuredLineWidth('figures-width-3-large.png');
    expect(Math.abs(large - 6), `measured ${large} in the Large mode`).toBeLessThanOrEqual(1);
    await page.getByTestId('large').click();
    await expect.poll(() => page.evaluate(() => document.body.classList.contains('large'))).toBe(false);
    await page.getByTestId('grid').click();
    expect(studio.problems).toEqual([]);
  });
});

/** Pixels with anything drawn on the 2D canvas over the view (web/src/view/sketch-canvas.ts); null without one. */
function pixelsDrawnIn2D(): Promise<number | null> {
  return page.evaluate(() => {
    const canvas = document.querySelector<HTMLCanvasElement>('[data-testid=viewport] canvas.sketch-canvas');
    const data = canvas?.getContext('2d', { willReadFrequently: true })?.getImageData(0, 0, canvas.width, canvas.height).data;
    if (!data) return null;
    let drawn = 0;
    for (let i = 3; i < data.length; i += 4) if (data[i] > 0) drawn++;
    return drawn;
  });
}

describe('the Lines mode without a GPU', () => {
  it('draws a big plant in 2D: in the width chosen, dimmed and highlighted as WebGL draws them, and tubes take it away', async () => {
    // These browsers draw WebGL with SwiftShader, where each frame of WebGL lines costs about 3 µs
    // a segment; from 50,000 segments the view draws them on a 2D canvas over it. Five straight
    // lines of 16,384 segments each (81,920), the width test's plant, the last one of H.
    await page.getByTestId('grid').click(); // a plain background
    await paste('#angle 35\n#iterations 14\n#draw F H\naxiom: F[+F][-F]F[++H]\nF -> FF\nH -> HH\n');
    expect(await renderMode()).toBe('lines');
    expect(await pixelsDrawnIn2D(), 'the lines are on the 2D canvas').toBeGreaterThan(1000);
    for (const width of [2, 6]) {
      await setLineWidth(width);
      const measured = await measuredLineWidth(`figures-2d-width-${width}.png`);
      expect(Math.abs(measured - width), `width ${width}: measured ${measured}`).toBeLessThanOrEqual(1);
    }
    // The cursor on `F -> FF`: the F segments in the highlight colour, the H line dimmed.
    const magenta = (picture: Picture) => {
      let count = 0;
      for (let i = 0; i < picture.data.length; i += 4) if (HIGHLIGHT_PIXELS.produced(picture.data[i], picture.data[i + 1], picture.data[i + 2])) count++;
      return count;
    };
    /** The brightness (r + g + b) of the darkest pixel outside the highlight (the background is lighter than any line). */
    const darkestInk = (picture: Picture) => {
      let darkest = Infinity;
      for (let i = 0; i < picture.data.length; i += 4) {
        const [r, g, b] = [picture.data[i], picture.data[i + 1], picture.data[i + 2]];
        if (!HIGHLIGHT_PIXELS.produced(r, g, b)) darkest = Math.min(darkest, r + g + b);
      }
      return darkest;
    };
    const plain = await canvasPicture(page, 'figures-2d-plain.png');
    expect(magenta(plain), 'no highlight yet').toBe(0);
    await page.getByTestId('editor').locator('.cm-line', { hasText: /^F -> FF/ }).click();
    await expect.poll(async () => magenta(await canvasPicture(page, 'figures-2d-highlight.png')), { message: 'the highlight, drawn in 2D' }).toBeGreaterThan(500);
    const lit = await canvasPicture(page, 'figures-2d-highlight.png');
    expect(darkestInk(lit), 'the H line dimmed').toBeLessThan(0.8 * darkestInk(plain));
    // A click on a line drawn in 2D picks its segment (the view's canvas under it takes the click).
    const spot = (await findPixel(page, HIGHLIGHT_PIXELS.produced))!;
    await page.getByTestId('editor').locator('.cm-line', { hasText: /^axiom/ }).click();
    await expect.poll(async () => magenta(await canvasPicture(page, 'figures-2d-plain.png'))).toBe(0);
    await page.mouse.click(spot.x, spot.y);
    await expect.poll(() => page.getByTestId('explain-summary').textContent()).toMatch(/^This F \(module \d+ of the derived string\) was written by rule 1/);
    // Tubes: WebGL draws them once built (their sketch meanwhile in 2D), and the 2D canvas leaves the page.
    const toggle = page.getByRole('toolbar', { name: 'View' }).getByRole('button', { name: 'Lines' });
    let before = await generation(page);
    await toggle.click();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await renderMode()).toBe('tubes');
    expect(await pixelsDrawnIn2D()).toBeNull();
    before = await generation(page);
    await toggle.click();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await renderMode()).toBe('lines');
    expect(await pixelsDrawnIn2D()).toBeGreaterThan(1000);
    await setLineWidth(2);
    await page.getByTestId('grid').click();
    expect(studio.problems).toEqual([]);
  });
});

describe('a plant too large to mesh without a GPU', () => {
  it('is drawn as one-pixel lines in 2D', async () => {
    // In the Tubes mode ABOP 1.24d at n = 11 (464,090 segments) would take more than the mesh's
    // 4 million vertices: it comes as lines, which SwiftShader would rasterize at every frame.
    const toggle = page.getByRole('toolbar', { name: 'View' }).getByRole('button', { name: 'Lines' });
    let before = await generation(page);
    await toggle.click();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await renderMode()).toBe('tubes');
    await paste(example('abop-1.24d.lsys').replace('#iterations 7', '#iterations 11'));
    await expect.poll(() => page.getByTestId('status').textContent()).toContain('too large to mesh');
    expect(await pixelsDrawnIn2D(), 'the lines are on the 2D canvas').toBeGreaterThan(1000);
    expect(foregroundShare(await canvasPicture(page, 'figures-too-large-2d.png')), 'and on screen').toBeGreaterThan(0.01);
    before = await generation(page);
    await toggle.click();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await renderMode()).toBe('lines');
    expect(studio.problems).toEqual([]);
  }, 60_000);
});

describe('pictures for print', () => {
  it('downloads ABOP 1.24a at 300 DPI on A5: white, no grid, lines of the width chosen', async () => {
    await paste(example('abop-1.24a.lsys') + '\n');
    expect(await renderMode()).toBe('lines');
    const menu = page.getByTestId('downloads');
    if (!(await menu.evaluate((m) => (m as HTMLDetailsElement).open))) await menu.locator('summary').click();
    await page.getByTestId('png-dpi').selectOption('300');
    await page.getByTestId('png-paper').selectOption('a5-portrait');
    expect([await page.getByTestId('png-width').inputValue(), await page.getByTestId('png-height').inputValue()]).toEqual(['1748', '2480']);
    await page.getByTestId('png-background').selectOption('white');
    await page.getByTestId('png-line-width').fill('5');
    const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('download-png').click()]);
    const bytes = readFileSync((await download.path())!);
    writeFileSync(new URL('figures-1.24a-300dpi.png', RESULTS), bytes);
    const picture = decodePng(bytes);
    expect([picture.width, picture.height]).toEqual([1748, 2480]);
    // 300 DPI recorded: 11811 pixels per metre.
    const phys = bytes.indexOf('pHYs');
    expect([bytes.readUInt32BE(phys + 4), bytes.readUInt32BE(phys + 8), bytes[phys + 12]]).toEqual([11811, 11811, 1]);
    expect(backgroundColour(picture), 'a white background').toEqual([255, 255, 255]);
    // No grid: every pixel is white or the plant's brown (antialiased towards white).
    const [r, g, b] = [...picture.data.subarray(0, 4)];
    expect([r, g, b]).toEqual([255, 255, 255]);
    let grey = 0;
    for (let i = 0; i < picture.data.length; i += 4) {
      const [pr, pg, pb] = [picture.data[i], picture.data[i + 1], picture.data[i + 2]];
      if (pr < 255 && Math.abs(pr - pg) < 4 && Math.abs(pg - pb) < 4) grey++; // grid lines are grey
    }
    expect(grey / (picture.width * picture.height), 'no grey grid lines').toBeLessThan(0.001);
    expect(foregroundShare(picture)).toBeGreaterThan(0.005);
    // Smooth edges: the lines' edge pixels blend the brown into the white, also where the view
    // draws without multisampling (a software rasterizer, as here: the picture is drawn at twice
    // its size and scaled down).
    const counts = new Map<number, number>();
    for (let i = 0; i < picture.data.length; i += 4) {
      const key = (picture.data[i] << 16) | (picture.data[i + 1] << 8) | picture.data[i + 2];
      counts.set(key, (counts.get(key) ?? 0) + 1);
    }
    const [white, brown, ...blends] = [...counts.values()].sort((a, b) => b - a);
    const blended = blends.reduce((sum, n) => sum + n, 0);
    expect(blended / (brown + blended), `edge pixels among the plant's (white ${white})`).toBeGreaterThan(0.05);
    const measured = strokeWidth(picture);
    expect(Math.abs(measured - 5), `stroke width measured ${measured}`).toBeLessThanOrEqual(1);
    await expect.poll(() => page.getByTestId('export-status').textContent()).toMatch(/ · 1748 × 2480 at 300 DPI · /);
    expect(studio.problems).toEqual([]);
  });

  it('downloads ABOP 1.24a as an SVG drawing on A5 at 300 DPI: the same settings, the bytes of meristem export', async () => {
    // The settings of the PNG above (A5 at 300 DPI, white, 5 px lines) are still chosen.
    const source = example('abop-1.24a.lsys') + '\n';
    const menu = page.getByTestId('downloads');
    if (!(await menu.evaluate((m) => (m as HTMLDetailsElement).open))) await menu.locator('summary').click();
    expect(await page.getByTestId('png-line-width').inputValue()).toBe('5');
    const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('download-svg').click()]);
    expect(download.suggestedFilename()).toBe('abop-1.24a.svg');
    const bytes = readFileSync((await download.path())!);
    writeFileSync(new URL('figures-1.24a-300dpi.svg', RESULTS), bytes);
    const grammar = join(scratch, 'abop-1.24a.lsys');
    writeFileSync(grammar, source);
    const look = ['--background', 'white', '--line-width', '5', '--size', '1748x2480', '--dpi', '300'];
    const cli = exportWithCli(grammar, join(scratch, 'abop-1.24a.svg'), look);
    expect(bytes.equals(cli), 'the download is meristem export with the same picture settings').toBe(true);
    const text = bytes.toString('utf8');
    expect(text).toContain(' width="148mm" height="209.97mm"');
    // Drawn by Chromium at its size in pixels: white, no grid, lines 5 px wide.
    const drawing = await browser.newPage({ viewport: { width: 1748, height: 2480 }, deviceScaleFactor: 1 });
    await drawing.setContent(
      `<body style="margin:0"><img width="1748" height="2480" style="display:block" src="data:image/svg+xml;base64,${bytes.toString('base64')}"></body>`,
    );
    await drawing.waitForFunction(() => document.querySelector('img')?.complete === true);
    const shot = await drawing.screenshot();
    await drawing.close();
    writeFileSync(new URL('figures-1.24a-300dpi-svg.png', RESULTS), shot);
    const picture = decodePng(shot);
    expect(backgroundColour(picture)).toEqual([255, 255, 255]);
    expect(foregroundShare(picture)).toBeGreaterThan(0.005);
    const measured = strokeWidth(picture);
    expect(Math.abs(measured - 5), `stroke width measured ${measured}`).toBeLessThanOrEqual(1);
    await expect.poll(() => page.getByTestId('export-status').textContent()).toMatch(/^Saved abop-1\.24a\.svg · /);
    expect(studio.problems).toEqual([]);
  });
});
