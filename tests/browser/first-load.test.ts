// The first load (issue 22): what the studio downloads until the first plant is on screen, gzipped
// as a static host serves it, against the budget; and the time to that first plant on a slow
// network (Chromium's DevTools "Fast 3G": 562.5 ms round trip, 1.6 Mbit/s down, 750 kbit/s up),
// recorded in test-results/first-load.json for the README (a measurement, not a timed test).
import { readFileSync, writeFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { chromium, type Browser } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { RESULTS } from './studio-page';
import { serveStatic, type StaticSite } from './static-server';

/**
 * Script + wasm + styles of the first paint of a plant, gzipped (bytes). Issue 22 asks for 400 KB;
 * this guards what the studio reaches now (635 KB: 285 KB of wasm without the importers and
 * exporters, 343 KB of script, three.js and CodeMirror most of it), a ratchet to lower, never to
 * raise without a reason. README "Performance" says what remains.
 */
const BUDGET = 640 * 1024;
const SUB_PATH = '/first/load/';
const DIST = new URL('../../dist/', import.meta.url);
const FAST_3G = { offline: false, latency: 562.5, downloadThroughput: (1.6 * 1024 * 1024 * 0.9) / 8, uploadThroughput: (750 * 1024 * 0.9) / 8 };

let site: StaticSite;
let browser: Browser;

beforeAll(async () => {
  site = await serveStatic(SUB_PATH, { gzip: true });
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
  await site?.close();
});

/** Opens the studio in a fresh context (no cache, no service worker); returns the site files it fetched until the first plant. */
async function firstPlant(throttle: boolean): Promise<{ files: string[]; millis: number }> {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'block' });
  const page = await context.newPage();
  const files = new Set<string>();
  let done = false;
  context.on('request', (request) => {
    const url = new URL(request.url());
    if (!done && url.pathname.startsWith(SUB_PATH)) files.add(url.pathname.slice(SUB_PATH.length) || 'index.html');
  });
  if (throttle) await (await context.newCDPSession(page)).send('Network.emulateNetworkConditions', FAST_3G);
  const start = Date.now();
  await page.goto(site.base);
  await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0, undefined, { timeout: 60_000, polling: 50 });
  const millis = Date.now() - start;
  done = true;
  await context.close();
  return { files: [...files].sort(), millis };
}

/** The gzipped size of a file of dist/. */
function gzipped(file: string): number {
  return gzipSync(readFileSync(new URL(file, DIST)), { level: 9 }).length;
}

describe('the first load', () => {
  it(`needs at most ${BUDGET / 1024} KB of script, wasm and styles (gzipped) for the first plant`, async () => {
    const { files } = await firstPlant(false);
    const counted = files.filter((f) => /\.(js|mjs|wasm|css)$/.test(f));
    const sizes = Object.fromEntries(counted.map((f) => [f, gzipped(f)]));
    const total = Object.values(sizes).reduce((a, b) => a + b, 0);
    writeFileSync(new URL('first-load-files.json', RESULTS), JSON.stringify({ total, sizes, other: files.filter((f) => !counted.includes(f)) }, null, 2));
    expect(counted.some((f) => f.endsWith('.wasm')), 'the core is part of it').toBe(true);
    expect(total, JSON.stringify(sizes)).toBeLessThanOrEqual(BUDGET);
  });

  it('shows the first plant on a "Fast 3G" network (the time goes to test-results/first-load.json)', async () => {
    const { millis } = await firstPlant(true);
    writeFileSync(new URL('first-load.json', RESULTS), JSON.stringify({ network: 'Fast 3G (DevTools preset)', ...FAST_3G, firstPlantMillis: millis }, null, 2));
    expect(millis).toBeGreaterThan(FAST_3G.latency); // throttled: at least one round trip
  });
});
