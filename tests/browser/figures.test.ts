// End-to-end: figures as in the book. Plants drawn in one plane show as lines of constant width
// (the Lines mode, a toggle in the view toolbar with a width in pixels), 3D plants as tubes;
// highlighting and picking work on lines. Screenshots land in test-results/.
import type { Browser, Page } from 'playwright-core';
import { chromium } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { changedShare, strokeWidth } from './pictures';
import { canvasPicture, example, generation, nextBuild, openStudio, type StudioPage } from './studio-page';

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
});

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
      await page.getByTestId('lines-menu').locator('summary').click();
      await page.getByTestId('line-width').fill(String(width));
      await page.getByTestId('line-width').press('Enter');
      await page.getByTestId('lines-menu').locator('summary').click();
      const picture = await canvasPicture(page, `figures-width-${width}.png`);
      const scale = picture.width / (await page.locator('[data-testid=viewport] canvas').boundingBox())!.width;
      const measured = strokeWidth(picture) / scale;
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
});
