// End-to-end: the context-sensitivity view. The cursor on a production lights up what it wrote and
// its contexts in the 3D view (read from pixels) and the derived-string panel, with its counts;
// clicking a segment marks the production that made it; "colour by production" and stepping the
// iterations show the signal of ABOP section 1.8 travelling; the panel stays virtual for 1,000,000
// modules. Screenshots land in test-results/.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { colourShare, decodePng, type Picture } from './pictures';
import { findPixel as findPagePixel, HIGHLIGHT_PIXELS, PLANT_ONLY, VIEW_CANVAS } from './studio-page';

const RESULTS = new URL('../../test-results/', import.meta.url);
const SIGNAL = readFileSync(new URL('../../public/examples/abop-sec-1.8-signal.lsys', import.meta.url), 'utf8');

let browser: Browser;
let page: Page;
const problems: string[] = [];

async function generation(): Promise<number> {
  return Number((await page.getByTestId('status').getAttribute('data-generation')) ?? '0');
}

async function waitForBuild(previous: number): Promise<void> {
  await page.waitForFunction(
    (before) =>
      Number(document.querySelector('[data-testid=status]')?.getAttribute('data-generation') ?? 0) > before &&
      window.__meristem?.preview?.settled === true,
    previous,
    { timeout: 30_000 },
  );
}

/** Replaces the grammar as a paste would and frames the new plant. */
async function paste(source: string): Promise<void> {
  const before = await generation();
  await page.getByTestId('editor').locator('.cm-content').click();
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText(source);
  await waitForBuild(before);
  await page.getByTestId('frame').click();
}

/** Puts the cursor at the end of the first line that starts with `start`. */
async function cursorOn(start: string): Promise<void> {
  await page.getByTestId('editor').locator('.cm-line', { hasText: new RegExp(`^${start}`) }).first().click();
  await page.keyboard.press('End');
}

async function canvas(name: string): Promise<{ picture: Picture; png: Buffer }> {
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  const png = await page
    .locator(VIEW_CANVAS)
    .screenshot({ style: PLANT_ONLY });
  writeFileSync(new URL(name, RESULTS), png);
  return { picture: decodePng(png), png };
}

const { produced: magenta, left: blue, selected: yellow } = HIGHLIGHT_PIXELS;
const findPixel = (test: (r: number, g: number, b: number) => boolean) => findPagePixel(page, test);

beforeAll(async () => {
  mkdirSync(RESULTS, { recursive: true });
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
  page = await browser.newPage({ viewport: { width: 1280, height: 800 }, colorScheme: 'light' });
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  await page.goto(inject('studioUrl'));
  await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
});

afterAll(async () => {
  await browser?.close();
});

describe('context sensitivity', () => {
  it('lights up what `b < a -> b` wrote and its left context, with the counts', async () => {
    await paste(SIGNAL);
    const plain = await canvas('context-signal-plain.png');
    expect(colourShare(plain.picture, magenta), 'no highlight before the cursor is on a production').toBeLessThan(0.01);

    await cursorOn('b < a');
    const summary = page.getByTestId('explain-summary');
    await expect.poll(() => summary.getAttribute('data-fired')).toBe('1');
    expect(await summary.getAttribute('data-context-matched')).toBe('1');
    expect(await summary.getAttribute('data-condition-failed')).toBe('0');
    expect(await summary.textContent()).toContain('b < a -> b');

    // aaaabaaaa: the b at 4 was written by the production, the a at 3 was its left context.
    const panel = page.getByTestId('string-panel');
    await expect.poll(() => panel.locator('.m-produced').getAttribute('data-i')).toBe('4');
    expect(await panel.locator('.m-left').getAttribute('data-i')).toBe('3');
    expect(await panel.locator('.m-produced').textContent()).toBe('b');

    const lit = await canvas('context-signal-highlight.png');
    expect(colourShare(lit.picture, magenta), 'the signal is drawn in the highlight colour').toBeGreaterThan(0.05);
    expect(colourShare(lit.picture, blue), 'its left context in the left-context colour').toBeGreaterThan(0.03);

    // Another production: b -> a fired once, with no context.
    await cursorOn('b -> a');
    await expect.poll(() => panel.locator('.m-produced').getAttribute('data-i')).toBe('3');
    expect(await panel.locator('.m-left').count()).toBe(0);
    expect(problems).toEqual([]);
  });

  it('selects the module and marks its production when a segment is clicked', async () => {
    await cursorOn('b < a');
    await expect.poll(async () => (await findPixel(magenta)) !== null).toBe(true);
    const spot = (await findPixel(magenta))!;
    // Move the cursor off the productions so that only the pick speaks.
    await cursorOn('axiom');
    await page.mouse.click(spot.x, spot.y);
    const summary = page.getByTestId('explain-summary');
    await expect.poll(() => summary.textContent()).toMatch(/^This b \(module 4 of the derived string\) was written by rule 1 \(line \d+: b < a -> b\) from a \(module 4 of the step before\): left context matched at 3\./);
    await expect.poll(() => page.locator('.cm-picked-production').textContent()).toBe('b < a -> b');
    const panel = page.getByTestId('string-panel');
    expect(await panel.locator('.m-selected').getAttribute('data-i')).toBe('4');
    expect(await panel.locator('.m-left').getAttribute('data-i')).toBe('3');
    const picked = await canvas('context-signal-picked.png');
    expect(colourShare(picked.picture, yellow), 'the picked segment').toBeGreaterThan(0.03);
    expect(colourShare(picked.picture, blue), 'its context').toBeGreaterThan(0.03);
    // With a module picked, the cursor on another production says why it did not fire there.
    await cursorOn('b -> a');
    await expect.poll(() => summary.textContent()).toMatch(/^rule 2 \(line \d+: b -> a\) fired 1 time.* cannot rewrite a \(module 4 of the string before the last step\): it is not the production's predecessor\.$/);
    expect(await panel.locator('.m-selected').getAttribute('data-i'), 'the pick stays').toBe('4');
    await page.getByTestId('string-panel').locator('.m[data-i="6"]').click();
    await cursorOn('b < a');
    await expect.poll(() => summary.textContent()).toMatch(/at a \(module 6 of the string before the last step\): left context b expected, found a at 5 — so it did not fire there\.$/);
    await cursorOn('axiom');
    // A click on the background clears the pick.
    const box = (await page.locator(VIEW_CANVAS).boundingBox())!;
    await page.mouse.click(box.x + 5, box.y + 5);
    await expect.poll(() => page.locator('.cm-picked-production').count()).toBe(0);
    expect(problems).toEqual([]);
  });

  it('watches the signal travel, step by step, coloured by production', async () => {
    await page.getByTestId('by-production').check();
    expect(await page.getByTestId('production-legend').locator('li').count()).toBe(2);
    expect(await page.getByTestId('production-legend').isVisible()).toBe(true);
    const positions: number[] = [];
    for (const n of [1, 2, 3]) {
      const before = await generation();
      await page.getByTestId('iterations').fill(String(n));
      await waitForBuild(before);
      await cursorOn('b < a');
      const produced = page.getByTestId('string-panel').locator('.m-produced');
      await expect.poll(() => produced.count()).toBe(1);
      positions.push(Number(await produced.getAttribute('data-i')));
    }
    expect(positions, 'the signal moves one cell per step').toEqual([1, 2, 3]);
    const coloured = await canvas('context-signal-by-production.png');
    expect(colourShare(coloured.picture, magenta) + colourShare(coloured.picture, blue)).toBeGreaterThan(0.05);
    await page.getByTestId('by-production').uncheck();
    await page.getByTestId('iterations').fill('');
    expect(problems).toEqual([]);
  });

  it('keeps the derived-string panel virtual for a million modules', async () => {
    await paste('#iterations 20\naxiom: A\nA -> AA');
    await expect.poll(() => page.evaluate(() => window.__meristem?.lastStats?.modules)).toBe(1_048_576);
    const panel = page.getByTestId('string-panel');
    await expect.poll(() => panel.locator('.m').count()).toBeGreaterThan(40);
    expect(await panel.locator('.m').count(), 'only the rows in view are in the page').toBeLessThan(2000);
    const took = await panel.evaluate(async (element) => {
      const start = performance.now();
      element.scrollTop = element.scrollHeight;
      await new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done)));
      return performance.now() - start;
    });
    expect(took, 'scrolling to the end does not freeze the page').toBeLessThan(500);
    await expect.poll(() => panel.locator('.m').last().getAttribute('data-i')).toBe(String(1_048_575));
    expect(problems).toEqual([]);
  });
});
