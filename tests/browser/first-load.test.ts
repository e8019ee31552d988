// The first load (issue 22): what the studio downloads until the first plant is on screen, gzipped
// as a static host serves it, against the budget; and the time to that first plant on a slow
// network (Chromium's DevTools "Fast 3G": 562.5 ms round trip, 1.6 Mbit/s down, 750 kbit/s up),
// recorded in test-results/first-load.json for the README (a measurement, with a guard against
// regressions: issue 22's 4 s is met on a quiet machine, not reliably on a loaded one).
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { chromium, type Browser } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { RESULTS } from './studio-page';
import { serveStatic, type StaticSite } from './static-server';

/**
 * Script + wasm + styles of the first paint of a plant, gzipped (bytes): issue 22's 400 KB. The
 * first-load work reached 399 KB on 2026-11-26, issue 20's engine work then took it to 415 KB
 * (its per-module classes, sized passes and sketch turtle are in the first plant's core), and two
 * changes to that core brought it to 393 KB the same day (docs/notes/performance-history.md, "The first load": numbers read
 * with JavaScript's parseFloat, the vocabulary fetched after the first plant): the first plant's
 * core 196 KB, three.js and the view 156 KB, the studio and the core's glue 30 KB, the build worker
 * 6 KB, styles 6 KB. The 7 KB under the bound are for the engine work landing in the same core; a
 * change that needs more than that takes it from elsewhere. That work brought it to 400.5 KB by
 * 08:25 UTC, and capping binaryen's one-caller inlining at 20 (crate/Cargo.toml) to 395 KB. On
 * 2026-11-27 the view's work reached 399,968 B, and branch editing loaded on first use left 398.4 KB.
 */
const BUDGET = 400_000;
/**
 * Time to the first plant on "Fast 3G": issue 22 asks for 4 s; 3.6 to 4.9 s measured on the shared
 * 2-core machine at 393 KB (docs/notes/performance-history.md, median 4.6 s at load 7 to 10; 3.7 to 4.6 s, median 4.1 s, at
 * 399 KB and load 5 to 9), so not a stable bound there. A guard against a regression (the core
 * downloaded twice, a blocking fetch, the worker started late), not the target.
 */
const FAST_3G_GUARD_MS = 5_500;
const SUB_PATH = '/first/load/';
const DIST = new URL('../../dist/', import.meta.url);
const FAST_3G = { offline: false, latency: 562.5, downloadThroughput: (1.6 * 1024 * 1024 * 0.9) / 8, uploadThroughput: (750 * 1024 * 0.9) / 8 };

let site: StaticSite;
let browser: Browser;

beforeAll(async () => {
  mkdirSync(RESULTS, { recursive: true });
  site = await serveStatic(SUB_PATH, { gzip: true });
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
  await site?.close();
});

/**
 * Opens the studio in a fresh context (no cache, no service worker); returns the site files it
 * (the page and its workers) asked for before the first plant arrived, those it asked for more than
 * once, and the time to that plant.
 */
async function firstPlant(throttle: boolean): Promise<{ files: string[]; twice: string[]; millis: number; waterfall: Waterfall; linkedAfter: number }> {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'block' });
  const page = await context.newPage();
  // When each WebGL program is linked (the wall clock): the first plant's frame should link none.
  await page.addInitScript(() => {
    const w = window as unknown as { __linkedAt: number[] };
    w.__linkedAt = [];
    const link = WebGL2RenderingContext.prototype.linkProgram;
    WebGL2RenderingContext.prototype.linkProgram = function (program: WebGLProgram) {
      w.__linkedAt.push(Date.now());
      link.call(this, program);
    };
  });
  const requests: { file: string; at: number }[] = [];
  const fileOf = (address: string) => new URL(address).pathname.slice(SUB_PATH.length) || 'index.html';
  context.on('request', (request) => {
    const url = new URL(request.url());
    if (url.pathname.startsWith(SUB_PATH)) requests.push({ file: fileOf(request.url()), at: Date.now() });
  });
  // Each request's start and last byte (ms after the navigation started), the workers' included.
  const finished: Promise<Waterfall[number] | undefined>[] = [];
  context.on('requestfinished', (request) => {
    if (!new URL(request.url()).pathname.startsWith(SUB_PATH)) return;
    finished.push(
      request.sizes().then(
        () => {
          const timing = request.timing();
          return { file: fileOf(request.url()), start: Math.round(timing.startTime - start), end: Math.round(timing.startTime + timing.responseEnd - start) };
        },
        () => undefined,
      ),
    );
  });
  if (throttle) await (await context.newCDPSession(page)).send('Network.emulateNetworkConditions', FAST_3G);
  const start = Date.now();
  await page.goto(site.base);
  await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0, undefined, { timeout: 60_000, polling: 50 });
  const millis = Date.now() - start;
  // The page's clock (the same wall clock) at the first plant's arrival: what was asked for later
  // (the editor, after the first frame) is not part of the first load, however slow the poll above.
  const at = (await page.evaluate(() => window.__meristem?.firstPlantAt)) ?? start + millis;
  await page.waitForFunction(() => window.__meristem?.rendered, undefined, { timeout: 60_000 });
  const linkedAt = await page.evaluate(() => (window as unknown as { __linkedAt: number[] }).__linkedAt);
  const linkedAfter = linkedAt.filter((t) => t >= at).length;
  const waterfall = (await Promise.all(finished)).filter((r) => r !== undefined && r.start <= at - start).sort((a, b) => a!.start - b!.start) as Waterfall;
  await context.close();
  const asked = requests.filter((r) => r.at <= at).map((r) => r.file);
  const twice = asked.filter((file, k) => asked.indexOf(file) !== k);
  return { files: [...new Set(asked)].sort(), twice, millis, waterfall, linkedAfter };
}

/** The requests made before the first plant: file, first and last byte's times after the navigation started (ms). */
type Waterfall = { file: string; start: number; end: number }[];

/** The gzipped size of a file of dist/. */
function gzipped(file: string): number {
  return gzipSync(readFileSync(new URL(file, DIST)), { level: 9 }).length;
}

describe('the first load', () => {
  it(`needs at most ${BUDGET / 1000} KB of script, wasm and styles (gzipped) for the first plant`, async () => {
    const { files, twice, linkedAfter } = await firstPlant(false);
    // The preloads (the core, the opening example) and the boot script's worker are used, not fetched again.
    expect(twice, 'asked for twice').toEqual([]);
    // The shaders were compiled while the core downloaded (PlantView.compileShaders): the first
    // plant's frame waits for no compiler.
    expect(linkedAfter, 'WebGL programs linked after the first plant arrived').toBe(0);
    const counted = files.filter((f) => /\.(js|mjs|wasm|css)$/.test(f));
    const sizes = Object.fromEntries(counted.map((f) => [f, gzipped(f)]));
    const total = Object.values(sizes).reduce((a, b) => a + b, 0);
    writeFileSync(new URL('first-load-files.json', RESULTS), JSON.stringify({ total, sizes, other: files.filter((f) => !counted.includes(f)) }, null, 2));
    expect(counted.some((f) => f.endsWith('.wasm')), 'the core is part of it').toBe(true);
    expect(total, JSON.stringify(sizes)).toBeLessThanOrEqual(BUDGET);
  });

  it('shows the first plant on a "Fast 3G" network (the time goes to test-results/first-load.json)', async () => {
    const { millis, waterfall } = await firstPlant(true);
    writeFileSync(
      new URL('first-load.json', RESULTS),
      JSON.stringify({ network: 'Fast 3G (DevTools preset)', ...FAST_3G, firstPlantMillis: millis, waterfall }, null, 2),
    );
    expect(millis).toBeGreaterThan(FAST_3G.latency); // throttled: at least one round trip
    expect(millis).toBeLessThanOrEqual(FAST_3G_GUARD_MS);
  });
});

describe('the grammar before the editor has loaded', () => {
  it('is a plain textarea that builds what is typed, and the editor takes over its text, cursor and focus', async () => {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'block' });
    const page = await context.newPage();
    let release!: () => void;
    const released = new Promise<void>((resolve) => (release = resolve));
    // Hold the editor's chunk back: the studio must work without it meanwhile.
    await page.route(/\/assets\/grammar-editor-[^/]*\.js$/, async (route) => {
      await released;
      await route.continue();
    });
    await page.goto(site.base);
    await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0, undefined, { timeout: 30_000 });
    const area = page.getByTestId('grammar-placeholder');
    const first = await area.inputValue();
    expect(first).toContain('->');
    expect(await page.locator('[data-testid=editor] .cm-editor').count()).toBe(0);
    expect(await area.getAttribute('aria-label')).toBe('L-system grammar');

    // Typed early: built at once, as the editor's changes are.
    const before = Number((await page.getByTestId('status').getAttribute('data-generation')) ?? '0');
    await area.focus();
    await area.press('Control+End');
    await page.keyboard.type('\n// typed before the editor');
    await page.waitForFunction(
      (b) => Number(document.querySelector('[data-testid=status]')?.getAttribute('data-generation') ?? 0) > b && window.__meristem?.preview?.settled === true,
      before,
    );
    expect(await page.evaluate(() => window.__meristem!.preview!.lastGood!.source)).toContain('// typed before the editor');

    release();
    await page.locator('[data-testid=editor] .cm-content').waitFor();
    await page.evaluate(() => window.__meristem?.ready);
    expect(await area.count()).toBe(0);
    const lines = await page.evaluate(() => [...document.querySelectorAll('[data-testid=editor] .cm-line')].map((l) => l.textContent ?? '').join('\n'));
    expect(lines).toBe(`${first}\n// typed before the editor`);
    // The focus and the cursor (at the end) went over: typing goes on where it stopped.
    await page.keyboard.type('!');
    await expect.poll(() => page.evaluate(() => [...document.querySelectorAll('[data-testid=editor] .cm-line')].map((l) => l.textContent ?? '').join('\n'))).toBe(
      `${first}\n// typed before the editor!`,
    );
    await context.close();
  });
});
