// End-to-end: the rough edges a class hits in its first week (issue 48), each as a lecturer met it.
// Stages downloads on white paper at a chosen DPI, its lines one width in every stage, its captions
// whole, every k-th step; the A5 PNG of the 3D bush 1.25 holds the whole plant; Large on a
// 683 × 384 projector shows the productions; the Iterations box says at the box what it accepts;
// a <meristem-plant> whose grammar is on a server without CORS says what the page needs; text
// typed over an example downloads under its own name.
import { readFileSync, writeFileSync } from 'node:fs';
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { decodePng, foregroundMask, strokeWidth, type Picture } from './pictures';
import { RESULTS, generation, nextBuild, openExample, openStudio, pasteText, savePage } from './studio-page';
import { serveStatic } from './static-server';

let browser: Browser;
let page: Page;
let problems: string[];

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
  ({ page, problems } = await openStudio(browser));
  await page.evaluate(() => window.__meristem?.ready);
});

afterAll(async () => {
  await browser?.close();
});

/** Clicks `testId` and returns the download it makes. */
async function download(testId: string, on = page): Promise<{ name: string; bytes: Buffer }> {
  const [file] = await Promise.all([on.waitForEvent('download'), on.getByTestId(testId).click()]);
  return { name: file.suggestedFilename(), bytes: readFileSync((await file.path())!) };
}

/** Opens the Download menu unless it is open. */
async function openDownloads(): Promise<void> {
  if (!(await page.getByTestId('downloads').evaluate((menu) => (menu as HTMLDetailsElement).open))) await page.getByTestId('downloads').locator('summary').click();
}

/** The part of `picture` from column `x`, `width` wide, and its top `height` rows. */
function crop(picture: Picture, x: number, width: number, height = picture.height): Picture {
  const data = new Uint8Array(width * height * 4);
  for (let row = 0; row < height; row++) data.set(picture.data.subarray(4 * (row * picture.width + x), 4 * (row * picture.width + x + width)), 4 * row * width);
  return { width, height, data };
}

/** The box of the pixels of `picture` clearly not `background`. */
function inkBox(picture: Picture, background: [number, number, number]): { left: number; right: number; top: number; bottom: number } {
  const mask = foregroundMask(picture, background);
  const box = { left: Infinity, right: -Infinity, top: Infinity, bottom: -Infinity };
  for (let p = 0; p < mask.length; p++) {
    if (!mask[p]) continue;
    const x = p % picture.width;
    const y = Math.floor(p / picture.width);
    box.left = Math.min(box.left, x);
    box.right = Math.max(box.right, x);
    box.top = Math.min(box.top, y);
    box.bottom = Math.max(box.bottom, y);
  }
  return box;
}

/** The resolution a PNG records (its pHYs chunk), in dots per inch; undefined without one. */
function pngDpi(png: Buffer): number | undefined {
  const at = png.indexOf('pHYs');
  return at < 0 ? undefined : Math.round(png.readUInt32BE(at + 4) * 0.0254);
}

const WHITE: [number, number, number] = [255, 255, 255];

describe('Stages', () => {
  /** Waits for the figure of `captions`, grown. */
  async function figureOf(captions: string[]): Promise<void> {
    // (A caption too long for its tile is broken in two lines.)
    const shown = async () => (await page.getByTestId('stages-figure').locator('.stage-caption').allTextContents()).map((c) => c.replace(/\s+/g, ' '));
    await expect.poll(shown, { timeout: 60_000 }).toEqual(captions);
    await expect.poll(() => page.getByTestId('stages-status').getAttribute('data-state'), { timeout: 60_000 }).toBe('done');
  }

  it('draws the lines of every stage at one width in pixels (each stage has its own width unit)', async () => {
    // 1.24d with wide segments: a width unit is 1/300 of each stage's own size, so at one scale the
    // tubes of n = 6 are four times as wide as those of n = 4; the view's Lines mode draws them all alike.
    expect(await openExample(page, 'abop-1.24d.lsys')).toBe('ok');
    await pasteText(page, '// ABOP Fig 1.24d, wide\n#angle 20\n#width 4\n#iterations 6\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF\n');
    await page.getByTestId('stages-toggle').click();
    await page.getByTestId('stages-from').fill('4');
    await page.getByTestId('stages-to').fill('6');
    await figureOf(['n = 4', 'n = 5', 'n = 6']);
    const png = await download('stages-png');
    writeFileSync(new URL('first-week-stages-lines.png', RESULTS), png.bytes);
    const picture = decodePng(png.bytes);
    const widths: number[] = [];
    for (let c = 0; c < 3; c++) widths.push(strokeWidth(crop(picture, Math.round((c * picture.width) / 3), Math.floor(picture.width / 3), Math.round(picture.height * 0.85))));
    expect(Math.max(...widths) / Math.min(...widths), `the lines of every stage as wide (${widths.join(', ')} px)`).toBeLessThan(1.2);
    await page.getByTestId('stages-toggle').click();
    expect(await openExample(page, 'abop-1.24d.lsys')).toBe('ok');
    await page.getByTestId('stages-toggle').click();
    expect(problems).toEqual([]);
  });

  it('keeps every caption whole, n = 0 (nothing drawn) among ten', async () => {
    await page.getByTestId('stages-from').fill('0');
    await page.getByTestId('stages-to').fill('9');
    await figureOf(['n = 0 (nothing drawn)', ...Array.from({ length: 9 }, (_, i) => `n = ${i + 1}`)]);
    await savePage(page, 'first-week-stages-captions.png');
    const figure = page.getByTestId('stages-figure');
    const area = (await figure.boundingBox())!;
    const boxes = await Promise.all((await figure.locator('.stage-caption').all()).map(async (c) => (await c.boundingBox())!));
    for (const [i, box] of boxes.entries()) {
      expect(box.x, `caption ${i + 1} starts inside the figure`).toBeGreaterThanOrEqual(area.x);
      expect(box.x + box.width, `caption ${i + 1} ends inside the figure`).toBeLessThanOrEqual(area.x + area.width);
      if (i > 0) expect(box.x, `caption ${i + 1} clear of the one before`).toBeGreaterThanOrEqual(boxes[i - 1].x + boxes[i - 1].width);
    }
    expect(problems).toEqual([]);
  });

  it('draws every second step, and downloads the figure on white A5 at 300 DPI', async () => {
    await page.getByTestId('stages-step').fill('2');
    await page.getByTestId('stages-to').fill('6');
    await figureOf(['n = 0 (nothing drawn)', 'n = 2', 'n = 4', 'n = 6']);
    await page.getByTestId('stages-background').selectOption('white');
    await page.getByTestId('stages-paper').selectOption('a5');
    await page.getByTestId('stages-dpi').selectOption('300');
    const png = await download('stages-png');
    writeFileSync(new URL('first-week-stages-a5.png', RESULTS), png.bytes);
    const picture = decodePng(png.bytes);
    // A row of four plants is wider than tall: A5 landscape, 210 × 148 mm at 300 DPI.
    expect([picture.width, picture.height]).toEqual([2480, 1748]);
    expect(pngDpi(png.bytes)).toBe(300);
    expect([...picture.data.subarray(0, 3)], 'white paper').toEqual(WHITE);
    // The caption n = 0 is whole: no ink in the picture's first and last columns.
    const ink = inkBox(picture, WHITE);
    expect(ink.left, 'nothing clipped on the left').toBeGreaterThan(0);
    expect(ink.right, 'nothing clipped on the right').toBeLessThan(picture.width - 1);
    await page.getByTestId('stages-toggle').click();
    expect(problems).toEqual([]);
  });
});

describe('pictures', () => {
  it('fits the whole 3D bush 1.25 on an A5 portrait PNG, with a margin', async () => {
    expect(await openExample(page, 'abop-1.25-bush.lsys')).toBe('ok');
    await openDownloads();
    await page.getByTestId('png-paper').selectOption('a5-portrait');
    await page.getByTestId('png-dpi').selectOption('72');
    await page.getByTestId('png-background').selectOption('white');
    const png = await download('download-png');
    writeFileSync(new URL('first-week-bush-a5.png', RESULTS), png.bytes);
    const picture = decodePng(png.bytes);
    expect([picture.width, picture.height]).toEqual([420, 595]);
    const ink = inkBox(picture, WHITE);
    const margin = 0.02 * picture.width;
    expect(ink.left, 'a margin on the left').toBeGreaterThan(margin);
    expect(picture.width - 1 - ink.right, 'a margin on the right').toBeGreaterThan(margin);
    expect(ink.top, 'a margin at the top').toBeGreaterThan(margin);
    expect(picture.height - 1 - ink.bottom, 'a margin at the bottom').toBeGreaterThan(margin);
    expect(ink.right - ink.left, 'and the plant fills the width').toBeGreaterThan(0.6 * picture.width);
    expect(problems).toEqual([]);
  });

  it('names a download after the text typed over an example, or untitled', async () => {
    await pasteText(page, '#angle 90\naxiom: F-F-F-F\nF -> F-F+F+FF-F-F+F\n');
    await openDownloads();
    await page.getByTestId('png-paper').selectOption('');
    expect((await download('download-png')).name).toBe('untitled.png');
    await pasteText(page, '// Quadratic Koch island\n#angle 90\naxiom: F-F-F-F\nF -> F-F+F+FF-F-F+F\n');
    await openDownloads();
    expect((await download('download-png')).name).toBe('quadratic-koch-island.png');
    expect(problems).toEqual([]);
  });
});

describe('the Iterations box', () => {
  /** The box's state: its value marked invalid, its words, whether it overrides. */
  const box = () =>
    page.evaluate(() => {
      const input = document.querySelector<HTMLInputElement>('[data-testid=iterations]')!;
      const tag = document.querySelector<HTMLElement>('[data-testid=iterations-tag]')!;
      return {
        invalid: input.getAttribute('aria-invalid') === 'true',
        tag: getComputedStyle(tag).display === 'none' ? '' : (tag.textContent ?? ''),
        override: document.querySelector('[data-testid=iterations-box]')!.hasAttribute('data-override'),
      };
    });
  /** Types `value` into the box and waits for the build it asks for (if any). */
  async function type(value: string): Promise<void> {
    const before = await generation(page);
    await page.getByTestId('iterations').fill(value);
    await nextBuild(page, before, 4000).catch(() => undefined); // (none when the value asks for the plant on screen)
    await page.waitForFunction(() => window.__meristem?.preview?.settled === true);
  }

  it('says at the box what it accepts, and never blames the grammar for the box', async () => {
    expect(await openExample(page, 'abop-1.24d.lsys')).toBe('ok');
    await type('-2');
    expect(await box()).toMatchObject({ invalid: true, tag: 'whole, 0–10000' });
    await type('2.5');
    expect(await box()).toMatchObject({ invalid: true, tag: 'whole, 0–10000' });
    expect(await page.evaluate(() => window.__meristem?.lastStats?.iterations), '2.5 is not run as 2').toBe(7);
    await type('7');
    expect(await box(), "the grammar's own value overrides nothing").toEqual({ invalid: false, tag: '', override: false });
    await type('3');
    expect(await box()).toEqual({ invalid: false, tag: 'overrides 7', override: true });
    await type('40');
    await expect.poll(box).toMatchObject({ invalid: true, tag: 'too many' });
    await page.locator('[data-testid=editor] .cm-content').waitFor();
    await page.waitForTimeout(800); // (the linter's pause)
    expect(await page.locator('[data-testid=editor] .cm-lintRange-error').count(), 'no error marked in the grammar').toBe(0);
    expect(await page.getByTestId('status').textContent(), 'nor told of its #iterations line').toBe('Too many iterations in the Iterations box — showing last good plant');
    await page.locator('.toolbar').screenshot({ path: new URL('first-week-iterations.png', RESULTS).pathname }).catch(() => undefined);
    await type('');
    expect(await box()).toMatchObject({ invalid: false, override: false });
  });
});

describe('Large on a projector', () => {
  it('shows the productions of 1.24d at 683 × 384, the empty Constants panel folded away', async () => {
    const context = await browser.newContext({ viewport: { width: 683, height: 384 }, deviceScaleFactor: 2 });
    const projector = await context.newPage();
    await projector.goto(inject('studioUrl'));
    await projector.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
    await projector.evaluate(() => window.__meristem?.ready);
    await projector.getByTestId('large').click();
    await projector.getByTestId('pane-toggle').click();
    const production = projector.locator('[data-testid=editor] .cm-line', { hasText: 'F -> FF' });
    await production.waitFor();
    await projector.waitForTimeout(300);
    await projector.screenshot({ path: new URL('first-week-large-projector.png', RESULTS).pathname });
    const constants = await projector.getByTestId('constants').boundingBox();
    expect(constants?.height ?? 0, 'no room for constants the grammar has none of').toBe(0);
    const scroller = (await projector.locator('[data-testid=editor] .cm-scroller').boundingBox())!;
    const line = (await production.boundingBox())!;
    expect(line.y + line.height, 'the last production in view').toBeLessThanOrEqual(scroller.y + scroller.height);
    await context.close();
  });
});

describe('<meristem-plant> with a grammar on a server without CORS', () => {
  it('says in the element that the server must send Access-Control-Allow-Origin', async () => {
    const other = await serveStatic('/other/');
    const course = await browser.newPage({ viewport: { width: 600, height: 400 } });
    const url = new URL('cors.html', inject('studioUrl')).href;
    const html = `<!doctype html><html><head><meta charset="utf-8"><title>Course</title><script type="module" src="meristem-plant.js"></script></head>
      <body><meristem-plant src="${other.base}examples/abop-1.24d.lsys" style="width: 480px; height: 300px"></meristem-plant></body></html>`;
    await course.route(url, (route) => route.fulfill({ contentType: 'text/html', body: html }));
    await course.goto(url);
    const message = course.locator('meristem-plant .mp-failed');
    await expect.poll(() => message.textContent(), { timeout: 30_000 }).toMatch(/Access-Control-Allow-Origin/);
    expect(await message.textContent()).toMatch(/inside the element/);
    expect(await message.isVisible()).toBe(true);
    await course.screenshot({ path: new URL('first-week-embed-cors.png', RESULTS).pathname });
    await course.close();
    await other.close();
  });
});
