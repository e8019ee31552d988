// Helpers for the browser tests that drive the studio's controls: open the page, collect every
// problem it reports, wait for builds, read the canvas.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import type { Browser, Locator, Page } from 'playwright-core';
import { expect, inject } from 'vitest';
import { decodePng, type Picture } from './pictures';

export const RESULTS = new URL('../../test-results/', import.meta.url);

/** The text of a gallery example. */
export function example(name: string): string {
  return readFileSync(new URL(`../../public/examples/${name}`, import.meta.url), 'utf8');
}

/** The gallery's example files, sorted as the manifest sorts them. */
export function exampleFiles(): string[] {
  return JSON.parse(readFileSync(new URL('../../dist/examples/index.json', import.meta.url), 'utf8')).map((e: { file: string }) => e.file);
}

/** A studio page and the console errors, page errors, failed requests and HTTP errors it showed. */
export interface StudioPage {
  page: Page;
  problems: string[];
}

/** Opens the studio in a new page and waits for the first plant. */
export async function openStudio(browser: Browser, colorScheme: 'light' | 'dark' = 'light', viewport = { width: 1280, height: 800 }): Promise<StudioPage> {
  return studioIn(await browser.newPage({ viewport, colorScheme }));
}

/** Opens the studio with `file` of the gallery shown and waits for the timeline's bar (which loads after the first plant). */
export async function openStudioOn(browser: Browser, file: string): Promise<StudioPage> {
  const opened = await openStudio(browser);
  await opened.page.getByTestId('timeline-slider').waitFor();
  if ((await openExample(opened.page, file)) !== 'ok') throw new Error(`${file} did not build`);
  return opened;
}

/** Opens the studio in `page` (of a context the caller made) and waits for the first plant and the editor. */
export async function studioIn(page: Page): Promise<StudioPage> {
  mkdirSync(RESULTS, { recursive: true });
  const problems: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
    // WebGL's errors come as warnings (a draw call refused: e.g. an attribute shorter than the mesh).
    else if (/GL_INVALID_/.test(message.text())) problems.push(`WebGL error: ${message.text()}`);
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('requestfailed', (request) => problems.push(`request failed: ${request.url()} ${request.failure()?.errorText}`));
  page.on('response', (response) => {
    if (response.status() >= 400) problems.push(`HTTP ${response.status()}: ${response.url()}`);
  });
  await page.goto(inject('studioUrl'));
  await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
  await page.evaluate(() => window.__meristem?.ready); // and the editor, which loads after the first plant
  return { page, problems };
}

/** The counter of delivered builds on the status line. */
export async function generation(page: Page): Promise<number> {
  return Number((await page.getByTestId('status').getAttribute('data-generation')) ?? '0');
}

/**
 * Waits for a build delivered after `previous`, and for the build of the text and options now in
 * the studio to be on screen; returns the status state.
 */
export async function nextBuild(page: Page, previous: number, timeout = 30_000): Promise<string | null> {
  await page.waitForFunction(
    (before) =>
      Number(document.querySelector('[data-testid=status]')?.getAttribute('data-generation') ?? 0) > before &&
      window.__meristem?.preview?.settled === true &&
      window.__meristem.uploading?.() !== true,
    previous,
    { timeout },
  );
  return page.getByTestId('status').getAttribute('data-state');
}

/** A phone's browser context: 390 × 844 CSS pixels, touch (taps, no hover). */
export const PHONE = { viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, isMobile: true, hasTouch: true };

/**
 * On a touch page with the grammar's pane shown: replaces the editor's text as a finger would
 * (a tap in the text, select all, the new text) and waits for its build; returns the status state.
 */
export async function replaceTextByTouch(page: Page, text: string): Promise<string | null> {
  const before = await generation(page);
  await page.getByTestId('editor').locator('.cm-content').tap();
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText(text);
  return nextBuild(page, before);
}

/** Replaces the editor's text as a paste would, and waits for its build; returns the status state. */
export async function pasteText(page: Page, text: string): Promise<string | null> {
  const before = await generation(page);
  await page.getByTestId('editor').locator('.cm-content').click();
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText(text);
  // A build of the text replaced may still be on its way: wait for the pasted text's own.
  await page.waitForFunction((source) => window.__meristem?.preview?.lastResult?.source === source, text.replace(/\r\n?/g, '\n'), { timeout: 30_000 });
  return nextBuild(page, before);
}

/** The editor's text, line by line as CodeMirror shows it (once it has loaded, after the first plant). */
export async function editorText(page: Page): Promise<string> {
  await page.locator('[data-testid=editor] .cm-content').waitFor();
  return page.evaluate(() => [...document.querySelectorAll('[data-testid=editor] .cm-line')].map((l) => l.textContent ?? '').join('\n'));
}

/** Waits two frames, so what was asked is drawn. */
export function twoFrames(page: Page): Promise<unknown> {
  return page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
}

/**
 * The view's WebGL canvas. Where a software rasterizer draws the view (here, SwiftShader) a 2D
 * canvas may lie over it (web/src/view/sketch-canvas.ts: a sketch, or a big plant's lines in the
 * Lines mode); a screenshot of the WebGL canvas's box shows both.
 */
export const VIEW_CANVAS = '[data-testid=viewport] canvas:not(.sketch-canvas)';

/**
 * The screenshot style that leaves the plant alone: the overlays on the view hidden, and no
 * keyboard focus ring on the canvas (a key pressed after a click shows it).
 */
export const PLANT_ONLY = '[data-testid=viewport] > :not(canvas) { visibility: hidden !important; } [data-testid=viewport] canvas { outline: none !important; }';

/** Scrubs the timeline to growth time `t` (as a drag of the slider does) and waits for its frame. */
export async function scrubTo(page: Page, t: number): Promise<void> {
  await page.getByTestId('timeline-slider').fill(String(t));
  await page.waitForFunction((want) => {
    const { t, span } = window.__meristem!.growth!();
    return span !== null && (t === want || (t === null && want >= span));
  }, t);
  await twoFrames(page);
}

/** Screenshots the 3D canvas (saved as `name` in test-results/) and decodes it. */
export async function canvasPicture(page: Page, name: string): Promise<Picture> {
  await twoFrames(page);
  const png = await page.locator(VIEW_CANVAS).screenshot({ style: PLANT_ONLY });
  writeFileSync(new URL(name, RESULTS), png);
  return decodePng(png);
}

/** Pixels of the highlight colours (sRGB of view/highlight.ts's HIGHLIGHT, shaded by the lights). */
export const HIGHLIGHT_PIXELS = {
  produced: (r: number, g: number, b: number) => r > 150 && b > 110 && g < 0.6 * r && g < 0.7 * b,
  left: (r: number, g: number, b: number) => b > 150 && r < 0.55 * b && g < 0.9 * b,
  selected: (r: number, g: number, b: number) => r > 150 && g > 130 && b < 0.45 * g,
};

/**
 * The first pixel of the 3D view (in page coordinates, scanning the canvas) that passes `test`
 * with all its eight neighbours: inside the shape, not on an antialiased edge a pick's ray might miss.
 */
export async function findPixel(page: Page, test: (r: number, g: number, b: number) => boolean): Promise<{ x: number; y: number } | null> {
  const picture = await canvasPicture(page, 'find-pixel.png');
  const box = (await page.locator(VIEW_CANVAS).boundingBox())!;
  const scale = picture.width / box.width;
  const passes = (x: number, y: number) => {
    const i = 4 * (y * picture.width + x);
    return test(picture.data[i], picture.data[i + 1], picture.data[i + 2]);
  };
  for (let y = 1; y < picture.height - 1; y += 1)
    for (let x = 1; x < picture.width - 1; x += 1) {
      let inside = true;
      for (let dy = -1; dy <= 1 && inside; dy++) for (let dx = -1; dx <= 1 && inside; dx++) inside = passes(x + dx, y + dy);
      // (The pixel's centre: a click half a pixel off a two-pixel line misses it.)
      if (inside) return { x: box.x + (x + 0.5) / scale, y: box.y + (y + 0.5) / scale };
    }
  return null;
}

/** Saves a screenshot of the whole page to test-results/. */
export async function savePage(page: Page, name: string): Promise<void> {
  writeFileSync(new URL(name, RESULTS), await page.screenshot());
}

/** Stats of the plant on screen. */
export function shownStats(page: Page): Promise<{ segments: number; iterations: number; vertices: number } | null> {
  return page.evaluate(() => window.__meristem?.lastStats ?? null);
}

/** Opens the view toolbar's Tubes menu (sides, smooth axes), if it is not open. */
export async function openTubesMenu(page: Page): Promise<void> {
  const menu = page.getByTestId('tubes-menu');
  if ((await menu.getAttribute('open')) === null) await menu.locator('summary').click();
}

/** Opens the timeline's menu of options (speed, loop, range, camera, turntable), if it is not open. */
export async function openTimelineMenu(page: Page): Promise<void> {
  const menu = page.getByTestId('timeline-menu');
  if ((await menu.getAttribute('open')) === null) await menu.locator('summary').click();
}

/** Opens `file` through the gallery dialog (mouse), answering the confirm dialog with `answer` if it asks. */
export async function openFromGallery(page: Page, file: string): Promise<void> {
  await page.getByTestId('open-gallery').click();
  const card = page.locator(`[data-testid=gallery-list] button[data-file="${file}"]`);
  await card.scrollIntoViewIfNeeded();
  await card.click();
}

/**
 * Opens an example from the gallery, replacing the text if the studio asks first, and waits for
 * its build: returns the build's status (`ok` when the plant is shown).
 */
export async function openExample(page: Page, file: string): Promise<string | null> {
  const text = await page.evaluate((name) => fetch(`examples/${encodeURIComponent(name)}`).then((r) => r.text()), file);
  const before = await generation(page);
  await openFromGallery(page, file);
  // The studio fetches the example before it asks, so the question may come a moment after the
  // click; and a build of the text replaced may still be on its way. Answer the question whenever
  // it shows, until the build delivered is the example's.
  const replace = page.getByTestId('confirm-replace-button');
  const built = (source: string) => window.__meristem?.preview?.lastResult?.source === source;
  for (let tries = 0; !(await page.evaluate(built, text)); tries++) {
    if (tries > 600) throw new Error(`${file} was not built within 30 s of opening it`);
    if (await replace.isVisible()) await replace.click();
    await page.waitForTimeout(50);
  }
  return nextBuild(page, before);
}

/**
 * Opens the example `file` at `iterations` steps with the ground grid hidden (only the plant
 * differs from the background), for pictures of its growth.
 */
export async function openGrowing(page: Page, file: string, iterations: number): Promise<void> {
  expect(await openExample(page, file)).toBe('ok');
  const before = await generation(page);
  await page.getByTestId('iterations').fill(String(iterations));
  await nextBuild(page, before);
  await page.getByTestId('grid').click();
}

/**
 * Has the browser take the WebGL context of `canvas` away and give it back (`WEBGL_lose_context`),
 * as a phone's browser does to a page sent to the background.
 */
export async function loseAndRestoreContext(canvas: Locator): Promise<void> {
  await canvas.evaluate(async (element: HTMLCanvasElement) => {
    const lose = element.getContext('webgl2')!.getExtension('WEBGL_lose_context')!;
    lose.loseContext();
    await new Promise((done) => setTimeout(done, 200));
    lose.restoreContext();
    await new Promise((done) => setTimeout(done, 300));
  });
}
