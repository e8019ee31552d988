// End-to-end: the toolbar's iterations box shows a grammar's iterations whole as its placeholder
// ("grammar: 10000": stepwise grammars, L-Py's continuous growth, have hundreds or thousands of
// steps) and an override with its × (of four digits: the only valid five, 10000, is then the
// grammar's own, which overrides nothing), at a laptop's size, at 200 % zoom and on a
// phone, the toolbar laid out as before (its lines, nothing past the page's edge). The box is as
// wide as the grammar's digits need: a first plant's toolbar is as it was.
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { encodeState } from '../../web/src/share';
import { PHONE, RESULTS } from './studio-page';

let browser: Browser;

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
});

/**
 * What the box shows, measured in the page: its text's width and the room it has; the toolbar's
 * height, and with the box as narrow as it was (`was`: before its placeholder had room for five
 * digits); whether anything is wider than the page.
 */
function measure(page: Page, was: string) {
  return page.evaluate((was) => {
    const input = document.querySelector<HTMLInputElement>('[data-testid=iterations]')!;
    const style = getComputedStyle(input);
    const context = document.createElement('canvas').getContext('2d')!;
    context.font = style.font;
    const text = input.value === '' ? input.placeholder : input.value;
    const room = input.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight);
    const toolbar = document.querySelector<HTMLElement>('.toolbar')!;
    const height = toolbar.getBoundingClientRect().height;
    input.style.width = was;
    const before = toolbar.getBoundingClientRect().height;
    input.style.width = '';
    const root = document.documentElement;
    // (A narrow toolbar is one row, scrolled sideways when longer: it may be wider than the page.)
    return { text, width: context.measureText(text).width, room, height, before, overflow: root.scrollWidth - root.clientWidth };
  }, was);
}

/** The sizes, each with the box's width before (web/src/styles/iterations-box.css, layout-modes.css's narrow layout). */
const SIZES = [
  { name: 'laptop', options: { viewport: { width: 1280, height: 800 } }, was: '7.6em' },
  // A laptop's 1280 × 800 at 200 % zoom: 640 × 400 CSS pixels, two device pixels each.
  { name: 'zoom-200', options: { viewport: { width: 640, height: 400 }, deviceScaleFactor: 2 }, was: '6.6em' },
  { name: 'phone', options: PHONE, was: '6.6em' },
] as const;

describe('the iterations box', () => {
  for (const { name, options, was } of SIZES) {
    it(`shows five digits whole at the ${name}’s size, the toolbar as it was`, async () => {
      // A link's grammar of 10,000 iterations.
      const context = await browser.newContext(options);
      const page = await context.newPage();
      const fragment = await encodeState({ text: '// Five digits of iterations\n#iterations 10000\naxiom: F\n' });
      await page.goto(new URL(fragment, inject('studioUrl')).href);
      await page.waitForFunction(() => window.__meristem?.lastStats?.iterations === 10000 && window.__meristem.preview?.settled === true);
      const grammar = await measure(page, was);
      expect(grammar.text).toBe('grammar: 10000');
      expect(grammar.width, 'the placeholder fits its box').toBeLessThanOrEqual(grammar.room);
      expect(grammar.room - grammar.width, 'and the box is no wider than it needs').toBeLessThan(20);
      await page.locator('.toolbar').screenshot({ path: new URL(`iterations-box-${name}-grammar.png`, RESULTS).pathname });
      await page.getByTestId('iterations').fill('9999');
      await page.getByTestId('iterations').blur();
      await page.waitForFunction(() => document.querySelector('[data-testid=iterations-box]')?.hasAttribute('data-override'));
      const override = await measure(page, was);
      expect(override.width, 'an override fits beside its ×').toBeLessThanOrEqual(override.room);
      await page.locator('.toolbar').screenshot({ path: new URL(`iterations-box-${name}.png`, RESULTS).pathname });
      for (const now of [grammar, override]) {
        expect(now.overflow, 'nothing wider than the page').toBeLessThanOrEqual(0);
        expect(now.height, 'the toolbar keeps its lines').toBe(now.before);
      }
      await context.close();
    });
  }
});

describe('iterations the core cannot take (issue 50, finding 9c)', () => {
  it('says at the box what it takes, never that the core crashed, and builds the grammar’s own', async () => {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    const page = await context.newPage();
    // A link may hold up to 2^32 − 1 iterations (the core's limit), more than the box takes.
    const fragment = await encodeState({ text: '#iterations 3\naxiom: F\nF -> F[+F]F', iterations: 2 ** 32 - 1 });
    await page.goto(new URL(fragment, inject('studioUrl')).href);
    await page.waitForFunction(() => window.__meristem?.lastStats?.iterations === 3 && window.__meristem.preview?.settled === true);
    for (const typed of ['4294967296', '4294967295', '1e400']) {
      await page.getByTestId('iterations').fill(typed);
      await page.getByTestId('iterations').blur();
      await expect.poll(() => page.getByTestId('iterations-tag').textContent()).toBe('whole, 0–10000');
      await page.waitForTimeout(500); // (a build it asked for, had it asked for one)
      expect(await page.evaluate(() => window.__meristem?.lastStats?.iterations), typed).toBe(3);
      expect(await page.getByTestId('status').getAttribute('data-state'), typed).not.toBe('crashed');
      const notice = page.getByTestId('notice');
      expect((await notice.isVisible()) ? await page.getByTestId('notice-text').textContent() : '', typed).not.toMatch(/crash/i);
    }
    await context.close();
  });
});
