// Deployment: the built site (dist/) served by a plain static file server from a sub-path, as any
// static host would, must load everything (gallery, wasm) with relative URLs, obey its own
// Content-Security-Policy (no inline script, no eval beyond wasm) and draw the plant.
import { createReadStream, existsSync, statSync } from 'node:fs';
import { createServer, type Server } from 'node:http';
import { extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium, type Browser } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { encodeState } from '../../web/src/share/codec';
import { decodePng, foregroundShare } from './pictures';

const DIST = fileURLToPath(new URL('../../dist/', import.meta.url));
const SUB_PATH = '/courses/botany/meristem/';
const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.wasm': 'application/wasm',
  '.lsys': 'text/plain; charset=utf-8',
  '.json': 'application/json',
  '.png': 'image/png',
};

let server: Server;
let base: string;
let browser: Browser;

/** A static server that knows nothing of the app: files under SUB_PATH, 404 for everything else. */
function serve(): Promise<Server> {
  const s = createServer((request, response) => {
    const path = decodeURIComponent(new URL(request.url ?? '/', 'http://x').pathname);
    if (!path.startsWith(SUB_PATH)) return void response.writeHead(404).end('not found');
    let file = normalize(join(DIST, path.slice(SUB_PATH.length)));
    if (!file.startsWith(DIST)) return void response.writeHead(403).end();
    if (existsSync(file) && statSync(file).isDirectory()) file = join(file, 'index.html');
    if (!existsSync(file)) return void response.writeHead(404).end('not found');
    response.writeHead(200, { 'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream' });
    createReadStream(file).pipe(response);
  });
  return new Promise((done) => s.listen(0, '127.0.0.1', () => done(s)));
}

beforeAll(async () => {
  server = await serve();
  const address = server.address();
  if (!address || typeof address === 'string') throw new Error('no address');
  base = `http://127.0.0.1:${address.port}${SUB_PATH}`;
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
  await new Promise((done) => server?.close(done));
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
    const shot = decodePng(await page.locator('[data-testid=viewport] canvas').screenshot());
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
    const lines = await page.evaluate(() => [...document.querySelectorAll('[data-testid=editor] .cm-line')].map((l) => l.textContent).join('\n'));
    expect(lines).toBe(text);
    expect(page.url()).toBe(base); // the fragment is consumed; the page stays under the sub-path
    expect(problems).toEqual([]);
    await page.close();
  });
});

