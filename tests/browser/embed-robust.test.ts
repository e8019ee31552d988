// End-to-end: <meristem-plant> when a page or a plant is hostile (issue 50, finding 9): a plant
// that never finishes holds up no other plant once its element is gone, and says it is growing
// meanwhile (9a); an attribute the core cannot use is named in the element, not called a bug (9c);
// a grammar too long for a studio link is offered as a file, never as a link the studio refuses (9d);
// 40 plants in sight are all drawn, by one shared WebGL renderer, each orbiting on its own (9b).
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { readFileSync, writeFileSync } from 'node:fs';
import { decodePng, foregroundShare } from './pictures';
import { RESULTS } from './studio-page';

let browser: Browser;

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
});

/** Serves `body` in a page beside the site (under its sub-path), as a course page would be, with the element's script. */
async function coursePage(name: string, body: string, viewport = { width: 1000, height: 1400 }): Promise<{ page: Page; problems: string[] }> {
  const page = await browser.newPage({ viewport });
  const problems: string[] = [];
  page.on('console', (m) => m.type() === 'error' && problems.push(`console error: ${m.text()}`));
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  const html = `<!doctype html><html><head><meta charset="utf-8"><title>A course page</title>
    <script type="module" src="../meristem-plant.js"></script></head><body>${body}</body></html>`;
  const url = new URL(`course/${name}`, inject('studioUrl')).href;
  await page.route(url, (route) => route.fulfill({ contentType: 'text/html', body: html }));
  await page.goto(url);
  return { page, problems };
}

/** Screenshots the canvas of the plant at `selector` and says what share of it is not background. */
async function drawnShare(page: Page, selector: string, name: string): Promise<number> {
  const png = await page.locator(`${selector} canvas`).screenshot({ timeout: 5_000 });
  writeFileSync(new URL(name, RESULTS), png);
  return foregroundShare(decodePng(png));
}

/**
 * Minutes of derivation (issue 50, finding 8): 4 million modules rewritten at each of 10,000
 * steps; the module limit raised so that a work budget of 20 times it (E0415) ends it only after
 * minutes, not the seconds the default gives.
 */
const ENDLESS = `#iterations 10000
#max_modules 100000000
axiom: A(0)
A(x) : x < 22 -> A(x+1)A(x+1)
A(x) -> A(x+1)`;

const SMALL = `#iterations 4
axiom: X
X -> F[+X]F[-X]+X
F -> FF`;

describe('a plant that never finishes (9a)', () => {
  it('says it is growing, and once its element is removed the other plants are built', async () => {
    const { page, problems } = await coursePage(
      'endless.html',
      `<meristem-plant id="slow" style="width: 320px; height: 240px">${ENDLESS}</meristem-plant>
       <meristem-plant id="b" style="width: 320px; height: 240px">${SMALL}</meristem-plant>`,
    );
    const slow = page.locator('#slow');
    await expect.poll(() => slow.locator('.mp-message').textContent(), { timeout: 30_000 }).toMatch(/^Growing… step \d+ of 10000$/);
    expect(await slow.locator('.mp-message').isVisible()).toBe(true);
    writeFileSync(new URL('embed-growing.png', RESULTS), await page.screenshot());
    expect(await page.locator('#b .mp').getAttribute('data-state'), 'waits behind the first').toBeNull();
    expect(await page.locator('#b .mp-message').textContent()).toBe('Waiting to grow…');

    await page.evaluate(() => document.getElementById('slow')!.remove());
    await expect.poll(() => page.locator('#b .mp').getAttribute('data-state'), { timeout: 20_000 }).toBe('ok');
    expect(await drawnShare(page, '#b', 'embed-after-endless.png'), 'the second plant is drawn').toBeGreaterThan(0.01);
    expect(await page.locator('#b .mp-message').isHidden(), 'its message gone').toBe(true);
    expect(problems).toEqual([]);
    await page.close();
  });
});

describe('attributes the core cannot use (9c)', () => {
  it('names the attribute and shows the plant at the grammar’s own iterations', async () => {
    const { page, problems } = await coursePage('iterations.html', `<meristem-plant id="a" iterations="4294967296" style="width: 320px; height: 240px">${SMALL}</meristem-plant>`);
    const a = page.locator('#a');
    await expect.poll(() => a.locator('.mp').getAttribute('data-state'), { timeout: 30_000 }).toBe('ok');
    expect(await a.locator('.mp-note').textContent()).toBe('iterations="4294967296" is not a whole number from 0 to 4294967295: the grammar’s own value is used.');
    expect(await a.locator('.mp').getAttribute('data-iterations')).toBe('4');
    expect(await a.locator('.mp-message').textContent()).not.toContain('bug');
    expect(await drawnShare(page, '#a', 'embed-bad-iterations.png')).toBeGreaterThan(0.01);
    expect(problems).toEqual([]);
    await page.close();
  });
});

describe('a grammar too long for a studio link (9d)', () => {
  it('offers the grammar as a file instead of a link the studio would refuse', async () => {
    const padding = Array.from({ length: 12_000 }, (_, i) => `// a comment line to make the grammar long, number ${i}`).join('\n');
    const long = `${SMALL}\n${padding}`;
    expect(long.length).toBeGreaterThan(480_000);
    const { page, problems } = await coursePage('long.html', `<meristem-plant id="a" style="width: 320px; height: 240px">${long}</meristem-plant>`);
    const a = page.locator('#a');
    await expect.poll(() => a.locator('.mp').getAttribute('data-state'), { timeout: 30_000 }).toBe('ok');
    const open = a.locator('.mp-open');
    await expect.poll(() => open.textContent()).toBe('Save the grammar ↓');
    expect(await open.getAttribute('href')).toMatch(/^blob:/);
    expect(await open.getAttribute('download')).toBe('plant.lsys');
    expect(await open.getAttribute('title')).toContain('Too long to open in Meristem by a link');
    // The file holds the whole grammar: nothing lost.
    const saved = await open.evaluate(async (link: HTMLAnchorElement) => (await fetch(link.href)).text());
    expect(saved).toBe(long);

    // A short grammar still gets its link, and the studio opens it.
    const { page: short } = await coursePage('short.html', `<meristem-plant id="a" style="width: 320px; height: 240px">${SMALL}</meristem-plant>`);
    const link = short.locator('#a .mp-open');
    await expect.poll(() => link.getAttribute('href'), { timeout: 30_000 }).toMatch(/#s=1\./);
    expect(await link.textContent()).toBe('Open in Meristem ↗');
    expect(problems).toEqual([]);
    await short.close();
    await page.close();
  });
});

describe('a page of many plants (9b)', () => {
  it('draws every plant in sight, and draws again one scrolled back to, or whose view was lost', async () => {
    const plants = Array.from({ length: 20 }, (_, i) => `<meristem-plant id="p${i}" style="width: 320px; height: 240px; margin-bottom: 16px">${SMALL}</meristem-plant>`);
    const { page, problems } = await coursePage('many.html', plants.join('\n'));
    const state = (i: number) => page.locator(`#p${i} .mp`).getAttribute('data-state');
    for (let i = 0; i < 20; i++) await expect.poll(() => state(i), { timeout: 60_000 }).toBe('ok');
    // The first ones, in sight from the start, are drawn (Chromium keeps 16 contexts: a view made
    // for each of 20 plants lost the first 4).
    await page.evaluate(() => window.scrollTo(0, 0));
    for (const i of [0, 1, 2]) await expect.poll(() => drawnShare(page, `#p${i}`, `embed-many-${i}.png`), { timeout: 10_000 }).toBeGreaterThan(0.01);
    // The last ones, scrolled to.
    await page.locator('#p19').scrollIntoViewIfNeeded();
    await expect.poll(() => drawnShare(page, '#p19', 'embed-many-19.png'), { timeout: 10_000 }).toBeGreaterThan(0.01);
    // And the first again, scrolled back to.
    await page.evaluate(() => window.scrollTo(0, 0));
    await expect.poll(() => drawnShare(page, '#p0', 'embed-many-0-again.png'), { timeout: 10_000 }).toBeGreaterThan(0.01);

    // The page's one WebGL context lost while in sight (the page made 16 WebGL canvases of its
    // own after it, and Chromium keeps 16): the plants say so, and are drawn again (with a new
    // shared renderer) once scrolled away and back.
    await page.evaluate(() => {
      const others = Array.from({ length: 16 }, () => document.createElement('canvas').getContext('webgl2'));
      (window as unknown as { __others: unknown[] }).__others = others; // (kept: collected, they would give their contexts back)
    });
    const message = page.locator('#p1 .mp-message');
    await expect.poll(() => message.textContent()).toContain('3D view was taken back by the browser');
    writeFileSync(new URL('embed-view-lost.png', RESULTS), await page.screenshot());
    await page.locator('#p19').scrollIntoViewIfNeeded();
    await page.waitForTimeout(300);
    await page.evaluate(() => window.scrollTo(0, 0));
    await expect.poll(() => drawnShare(page, '#p1', 'embed-view-again.png'), { timeout: 10_000 }).toBeGreaterThan(0.01);
    expect(await message.isHidden()).toBe(true);
    expect(problems).toEqual([]);
    await page.close();
  });
});

/**
 * What each plant's canvas shows: its share of pixels unlike its corner's (the background), and a
 * fingerprint of its pixels. Read by drawing the canvas into a 2D one (a WebGL canvas keeps its
 * drawing buffer for this, a 2D one has its pixels).
 */
function canvasPixels(page: Page, count: number): Promise<{ share: number; print: number }[]> {
  return page.evaluate((n) => {
    const scratch = document.createElement('canvas').getContext('2d', { willReadFrequently: true })!;
    return Array.from({ length: n }, (_, i) => {
      const canvas = document.getElementById(`p${i}`)!.shadowRoot!.querySelector<HTMLCanvasElement>('.mp-view canvas:not(.sketch-canvas)');
      if (!canvas || canvas.width === 0) return { share: 0, print: 0 };
      scratch.canvas.width = canvas.width;
      scratch.canvas.height = canvas.height;
      scratch.drawImage(canvas, 0, 0);
      const pixels = scratch.getImageData(0, 0, canvas.width, canvas.height).data;
      let unlike = 0;
      let print = 0;
      for (let p = 0; p < pixels.length; p += 4) {
        const d = Math.abs(pixels[p] - pixels[0]) + Math.abs(pixels[p + 1] - pixels[1]) + Math.abs(pixels[p + 2] - pixels[2]);
        if (d > 30) unlike++;
        print = (Math.imul(print, 31) + pixels[p] + 7 * pixels[p + 1] + 13 * pixels[p + 2]) | 0;
      }
      return { share: unlike / (pixels.length / 4), print };
    });
  }, count);
}

describe('forty plants in sight at once (9b)', () => {
  it('draws every one with one shared WebGL context, and a drag turns only the plant dragged', async () => {
    const n = 40;
    // A bush in 3D (a flat plant is seen face on, where a drag does not turn it).
    const bush = readFileSync(new URL('../../public/examples/abop-1.25-bush.lsys', import.meta.url), 'utf8');
    const plants = Array.from({ length: n }, (_, i) => `<meristem-plant id="p${i}" iterations="3" style="width: 200px; height: 180px; min-width: 0; min-height: 0">${bush}</meristem-plant>`);
    const grid = `<div style="display: grid; grid-template-columns: repeat(8, 200px); gap: 8px">${plants.join('\n')}</div>`;
    const { page, problems } = await coursePage('forty.html', grid, { width: 1720, height: 1000 });
    for (let i = 0; i < n; i++) await expect.poll(() => page.locator(`#p${i} .mp`).getAttribute('data-state'), { timeout: 60_000 }).toBe('ok');
    // Every canvas drawn (with a context per plant, Chromium's 16 left 24 of them blank).
    await expect
      .poll(async () => (await canvasPixels(page, n)).map((c, i) => (c.share > 0.01 ? -1 : i)).filter((i) => i >= 0), { timeout: 20_000 })
      .toEqual([]);
    writeFileSync(new URL('embed-forty.png', RESULTS), await page.screenshot());
    expect(await page.locator('meristem-plant .mp-message:not([hidden])').count(), 'no plant says its view was lost').toBe(0);
    // Settled (textures arrive after the first frames): two readings a moment apart agree.
    let before = await canvasPixels(page, n);
    for (let tries = 0; tries < 20; tries++) {
      await page.waitForTimeout(500);
      const again = await canvasPixels(page, n);
      const same = again.every((c, i) => c.print === before[i].print);
      before = again;
      if (same) break;
    }
    // A drag across plant 13 (its orbit controls load after its first frame: dragged until it turns).
    const box = (await page.locator('#p13 .mp-view canvas:not(.sketch-canvas)').boundingBox())!;
    let after = before;
    for (let tries = 0; tries < 10 && after[13].print === before[13].print; tries++) {
      await page.mouse.move(box.x + box.width * 0.3, box.y + box.height / 2);
      await page.mouse.down();
      await page.mouse.move(box.x + box.width * 0.7, box.y + box.height / 2, { steps: 8 });
      await page.mouse.up();
      await page.waitForTimeout(300);
      after = await canvasPixels(page, n);
    }
    writeFileSync(new URL('embed-forty-dragged.png', RESULTS), await page.screenshot());
    expect(after[13].print, 'the plant dragged turned').not.toBe(before[13].print);
    expect(after[13].share).toBeGreaterThan(0.01);
    expect(after.map((c, i) => (i !== 13 && c.print !== before[i].print ? i : -1)).filter((i) => i >= 0), 'plants that changed but were not dragged').toEqual([]);
    expect(problems).toEqual([]);
    await page.close();
  }, 120_000);
});
