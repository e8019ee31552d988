// Helpers for the browser tests that drive the studio's controls: open the page, collect every
// problem it reports, wait for builds, read the canvas.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import type { Browser, Page } from 'playwright-core';
import { inject } from 'vitest';
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
  mkdirSync(RESULTS, { recursive: true });
  const page = await browser.newPage({ viewport, colorScheme });
  const problems: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('requestfailed', (request) => problems.push(`request failed: ${request.url()} ${request.failure()?.errorText}`));
  page.on('response', (response) => {
    if (response.status() >= 400) problems.push(`HTTP ${response.status()}: ${response.url()}`);
  });
  await page.goto(inject('studioUrl'));
  await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
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
      window.__meristem?.preview?.settled === true,
    previous,
    { timeout },
  );
  return page.getByTestId('status').getAttribute('data-state');
}

/** The editor's text, line by line as CodeMirror shows it. */
export function editorText(page: Page): Promise<string> {
  return page.evaluate(() => [...document.querySelectorAll('[data-testid=editor] .cm-line')].map((l) => l.textContent ?? '').join('\n'));
}

/** Waits two frames, so what was asked is drawn. */
export function twoFrames(page: Page): Promise<unknown> {
  return page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
}

/** Screenshots the 3D canvas (saved as `name` in test-results/) and decodes it. */
export async function canvasPicture(page: Page, name: string): Promise<Picture> {
  await twoFrames(page);
  const png = await page.locator('[data-testid=viewport] canvas').screenshot({ style: '[data-testid=viewport] > :not(canvas) { visibility: hidden !important; }' });
  writeFileSync(new URL(name, RESULTS), png);
  return decodePng(png);
}

/** Saves a screenshot of the whole page to test-results/. */
export async function savePage(page: Page, name: string): Promise<void> {
  writeFileSync(new URL(name, RESULTS), await page.screenshot());
}

/** Stats of the plant on screen. */
export function shownStats(page: Page): Promise<{ segments: number; iterations: number; vertices: number } | null> {
  return page.evaluate(() => window.__meristem?.lastStats ?? null);
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
  const before = await generation(page);
  await openFromGallery(page, file);
  const replace = page.getByTestId('confirm-replace-button');
  if (await replace.isVisible()) await replace.click();
  return nextBuild(page, before);
}
