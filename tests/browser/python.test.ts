// Python in the studio (issue 49): an L-Py model that the hand translation does not reach (a
// production whose body is Python) opened with the Open control is run by Pyodide, loaded from the
// site on first use in a worker of its own, and the plant it derived is drawn, with the notice
// saying how; a model that never ends is stopped with Stop, the user's text as it was. Laptop and
// phone.
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { decodePng, foregroundShare } from './pictures';
import { editorText, generation, nextBuild, PHONE, RESULTS, studioIn, VIEW_CANVAS, type StudioPage } from './studio-page';
import { writeFileSync } from 'node:fs';
import { zipSync } from 'fflate';

/**
 * A branching tree whose growth is Python: a function with a loop (which the hand translation
 * cannot carry), `if`, `produce` with computed parameters.
 */
const TREE = `from math import sqrt

def length(order):
    s = 1.0
    for i in range(order):
        s = s * sqrt(0.5)
    return s

Axiom: A(0)
derivation length: 5
production:
A(order):
    if order < 4:
        produce F(length(order)) [ +(35) A(order + 1) ] [ -(35) A(order + 1) ] A(order + 1)
    else:
        produce F(0.3)
endlsystem
`;

/** A production whose body never returns: only Stop (or the time limit) ends it. */
const LOOP = `Axiom: A
derivation length: 2
production:
A:
    n = 0
    while n >= 0:
        n += 1
    produce F A
endlsystem
`;

/** Text of the user's that must survive a stopped open. */
const MINE = '// mine\n#iterations 3\naxiom: F\nF -> F[+F]F';

let browser: Browser;

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
});

async function open(page: Page, name: string, text: string): Promise<void> {
  await page.getByTestId('file-input').setInputFiles({ name, mimeType: 'text/plain', buffer: Buffer.from(text) });
}

/** Opens `name` over text of the user's: answers Replace when asked; the build's status. */
async function openOver(page: Page, name: string, text: string): Promise<string | null> {
  const before = await generation(page);
  await open(page, name, text);
  const replace = page.getByTestId('confirm-replace-button');
  const deadline = Date.now() + 120_000;
  while (Date.now() < deadline && (await generation(page)) === before) {
    if (await replace.isVisible()) await replace.click();
    await page.waitForTimeout(200);
  }
  return nextBuild(page, before);
}

/** The share of the plant's canvas that is not background, from a screenshot of it. */
async function plantShare(page: Page, name: string): Promise<number> {
  const png = await page.locator(VIEW_CANVAS).screenshot();
  writeFileSync(new URL(name, RESULTS), png);
  return foregroundShare(decodePng(png));
}

/** The text of the plant on screen (the editor is behind a tab on a phone). */
function builtText(page: Page): Promise<string> {
  return page.evaluate(() => window.__meristem?.preview?.lastResult?.source ?? '');
}

async function noticeText(page: Page): Promise<string | null> {
  return page.getByTestId('notice-text').textContent();
}

describe('an L-Py model run by Python', () => {
  for (const [device, options] of [
    ['laptop', { viewport: { width: 1280, height: 800 } }],
    ['phone', PHONE],
  ] as const) {
    it(`opens through Open, loads Python once, and draws the plant Python derived (${device})`, async () => {
      const context = await browser.newContext(options);
      const { page, problems }: StudioPage = await studioIn(await context.newPage());
      const before = await generation(page);
      await open(page, 'tree.lpy', TREE);
      await expect.poll(() => noticeText(page), { timeout: 10_000 }).toMatch(/^(Loading Python \(about 13 MB, once\)…|Running tree\.lpy in Python…)$/);
      expect(await nextBuild(page, before, 120_000)).toBe('ok');
      expect(await noticeText(page)).toMatch(/^Imported tree\.lpy from L-Py/);
      // The text built (the editor is behind a tab on a phone): what Python derived, saying so.
      const text = await builtText(page);
      expect(text).toMatch(/^\/\/ Derived by Python from tree\.lpy in 5 steps, with seed 0/);
      // A(0)…A(3) each make one F and three children: 1 + 3 + 9 + 27 segments, and the 81 A(4) of
      // step 5 one F(0.3) each: 121, counted by hand.
      const stats = await page.evaluate(() => window.__meristem!.lastStats!);
      expect(stats.segments).toBe(121);
      expect(await plantShare(page, `python-tree-${device}.png`)).toBeGreaterThan(0.01);
      writeFileSync(new URL(`python-tree-page-${device}.png`, RESULTS), await page.screenshot());
      expect(problems).toEqual([]);
      await context.close();
    });
  }

  it('opens a zipped lpfg object whose production loops in C++, by Python, with its view file', async () => {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    const { page, problems } = await studioIn(await context.newPage());
    const encode = (text: string) => new TextEncoder().encode(text);
    const zip = zipSync({
      'loop/specifications': encode('lpfg lsystem.l view.v\n'),
      'loop/view.v': encode('line style: cylinder\n'),
      'loop/lsystem.l': encode('#include <lpfgall.h>\nderivation length: 1;\nmodule A(int);\nAxiom: A(3);\nA(n):\n{\n  for (int i = 0; i < n; i++)\n    nproduce F(1) SB() Left(30) F(0.5) EB();\n  produce;\n}\n'),
    });
    const before = await generation(page);
    await page.getByTestId('file-input').setInputFiles({ name: 'loop.zip', mimeType: 'application/zip', buffer: Buffer.from(zip) });
    expect(await nextBuild(page, before, 120_000)).toBe('ok');
    expect(await noticeText(page)).toMatch(/^Imported loop\.zip from /);
    expect(await builtText(page)).toMatch(/^\/\/ Derived by Python from (loop\/)?lsystem\.l in 1 step/);
    // Three F(1), each with a branch of F(0.5): six segments, by hand.
    expect(await page.evaluate(() => window.__meristem!.lastStats!.segments)).toBe(6);
    expect(problems).toEqual([]);
    await context.close();
  });

  it('stops a model that runs on, with Stop, and leaves the text as it was', async () => {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    const { page, problems } = await studioIn(await context.newPage());
    const before = await generation(page);
    await page.getByTestId('editor').locator('.cm-content').click();
    await page.keyboard.press('Control+A');
    await page.keyboard.insertText(MINE);
    expect(await nextBuild(page, before)).toBe('ok');
    await open(page, 'loop.lpy', LOOP);
    await expect.poll(() => noticeText(page), { timeout: 120_000 }).toBe('Running loop.lpy in Python…');
    await page.getByTestId('python-stop').click();
    await expect.poll(() => noticeText(page)).toBe('Could not open loop.lpy: you stopped Python while it ran loop.lpy; your text is as it was.');
    expect(await editorText(page)).toBe(MINE);
    // Python starts again for the next model (the stopped worker was ended).
    expect(await openOver(page, 'tree.lpy', TREE)).toBe('ok');
    expect(problems).toEqual([]);
    await context.close();
  });
});

describe('Python offline', () => {
  it('is kept by the service worker once a model has opened: the studio reloads offline and opens another', async () => {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    const { page, problems } = await studioIn(await context.newPage());
    await page.evaluate(async () => (await navigator.serviceWorker.ready).active?.state);
    await page.reload(); // controlled by the service worker from now on
    await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
    await page.evaluate(() => window.__meristem?.ready);
    // Nothing of Python is precached: a visitor who opens no model never downloads it.
    const precached = await page.evaluate(async () => (await Promise.all((await caches.keys()).map(async (name) => [name, (await (await caches.open(name)).keys()).map((r) => r.url)] as const))));
    expect(precached.flatMap(([, urls]) => urls).filter((url) => url.includes('/pyodide/'))).toEqual([]);
    const before = await generation(page);
    await open(page, 'tree.lpy', TREE);
    expect(await nextBuild(page, before, 120_000)).toBe('ok');
    const kept = await page.evaluate(async () => {
      const names = (await caches.keys()).filter((name) => name.startsWith('meristem-pyodide-'));
      return names.length === 1 ? (await (await caches.open(names[0])).keys()).map((r) => new URL(r.url).pathname.split('/').pop()).sort() : names;
    });
    expect(kept).toEqual(['pyodide-lock.json', 'pyodide.asm.mjs', 'pyodide.asm.wasm', 'pyodide.mjs', 'python_stdlib.zip']);
    await context.setOffline(true);
    await page.reload();
    await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0, undefined, { timeout: 30_000 });
    await page.evaluate(() => window.__meristem?.ready);
    expect(await openOver(page, 'tree.lpy', TREE.replace('derivation length: 5', 'derivation length: 4'))).toBe('ok');
    expect(await builtText(page)).toMatch(/^\/\/ Derived by Python from tree\.lpy in 4 steps/);
    expect(problems).toEqual([]);
    await context.close();
  });
});
