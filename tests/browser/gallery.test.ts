// End-to-end: gallery grammars that use the turtle's geometry beyond plain tubes (polygon leaves,
// tropism, smooth axes, pruning), typed into the studio as a user would paste them, and checked on
// the pixels of the 3D view. Screenshots land in test-results/ for a person to look at.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { changedShare, colourShare, decodePng, foregroundExtent, foregroundShare, type Picture } from './pictures';

import { PLANT_ONLY, RESULTS, VIEW_CANVAS } from './studio-page';

let browser: Browser;
let page: Page;
const problems: string[] = [];

function example(name: string): string {
  return readFileSync(new URL(`../../public/examples/${name}`, import.meta.url), 'utf8');
}

/** Replaces the whole grammar as a paste would, waits for the build, frames it and screenshots it. */
async function show(source: string, picture: string): Promise<{ state: string | null; shot: Picture }> {
  const before = Number((await page.getByTestId('status').getAttribute('data-generation')) ?? '0');
  await page.getByTestId('editor').locator('.cm-content').click();
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText(source);
  await page.waitForFunction(
    (previous) =>
      Number(document.querySelector('[data-testid=status]')?.getAttribute('data-generation') ?? 0) > previous &&
      window.__meristem?.preview?.settled === true,
    before,
    { timeout: 30_000 },
  );
  const state = await page.getByTestId('status').getAttribute('data-state');
  await page.getByTestId('frame').click();
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  const png = await page
    .locator(VIEW_CANVAS)
    .screenshot({ style: PLANT_ONLY });
  writeFileSync(new URL(picture, RESULTS), png);
  return { state, shot: decodePng(png) };
}

/** Leaf green (the example's `#color` ramp past index 3) against the brown wood: green well above red and blue. */
const leafGreen = (r: number, g: number, b: number) => g > 1.3 * r && g > 1.3 * b;

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

describe('turtle geometry in the view', () => {
  it('draws the polygon leaves of the bush of Fig 1.25 in leaf green', async () => {
    const bush = example('abop-1.25-bush.lsys');
    const { state, shot } = await show(bush, 'gallery-1.25-bush.png');
    expect(state).toBe('ok');
    expect(foregroundShare(shot)).toBeGreaterThan(0.03);
    const withLeaves = colourShare(shot, leafGreen);
    // The same bush without its leaf polygons: only stems.
    const bare = await show(bush.replace(/^L -> .*$/m, 'L -> '), 'gallery-1.25-bush-bare.png');
    expect(bare.state).toBe('ok');
    const withoutLeaves = colourShare(bare.shot, leafGreen);
    expect(withLeaves, 'leaves make the bush green').toBeGreaterThan(0.3);
    expect(withLeaves - withoutLeaves, 'the green comes from the leaves').toBeGreaterThan(0.2);
    expect(problems).toEqual([]);
  });

  it('bends the ternary tree of Fig 2.8a by tropism', async () => {
    const tree = example('abop-2.08a-ternary-tree.lsys');
    const bent = await show(tree, 'gallery-2.08a-tropism.png');
    const straight = await show(tree.replace(/^#tropism .*$/m, ''), 'gallery-2.08a-no-tropism.png');
    expect(bent.state).toBe('ok');
    expect(straight.state).toBe('ok');
    expect(foregroundShare(bent.shot)).toBeGreaterThan(0.02);
    expect(changedShare(bent.shot, straight.shot), 'tropism changes the tree').toBeGreaterThan(0.3);
    expect(problems).toEqual([]);
  });

  it('draws smooth axes and pruned crowns', async () => {
    const smooth = await show(example('smooth-tree.lsys'), 'gallery-smooth-tree.png');
    expect(smooth.state).toBe('ok');
    expect(foregroundShare(smooth.shot)).toBeGreaterThan(0.02);
    expect(foregroundExtent(smooth.shot).height).toBeGreaterThan(0.6);
    const pruned = await show(example('green-prune-ellipsoid.lsys'), 'gallery-prune-ellipsoid.png');
    expect(pruned.state).toBe('ok');
    expect(foregroundShare(pruned.shot)).toBeGreaterThan(0.02);
    expect(problems).toEqual([]);
  });
});
