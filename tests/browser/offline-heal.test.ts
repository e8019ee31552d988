// End-to-end: a damaged offline cache heals (issue 50, finding 10). Garbage put in the service
// worker's copy of the core's wasm: online, the next load fetches it again and the plant grows;
// offline, the studio says the copy is damaged and to reconnect and reload. A damaged copy of the
// gallery's manifest: online, the gallery opens with its examples; offline, it says it could not
// read the list. The set-up is offline.test.ts's (the built site from a sub-path of a plain host).
import { chromium, type Browser, type BrowserContext, type Page } from 'playwright-core';
import { writeFileSync } from 'node:fs';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { RESULTS } from './studio-page';
import { serveStatic, type StaticSite } from './static-server';

const SUB_PATH = '/school/meristem/';

let site: StaticSite;
let browser: Browser;

beforeAll(async () => {
  site = await serveStatic(SUB_PATH);
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
  await site?.close();
});

async function plantShown(page: Page): Promise<void> {
  await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0, undefined, { timeout: 30_000 });
}

/** A new context's studio page, the first plant shown, the service worker active and in control. */
async function visited(): Promise<{ context: BrowserContext; page: Page }> {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  await page.goto(site.base);
  await plantShown(page);
  await page.evaluate(() => navigator.serviceWorker.ready);
  await page.reload();
  await plantShown(page);
  expect(await page.evaluate(() => navigator.serviceWorker.controller !== null)).toBe(true);
  return { context, page };
}

/**
 * Puts `garbage` in place of every precached file whose URL (without its query) matches `pattern`;
 * returns how many.
 */
function damage(page: Page, pattern: string, garbage: string): Promise<number> {
  return page.evaluate(
    async ([pattern, garbage]) => {
      const name = (await caches.keys()).find((key) => key.startsWith('workbox-precache'))!;
      const cache = await caches.open(name);
      let damaged = 0;
      for (const request of await cache.keys()) {
        if (!new RegExp(pattern).test(new URL(request.url).pathname)) continue;
        const type = (await cache.match(request))!.headers.get('Content-Type') ?? '';
        await cache.put(request, new Response(garbage, { headers: { 'Content-Type': type } }));
        damaged++;
      }
      return damaged;
    },
    [pattern, garbage],
  );
}

/** Whether every precached file matching `pattern` is valid wasm. */
function cachedWasmValid(page: Page, pattern: string): Promise<boolean> {
  return page.evaluate(async (pattern) => {
    const cache = await caches.open((await caches.keys()).find((key) => key.startsWith('workbox-precache'))!);
    const requests = (await cache.keys()).filter((r) => new RegExp(pattern).test(new URL(r.url).pathname));
    const valid = await Promise.all(requests.map(async (r) => WebAssembly.validate(await (await cache.match(r))!.arrayBuffer())));
    return valid.length > 0 && valid.every(Boolean);
  }, pattern);
}

describe('a damaged offline copy of the core', () => {
  it('is fetched again online (the plant grows at the next load), and offline the studio says what to do', async () => {
    const { context, page } = await visited();
    expect(await damage(page, '\\.wasm$', 'this is not WebAssembly')).toBeGreaterThan(0);
    await page.reload();
    await plantShown(page);
    // Both cores healed: the first plant's at once, the studio's when the worker loads it after the first plant.
    await expect.poll(() => cachedWasmValid(page, '\\.wasm$'), { message: 'the healed copies are kept', timeout: 20_000 }).toBe(true);

    expect(await damage(page, '\\.wasm$', 'this is not WebAssembly')).toBeGreaterThan(0);
    await context.setOffline(true);
    await page.reload();
    const status = page.getByTestId('status');
    await expect.poll(() => status.textContent(), { timeout: 30_000 }).toContain('Could not start');
    const said = (await status.textContent())!;
    writeFileSync(new URL('offline-damaged-core.png', RESULTS), await page.screenshot());
    expect(said).toContain('damaged');
    expect(said).toContain('connect to the network and reload');
    expect(said).not.toContain('CompileError');

    // Back online, a reload heals it.
    await context.setOffline(false);
    await page.reload();
    await plantShown(page);
    await expect.poll(() => cachedWasmValid(page, '\\.wasm$'), { timeout: 20_000 }).toBe(true);
    await context.close();
  });
});

describe('a damaged offline copy of the gallery’s manifest', () => {
  it('is fetched again online; offline the gallery says it could not read the list', async () => {
    const { context, page } = await visited();
    expect(await damage(page, '/examples/index\\.json$', '{"garbage": [')).toBe(1);
    await context.setOffline(true);
    await page.getByTestId('open-gallery').click();
    const list = page.getByTestId('gallery-list');
    await expect.poll(() => list.textContent(), { timeout: 10_000 }).toContain('The list of examples could not be read');
    expect(await list.textContent()).toContain('Connect to the network, then open the gallery again.');
    writeFileSync(new URL('offline-damaged-gallery.png', RESULTS), await page.screenshot());
    await page.keyboard.press('Escape');

    await context.setOffline(false);
    await page.getByTestId('open-gallery').click();
    await list.locator('button[data-file="abop-1.24a.lsys"]').waitFor({ timeout: 10_000 });
    expect(await list.locator('.gallery-unreadable').count()).toBe(0);
    // The copy in the cache is whole again: offline, the gallery opens from it.
    await page.keyboard.press('Escape');
    await page.reload();
    await plantShown(page);
    await context.setOffline(true);
    await page.getByTestId('open-gallery').click();
    await list.locator('button[data-file="abop-1.24a.lsys"]').waitFor({ timeout: 10_000 });
    await context.close();
  });
});
