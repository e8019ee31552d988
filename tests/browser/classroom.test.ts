// End-to-end: Meristem in a classroom (issue 18). Large and fullscreen keep the plant big at a
// projector's 200 % zoom; a phone sees the plant without scrolling; the view orbits and zooms from
// the keyboard; plants embed in a plain course page (two <meristem-plant> elements sharing one
// core) and in an 860 × 520 iframe of embed.html, from a site served under a sub-path.
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { decodePng, foregroundShare } from './pictures';
import { RESULTS, example, VIEW_CANVAS } from './studio-page';
import { encodeState } from '../../web/src/share';
import { writeFileSync } from 'node:fs';

let browser: Browser;

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
});

/** A studio page at `width` × `height` CSS pixels and `scale` device pixels each; its problems. */
async function studioAt(width: number, height: number, scale = 1): Promise<{ page: Page; problems: string[] }> {
  const page = await browser.newPage({ viewport: { width, height }, deviceScaleFactor: scale });
  const problems: string[] = [];
  page.on('console', (m) => m.type() === 'error' && problems.push(`console error: ${m.text()}`));
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  await page.goto(inject('studioUrl'));
  await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
  return { page, problems };
}

/** The 3D view's box on the page. */
async function viewBox(page: Page): Promise<{ x: number; y: number; width: number; height: number }> {
  return (await page.getByTestId('viewport').boundingBox())!;
}

/** Screenshots an element and says what share of it is not background. */
async function drawnShare(page: Page, selector: string, name: string): Promise<number> {
  const png = await page.locator(selector).screenshot();
  writeFileSync(new URL(name, RESULTS), png);
  return foregroundShare(decodePng(png));
}

describe('a projector at 200 % zoom (1280 × 800 shown as 640 × 400)', () => {
  it('keeps the plant at least 60 % of the window high in Large and in fullscreen', async () => {
    const { page, problems } = await studioAt(640, 400, 2);
    await page.getByTestId('large').click();
    expect(await page.evaluate(() => document.body.classList.contains('large'))).toBe(true);
    await page.waitForTimeout(300);
    expect((await viewBox(page)).height, 'Large').toBeGreaterThanOrEqual(0.6 * 400);
    writeFileSync(new URL('classroom-large-200.png', RESULTS), await page.screenshot());
    expect(await drawnShare(page, VIEW_CANVAS, 'classroom-large-200-canvas.png')).toBeGreaterThan(0.01);

    await page.getByTestId('fullscreen').click();
    await expect.poll(() => page.evaluate(() => document.body.classList.contains('view-only'))).toBe(true);
    await page.waitForTimeout(300);
    expect((await viewBox(page)).height, 'fullscreen').toBeGreaterThanOrEqual(0.6 * 400);
    expect(await page.getByTestId('editor').isVisible(), 'the plant alone').toBe(false);
    expect(await page.getByTestId('play').isVisible(), 'with its derivation controls').toBe(true);
    writeFileSync(new URL('classroom-fullscreen-200.png', RESULTS), await page.screenshot());
    await page.getByTestId('exit-view-only').click();
    await expect.poll(() => page.evaluate(() => document.body.classList.contains('view-only'))).toBe(false);
    // Large is remembered in this browser.
    await page.reload();
    await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
    expect(await page.getByTestId('large').getAttribute('aria-pressed')).toBe('true');
    await page.getByTestId('large').click();
    expect(problems).toEqual([]);
    await page.close();
  });
});

describe('a phone (390 × 844)', () => {
  it('shows the plant without scrolling, and the grammar on its own button', async () => {
    const { page, problems } = await studioAt(390, 844, 3);
    const box = await viewBox(page);
    expect(box.y + box.height, 'the whole view is on screen').toBeLessThanOrEqual(844);
    expect(box.height).toBeGreaterThan(300);
    expect(await page.evaluate(() => document.scrollingElement!.scrollHeight <= innerHeight + 1), 'no page scrolling').toBe(true);
    expect(await drawnShare(page, VIEW_CANVAS, 'classroom-phone-canvas.png')).toBeGreaterThan(0.01);
    expect(await page.getByTestId('step-forward').isVisible(), 'the iterations are at hand').toBe(true);
    writeFileSync(new URL('classroom-phone.png', RESULTS), await page.screenshot());
    await page.getByTestId('pane-toggle').click();
    await expect.poll(() => page.getByTestId('editor').isVisible()).toBe(true);
    expect(await page.getByTestId('viewport').isVisible()).toBe(false);
    await page.getByTestId('pane-toggle').click();
    await expect.poll(() => page.getByTestId('viewport').isVisible()).toBe(true);
    expect(problems).toEqual([]);
    await page.close();
  });
});

describe('the view from the keyboard', () => {
  it('orbits with the arrow keys, zooms with + and −, and fits again with Home', async () => {
    const { page, problems } = await studioAt(1280, 800);
    // A 3D plant, so the arrows orbit (in 2D they pan).
    await page.getByTestId('projection').click();
    const pose = () => page.evaluate(() => window.__meristem!.cameraPose!());
    const canvas = page.locator(VIEW_CANVAS);
    await canvas.focus();
    expect(await canvas.evaluate((c) => c === document.activeElement)).toBe(true);
    const start = await pose();
    const distance = (p: typeof start) => Math.hypot(...p.position.map((v, i) => v - p.target[i]));
    for (let i = 0; i < 6; i++) await page.keyboard.press('ArrowLeft');
    const turned = await pose();
    expect(turned.target, 'it turns about the plant').toEqual(start.target);
    const angle = (p: typeof start) => Math.atan2(p.position[0] - p.target[0], p.position[2] - p.target[2]);
    expect(Math.abs(angle(turned) - angle(start)), 'six steps of 5°').toBeCloseTo((30 * Math.PI) / 180, 2);
    expect(distance(turned)).toBeCloseTo(distance(start), 5);
    await page.keyboard.press('+');
    expect(distance(await pose()), 'nearer').toBeLessThan(distance(turned));
    await page.keyboard.press('Home');
    const home = await pose();
    home.position.forEach((v, i) => expect(v).toBeCloseTo(start.position[i], 5));
    await page.getByTestId('projection').click();
    expect(problems).toEqual([]);
    await page.close();
  });
});

describe('plants in a course page', () => {
  /** Serves `html` at `name` beside the site (under its sub-path), as a course page would be. */
  async function coursePage(name: string, html: string): Promise<{ page: Page; problems: string[]; workers: () => Promise<number> }> {
    const page = await browser.newPage({ viewport: { width: 1000, height: 1400 } });
    const problems: string[] = [];
    page.on('console', (m) => m.type() === 'error' && problems.push(`console error: ${m.text()}`));
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
    // Count the build workers the page starts.
    await page.addInitScript(() => {
      const Original = window.Worker;
      (window as unknown as { __workers: number }).__workers = 0;
      window.Worker = class extends Original {
        constructor(url: string | URL, options?: WorkerOptions) {
          super(url, options);
          if (options?.name === 'meristem-build') (window as unknown as { __workers: number }).__workers++;
        }
      };
    });
    const url = new URL(`course/${name}`, inject('studioUrl')).href;
    await page.route(url, (route) => route.fulfill({ contentType: 'text/html', body: html }));
    await page.goto(url);
    return { page, problems, workers: () => page.evaluate(() => (window as unknown as { __workers: number }).__workers) };
  }

  it('shows two <meristem-plant> elements, with iteration buttons and sliders, sharing one core', async () => {
    const { page, problems, workers } = await coursePage(
      'lesson.html',
      `<!doctype html><html><head><meta charset="utf-8"><title>A course page</title>
      <script type="module" src="../meristem-plant.js"></script></head>
      <body><h1>Chapter 1</h1>
      <meristem-plant id="a" src="../examples/abop-1.24d.lsys" iterations="4" controls="iterations" style="width: 480px; height: 360px"></meristem-plant>
      <p>A plant written in the page itself:</p>
      <meristem-plant id="b" controls="sliders" style="width: 320px; height: 240px">#define a 25 // [5, 60]
#angle a
#iterations 4
axiom: X
X -> F[+X]F[-X]+X
F -> FF</meristem-plant></body></html>`,
    );
    const state = (id: string) => page.locator(`#${id} .mp`).getAttribute('data-state');
    await expect.poll(() => state('a'), { timeout: 30_000 }).toBe('ok');
    await expect.poll(() => state('b'), { timeout: 30_000 }).toBe('ok');
    expect(await drawnShare(page, '#a', 'embed-element-a.png'), 'the first plant is drawn').toBeGreaterThan(0.01);
    expect(await drawnShare(page, '#b', 'embed-element-b.png'), 'the second plant is drawn').toBeGreaterThan(0.01);
    expect(await workers(), 'one core for the page').toBe(1);

    // The iteration buttons.
    const a = page.locator('#a');
    expect(await a.locator('.mp-count').textContent()).toBe('n = 4');
    await a.getByRole('button', { name: 'One iteration more' }).click();
    await expect.poll(() => a.locator('.mp').getAttribute('data-iterations')).toBe('5');
    expect(await a.locator('.mp-count').textContent()).toBe('n = 5');
    // The slider of #define a changes the plant.
    const b = page.locator('#b');
    const before = await b.locator('canvas').screenshot();
    await b.locator('input[type=range]').fill('55');
    await expect.poll(async () => (await b.locator('canvas').screenshot()).equals(before)).toBe(false);
    // Open in Meristem: the studio with the plant's state.
    const open = await a.locator('.mp-open').getAttribute('href');
    expect(open?.startsWith(`${inject('studioUrl')}#s=1.`)).toBe(true);
    writeFileSync(new URL('embed-course-page.png', RESULTS), await page.screenshot());
    expect(problems).toEqual([]);
    await page.close();
  });

  it('shows a plant at least 400 px tall in an 860 × 520 iframe of embed.html', async () => {
    const fragment = await encodeState({ text: example('abop-1.24d.lsys'), iterations: 5 });
    const { page, problems } = await coursePage(
      'frame.html',
      `<!doctype html><html><head><meta charset="utf-8"><title>Frame</title></head><body>
      <iframe id="f" src="../embed.html?controls=iterations${fragment}" width="860" height="520" title="A plant"></iframe></body></html>`,
    );
    const frame = page.frameLocator('#f');
    await expect.poll(() => frame.locator('.mp').getAttribute('data-state'), { timeout: 30_000 }).toBe('ok');
    const canvas = frame.locator('.mp-view canvas');
    const box = (await canvas.boundingBox())!;
    expect(box.height, 'the plant takes the frame').toBeGreaterThanOrEqual(400);
    expect(await drawnShare(page, '#f', 'embed-iframe.png')).toBeGreaterThan(0.01);
    expect(await frame.locator('.mp-count').textContent()).toBe('n = 5');
    expect(problems).toEqual([]);
    await page.close();
  });

  it("offers the Share dialog's snippets, and the element snippet works pasted into a page", async () => {
    const { page: studio, problems: studioProblems } = await studioAt(1280, 800);
    await studio.getByTestId('share').click();
    await studio.getByTestId('embed-snippets').locator('summary').click();
    await studio.getByTestId('embed-sliders').check();
    const frame = await studio.getByTestId('embed-frame').inputValue();
    const element = await studio.getByTestId('embed-element').inputValue();
    expect(frame).toContain(`src="${inject('studioUrl')}embed.html?controls=iterations,sliders#s=1.`);
    expect(element.startsWith(`<script type="module" src="${inject('studioUrl')}meristem-plant.js"></script>\n<meristem-plant controls="iterations,sliders"`)).toBe(true);
    writeFileSync(new URL('share-embed.png', RESULTS), await studio.screenshot());
    expect(studioProblems).toEqual([]);
    await studio.close();

    const { page, problems, workers } = await coursePage('pasted.html', `<!doctype html><html><head><meta charset="utf-8"><title>Pasted</title></head><body>${element}</body></html>`);
    await expect.poll(() => page.locator('meristem-plant .mp').getAttribute('data-state'), { timeout: 30_000 }).toBe('ok');
    expect(await page.locator('meristem-plant').getAttribute('style')).toContain('height');
    expect(await drawnShare(page, 'meristem-plant', 'embed-pasted.png')).toBeGreaterThan(0.01);
    expect(await workers()).toBe(1);
    expect(problems).toEqual([]);
    await page.close();
  });

  it('says so politely when the address holds no plant', async () => {
    const page = await browser.newPage();
    await page.goto(new URL('embed.html#s=1.garbage', inject('studioUrl')).href);
    await expect.poll(() => page.locator('.mp-failed').textContent()).toMatch(/^This embedded plant could not be shown: /);
    await page.close();
  });
});
