// Offline and installable (issue 22), on the built site served from a sub-path by a plain static
// host: after one visit the service worker holds the whole site, so with the network off the studio
// reloads, builds a new plant, opens a gallery example and a lesson; Chromium finds the app
// installable (manifest, icons, service worker); a new deployment shows "A new version is ready",
// and Reload switches to it.
import { chromium, type Browser, type BrowserContext, type Page } from 'playwright-core';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { decodePng } from './pictures';
import { generation, nextBuild, pasteText, RESULTS, VIEW_CANVAS } from './studio-page';
import { serveStatic, type StaticSite } from './static-server';

const SUB_PATH = '/school/meristem/';
const DIST = new URL('../../dist/', import.meta.url);

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

/** A new context's studio page, its problems, the first plant shown and the service worker active. */
async function firstVisit(): Promise<{ context: BrowserContext; page: Page; problems: string[] }> {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  const problems: string[] = [];
  page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
  await page.goto(site.base);
  await plantShown(page);
  // Installed: everything is precached before the worker activates.
  expect(await page.evaluate(async () => (await navigator.serviceWorker.ready).active?.state)).toMatch(/activat/);
  return { context, page, problems };
}

async function plantShown(page: Page): Promise<void> {
  await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0, undefined, { timeout: 30_000 });
}

describe('offline', () => {
  it('reloads with the network off and builds a plant, opens an example and a lesson', async () => {
    const { context, page, problems } = await firstVisit();
    await context.setOffline(true);
    const served = site.requests;
    await page.reload();
    await plantShown(page);
    expect(await page.evaluate(() => navigator.serviceWorker.controller !== null), 'the service worker serves the page').toBe(true);

    // A grammar of the user's: built by the worker's wasm, from the cache.
    expect(await pasteText(page, '// Offline\n#angle 22.5\n#iterations 4\naxiom: F\nF -> FF-[-F+F+F]+[+F-F-F]')).toBe('ok');
    expect(await page.evaluate(() => window.__meristem!.lastStats)).toMatchObject({ iterations: 4, segments: 8 ** 4 });
    const png = await page.locator(VIEW_CANVAS).screenshot();
    writeFileSync(new URL('offline-plant.png', RESULTS), png);
    expect(decodePng(png).width).toBeGreaterThan(0);

    // The gallery (its manifest, the example files) and a lesson, from the cache.
    await page.getByTestId('open-gallery').click();
    const card = page.locator('[data-testid=gallery-list] button[data-file="abop-1.24a.lsys"]');
    await card.scrollIntoViewIfNeeded();
    const opened = await generation(page);
    await card.click();
    const replace = page.getByTestId('confirm-replace-button');
    await replace.waitFor({ timeout: 5_000 }).then(() => replace.click(), () => undefined);
    expect(await nextBuild(page, opened)).toBe('ok');
    await page.getByTestId('open-learn').click();
    await page.getByTestId('learn-contents').locator('button, a').first().click();
    await page.getByTestId('learn-lesson').locator('.lesson-body').waitFor();
    expect(site.requests, 'nothing reached the server').toBe(served);
    expect(problems).toEqual([]);
    await context.close();
  });

  it('is installable: a manifest with icons, a service worker, from the sub-path', async () => {
    // Chromium never offers to install from an incognito-like context: a real profile, for once.
    const profile = mkdtempSync(join(tmpdir(), 'meristem-profile-'));
    const context = await chromium.launchPersistentContext(profile, { executablePath: '/usr/bin/chromium' });
    try {
      const page = await context.newPage();
      await page.goto(site.base);
      await plantShown(page);
      await page.evaluate(() => navigator.serviceWorker.ready);
      const cdp = await context.newCDPSession(page);
      const manifest = (await cdp.send('Page.getAppManifest')) as { url: string; errors: unknown[] };
      expect(manifest.url).toBe(`${site.base}manifest.webmanifest`);
      expect(manifest.errors).toEqual([]);
      const { installabilityErrors } = (await cdp.send('Page.getInstallabilityErrors')) as { installabilityErrors: unknown[] };
      expect(installabilityErrors).toEqual([]);
    } finally {
      await context.close();
      rmSync(profile, { recursive: true, force: true });
    }
    const icons = JSON.parse(readFileSync(new URL('manifest.webmanifest', DIST), 'utf8')).icons as { src: string; sizes: string; type: string }[];
    expect(icons.some((i) => i.sizes === '512x512' && i.type === 'image/png')).toBe(true);
    for (const icon of icons.filter((i) => i.type === 'image/png')) {
      const picture = decodePng(readFileSync(new URL(icon.src, DIST)));
      expect(`${picture.width}x${picture.height}`, icon.src).toBe(icon.sizes);
    }
  });

  it('says when a new version is ready, and Reload switches to it', async () => {
    const { context, page, problems } = await firstVisit();
    await page.reload(); // now controlled by the first version
    await plantShown(page);
    const first = await page.evaluate(() => navigator.serviceWorker.controller?.scriptURL);
    expect(first).toBe(`${site.base}sw.js`);
    expect(await page.getByTestId('update-ready').count()).toBe(0);

    // A new deployment: another service worker (here the same, one byte different).
    site.replaced.set('sw.js', `${readFileSync(new URL('sw.js', DIST), 'utf8')}\n// the next version\n`);
    await page.evaluate(async () => (await navigator.serviceWorker.getRegistration())?.update());
    const bar = page.getByTestId('update-ready');
    await bar.waitFor({ timeout: 30_000 });
    expect(await bar.textContent()).toContain('A new version is ready — reload');
    writeFileSync(new URL('offline-update-ready.png', RESULTS), await page.screenshot());
    const reloaded = page.waitForEvent('load', { timeout: 30_000 });
    await page.getByTestId('update-reload').click();
    await reloaded;
    await plantShown(page);
    expect(await page.getByTestId('update-ready').count(), 'no bar after the switch').toBe(0);
    expect(await page.evaluate(async () => (await navigator.serviceWorker.getRegistration())?.waiting ?? null), 'nothing waits').toBeNull();
    site.replaced.clear();
    expect(problems).toEqual([]);
    await context.close();
  });
});
