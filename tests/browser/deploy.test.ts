// Deployment: the built site (dist/) served by a plain static file server from a sub-path, as any
// static host would, must load everything (gallery, wasm) with relative URLs, obey its own
// Content-Security-Policy (no inline script, no eval beyond wasm) and draw the plant.
import { chromium, type Browser } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { encodeState } from '../../web/src/share';
import { decodePng, foregroundShare } from './pictures';
import { serveStatic, type StaticSite } from './static-server';
import { VIEW_CANVAS } from './studio-page';

const SUB_PATH = '/courses/botany/meristem/';

let site: StaticSite;
let base: string;
let browser: Browser;

beforeAll(async () => {
  site = await serveStatic(SUB_PATH);
  base = site.base;
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
  await site?.close();
});

describe('deployment from a sub-path of a static host', () => {
  it('loads everything relative to the page, obeys its CSP and draws the plant', async () => {
    const page = await browser.newPage({ viewport: { width: 1024, height: 700 } });
    const problems: string[] = [];
    page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('response', (r) => r.status() >= 400 && problems.push(`HTTP ${r.status()} ${r.url()}`));
    await page.addInitScript(() => {
      document.addEventListener('securitypolicyviolation', (e) => console.error(`CSP violation: ${e.violatedDirective} ${e.blockedURI}`));
    });
    await page.goto(base);
    await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0, undefined, { timeout: 30_000 });
    const csp = await page.locator('meta[http-equiv="Content-Security-Policy"]').getAttribute('content');
    expect(csp).toContain("script-src 'self' 'wasm-unsafe-eval'");
    expect(csp).not.toContain("'unsafe-eval'");
    await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
    const shot = decodePng(await page.locator(VIEW_CANVAS).screenshot());
    expect(foregroundShare(shot), 'the plant is drawn').toBeGreaterThan(0.003);
    // The gallery file came from the sub-path.
    expect(await page.evaluate(() => performance.getEntriesByType('resource').map((e) => e.name).filter((n) => n.endsWith('.lsys'))))
      .toEqual([expect.stringContaining(`${SUB_PATH}examples/`)]);
    expect(problems).toEqual([]);
    // The policy is in force: an inline script injected into the page does not run.
    const ran = await page.evaluate(async () => {
      const script = document.createElement('script');
      script.textContent = 'window.__inlineRan = true';
      document.body.append(script);
      await new Promise((done) => setTimeout(done, 50));
      return (window as unknown as { __inlineRan?: boolean }).__inlineRan === true;
    });
    expect(ran, 'inline script is blocked').toBe(false);
    expect(problems.some((p) => p.includes('CSP violation'))).toBe(true);
    await page.close();
  });

  it('opens a share link there', async () => {
    const page = await browser.newPage({ viewport: { width: 1024, height: 700 } });
    const problems: string[] = [];
    page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('response', (r) => r.status() >= 400 && problems.push(`HTTP ${r.status()} ${r.url()}`));
    const text = '// Shared from a course page\n#angle 20\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF';
    await page.goto(base + (await encodeState({ text, iterations: 5, seed: 3 })));
    await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0, undefined, { timeout: 30_000 });
    expect(await page.evaluate(() => window.__meristem!.lastStats!.iterations)).toBe(5);
    expect(await page.getByTestId('iterations').inputValue()).toBe('5');
    await page.evaluate(() => window.__meristem?.ready); // the editor loads after the first plant
    const lines = await page.evaluate(() => [...document.querySelectorAll('[data-testid=editor] .cm-line')].map((l) => l.textContent).join('\n'));
    expect(lines).toBe(text);
    expect(page.url()).toBe(base); // the fragment is consumed; the page stays under the sub-path
    expect(problems).toEqual([]);
    await page.close();
  });
});

