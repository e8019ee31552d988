// End-to-end (issue 19, the studio): nothing the user opens loses their text or freezes the page.
// With localStorage full, opening a shared link (in a new tab, or in the same tab after Replace)
// keeps the earlier text in IndexedDB, or, when nothing can keep it, asks to download it first; a
// long build says "Building… step k of n" (never an older plant's figures, never "Loading…" for
// ever) and Stop ends it with the text intact; a pathological file of another dialect is imported
// in a worker, with Cancel and a time limit, while the page answers. A WebGL context the browser
// takes away and gives back (a phone's browser sent to the background) shows the plant again. On a
// phone, a grammar's errors are read in full (Problems), not cut to the status line's width.
import { readFileSync } from 'node:fs';
import { deflateRawSync } from 'node:zlib';
import { chromium, type Browser, type BrowserContext, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { foregroundOverlap, foregroundShare } from './pictures';
import { canvasPicture, editorText, generation, loseAndRestoreContext, nextBuild, pasteText, PHONE, replaceTextByTouch, VIEW_CANVAS } from './studio-page';

let browser: Browser;

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
});

/** A browser context of its own (its own storage); `noDatabase` takes IndexedDB away from its pages. */
async function newContext(noDatabase = false): Promise<BrowserContext> {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, acceptDownloads: true });
  if (noDatabase) await context.addInitScript(() => Object.defineProperty(window, 'indexedDB', { value: undefined, configurable: true }));
  return context;
}

/** Opens `url` in `context` and records the page's errors; `plant` waits for the first plant. */
async function openAt(url: string, context: BrowserContext, plant = true): Promise<{ page: Page; problems: string[] }> {
  const page = await context.newPage();
  const problems: string[] = [];
  page.on('console', (m) => m.type() === 'error' && problems.push(`console error: ${m.text()}`));
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  await page.goto(url);
  if (plant) {
    await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0, undefined, { timeout: 30_000 });
    await page.waitForFunction(() => window.__meristem?.preview?.settled === true);
  }
  return { page, problems };
}

/** Replaces the editor's text by pasting `text`; `built` waits for its build. */
async function typeText(page: Page, text: string, built = true): Promise<void> {
  const before = await generation(page);
  await page.getByTestId('editor').locator('.cm-content').click();
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText(text);
  if (built) await nextBuild(page, before);
}

/** Fills the page's localStorage to its last byte; returns how many items that took. */
function fillStorage(page: Page): Promise<number> {
  return page.evaluate(() => {
    let size = 1 << 20;
    let items = 0;
    while (size >= 1) {
      try {
        localStorage.setItem(`filler-${items}`, 'x'.repeat(size));
        items++;
      } catch {
        size = Math.floor(size / 2);
      }
    }
    return items;
  });
}

/** A share link's fragment holding `text`. */
const linkOf = (text: string, iterations = 2) => `#s=1.${Buffer.from(deflateRawSync(Buffer.from(JSON.stringify({ v: 1, text, iterations })))).toString('base64url')}`;

const MINE = '// my precious bush\n#angle 30\naxiom: F\nF -> F[+F]F[-F]F';
const THEIRS = '// from a friend\n#angle 90\naxiom: F-F-F-F\nF -> F+F-F';

/** Opens My grammars and returns its items. */
async function libraryItems(page: Page) {
  await page.getByTestId('file-menu').locator('summary').click();
  await page.getByTestId('open-library').click();
  const items = page.getByTestId('library-list').locator('li');
  await items.first().waitFor();
  return items;
}

/** Types MINE in a fresh studio of `context`, waits for its autosave, then fills localStorage. */
async function myWorkWithStorageFull(context: BrowserContext): Promise<{ page: Page; problems: string[] }> {
  const opened = await openAt(inject('studioUrl'), context);
  await typeText(opened.page, MINE);
  await opened.page.waitForTimeout(600); // autosave waits for a pause in typing
  expect(await fillStorage(opened.page)).toBeGreaterThan(1);
  // Full indeed: My grammars cannot save anything now.
  expect(await opened.page.evaluate(() => {
    try {
      localStorage.setItem('one-more', 'y'.repeat(64));
      return true;
    } catch {
      return false;
    }
  })).toBe(false);
  return opened;
}

describe('with localStorage full, opening a link never loses the text', () => {
  it('in a new tab: the text is kept in IndexedDB, said truthfully, listed in My grammars and opens again', async () => {
    const context = await newContext();
    const first = await myWorkWithStorageFull(context);
    await first.page.close();
    const { page, problems } = await openAt(inject('studioUrl') + linkOf(THEIRS), context);
    expect(await editorText(page)).toBe(THEIRS);
    expect(await page.getByTestId('notice-text').textContent()).toBe(
      'Opened a shared link. Your previous text is kept in My grammars as “Before a shared link: my precious bush” (in this browser’s database: its other storage is full).',
    );
    const items = await libraryItems(page);
    const kept = items.filter({ hasText: 'Before a shared link: my precious bush' });
    expect(await kept.getAttribute('data-kept')).toBe('database');
    // The kept text comes back (the link's text is the user's now: asked first).
    await kept.getByTestId('library-open').click();
    await page.getByTestId('confirm-replace-button').click();
    await expect.poll(() => editorText(page)).toBe(MINE);
    // And a download of it is offered from the list (the link's text, replaced in turn, is kept too).
    const again = await libraryItems(page);
    expect(await again.filter({ hasText: /^Before “Before a shared link: my precious bush”: from a friend/ }).getAttribute('data-kept')).toBe('database');
    const mineAgain = again.filter({ hasText: /^Before a shared link: my precious bush/ });
    const [download] = await Promise.all([page.waitForEvent('download'), mineAgain.getByTestId('library-download').click()]);
    expect(readFileSync(await download.path(), 'utf8')).toBe(MINE);
    expect(problems).toEqual([]);
    await context.close();
  });

  it('in the same tab, after Replace: the text is kept in IndexedDB first', async () => {
    const context = await newContext();
    const { page, problems } = await myWorkWithStorageFull(context);
    await page.evaluate((hash) => (location.hash = hash), linkOf(THEIRS));
    await page.getByTestId('confirm-replace-button').click();
    await expect.poll(() => editorText(page)).toBe(THEIRS);
    await expect.poll(() => page.getByTestId('notice-text').textContent()).toBe(
      'Opened a shared link. Your previous text is kept in My grammars as “Before a shared link: my precious bush” (in this browser’s database: its other storage is full).',
    );
    const items = await libraryItems(page);
    expect(await items.filter({ hasText: 'Before a shared link: my precious bush' }).getAttribute('data-kept')).toBe('database');
    // A reload still finds it (IndexedDB outlives the page).
    await page.reload();
    await page.waitForFunction(() => window.__meristem?.preview?.settled === true && (window.__meristem.lastStats?.segments ?? 0) > 0);
    expect(await (await libraryItems(page)).filter({ hasText: 'Before a shared link: my precious bush' }).count()).toBe(1);
    expect(problems).toEqual([]);
    await context.close();
  });

  it('with no storage that can keep it: the link opens only after the text is downloaded, or not at all', async () => {
    const context = await newContext(true);
    const first = await myWorkWithStorageFull(context);
    await first.page.close();
    // Declined: the studio opens with the user's text, and says why the link was not opened.
    const declined = await openAt(inject('studioUrl') + linkOf(THEIRS), context, false);
    await declined.page.getByTestId('cannot-keep').waitFor();
    await declined.page.getByTestId('cannot-keep-cancel').click();
    await declined.page.waitForFunction(() => window.__meristem?.preview?.settled === true && (window.__meristem.lastStats?.segments ?? 0) > 0);
    expect(await editorText(declined.page)).toBe(MINE);
    expect(await declined.page.getByTestId('notice-text').textContent()).toMatch(/^The shared link was not opened, so your text stays as it was: this browser’s storage is full/);
    expect(declined.problems).toEqual([]);
    await declined.page.close();
    // Downloaded: the file holds the text, then the link opens, and the notice says where it went.
    const { page, problems } = await openAt(inject('studioUrl') + linkOf(THEIRS), context, false);
    await page.getByTestId('cannot-keep').waitFor();
    const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('cannot-keep-download').click()]);
    expect(download.suggestedFilename()).toBe('my-precious-bush.lsys');
    expect(readFileSync(await download.path(), 'utf8')).toBe(MINE);
    await page.waitForFunction(() => window.__meristem?.preview?.settled === true && (window.__meristem.lastStats?.segments ?? 0) > 0);
    expect(await editorText(page)).toBe(THEIRS);
    expect(await page.getByTestId('notice-text').textContent()).toBe(
      'Opened a shared link. Your previous text was downloaded as my-precious-bush.lsys: this browser’s storage could not keep it.',
    );
    expect(problems).toEqual([]);
    await context.close();
  });
});

/**
 * Derives for minutes: 200,000 steps over a string that grows by one module a step (2·10^10
 * modules written: the module limit is raised so that the work budget, 20 times it, does not
 * end it first).
 */
const SLOW = '// slow\n#max_modules 1000000000\n#max_steps 1000000\n#iterations 200000\naxiom: A\nA -> AB';
const status = (page: Page) => page.getByTestId('status');

/** Waits until the status says the build is at some derivation step; returns the step. */
async function stepShown(page: Page, after = -1): Promise<number> {
  let step = -1;
  await expect
    .poll(async () => {
      const match = /^Building… step ([\d,]+) of 200,000/.exec((await status(page).textContent()) ?? '');
      step = match ? Number(match[1].replace(/,/g, '')) : -1;
      return step > after;
    }, { timeout: 20_000 })
    .toBe(true);
  return step;
}

describe('a long build', () => {
  it('says "Building… step k of n" (never the older plant’s figures) and Stop ends it with the text intact', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl'), context);
    // Every status text from now on.
    await page.evaluate(() => {
      const seen: string[] = ((window as unknown as { seenStatus: string[] }).seenStatus = []);
      const el = document.querySelector('[data-testid=status]')!;
      new MutationObserver(() => seen.push(`${el.getAttribute('data-state')}: ${el.textContent}`)).observe(el, { childList: true, characterData: true, subtree: true, attributes: true });
    });
    await typeText(page, SLOW, false);
    const first = await stepShown(page);
    expect(await status(page).getAttribute('data-state')).toBe('building');
    expect(await page.getByTestId('build-stop').isVisible()).toBe(true);
    await stepShown(page, first); // it moves on
    const seen = await page.evaluate(() => (window as unknown as { seenStatus: string[] }).seenStatus);
    expect(seen.filter((s) => s.startsWith('ok:')), 'no plant figures while building').toEqual([]);
    expect(seen.filter((s) => s.startsWith('building: Building… step')).length).toBeGreaterThan(1);
    await page.getByTestId('build-stop').click();
    await expect.poll(() => status(page).getAttribute('data-state')).toBe('stopped');
    expect(await status(page).textContent()).toBe('Build stopped — the plant shown is of an earlier text; change the text or an option to build again');
    expect(await page.getByTestId('build-stop').isHidden()).toBe(true);
    expect(await page.locator('#stale-badge').textContent()).toBe('Stale — the build was stopped');
    expect(await page.locator('#stale-badge').isVisible()).toBe(true);
    expect(await editorText(page)).toBe(SLOW);
    // The next change builds again, in a fresh worker.
    const before = await generation(page);
    await page.getByTestId('editor').locator('.cm-content').click();
    await page.keyboard.press('Control+A');
    await page.keyboard.insertText('axiom: F+F+F');
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await page.locator('#stale-badge').isHidden()).toBe(true);
    expect(problems).toEqual([]);
    await context.close();
  });

  it('leaves the String and Derivation panels showing the plant on screen after Stop, marked as of an earlier text', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl'), context);
    const shown = '// shown\n#iterations 5\n#angle 25\naxiom: A\nA -> F[+A][-A]FA';
    await typeText(page, shown);
    const modules = page.getByTestId('string-panel').locator('.m');
    await expect.poll(() => modules.count()).toBeGreaterThan(40);
    // Each module shown, by its index (how many rows are in view may change with the layout).
    const shownModules = () => modules.evaluateAll((spans) => spans.map((s) => [(s as HTMLElement).dataset.i!, s.textContent!] as const));
    const stringBefore = new Map(await shownModules());
    await page.getByTestId('tab-derivation').click();
    const rows = page.getByTestId('derivation').locator('.dv-row');
    await expect.poll(() => rows.count()).toBe(6); // steps 0 to 5
    const derivationBefore = await page.getByTestId('derivation').textContent();
    await page.getByTestId('tab-string').click();
    expect(await page.getByTestId('inspector-stale').isHidden()).toBe(true);

    await typeText(page, SLOW, false);
    await stepShown(page);
    await page.getByTestId('build-stop').click();
    await expect.poll(() => status(page).getAttribute('data-state')).toBe('stopped');
    // Marked as the view is, and still the plant on screen: the string, also once scrolled away and
    // back (rows asked for anew, after the worker that kept the plant was terminated)…
    expect(await page.getByTestId('inspector-stale').isVisible()).toBe(true);
    expect(await page.getByTestId('inspector-stale').textContent()).toBe('Of the plant shown (an earlier text)');
    expect(await page.locator('#stale-badge').isVisible()).toBe(true);
    const sameAsBefore = async () => {
      const now = await shownModules();
      const compared = now.filter(([i]) => stringBefore.has(i));
      return now.length > 40 && compared.length > 40 && compared.every(([i, text]) => stringBefore.get(i) === text);
    };
    await expect.poll(sameAsBefore).toBe(true);
    const scroller = page.getByTestId('string-panel');
    await scroller.evaluate((el) => (el.scrollTop = el.scrollHeight));
    await expect.poll(() => modules.first().getAttribute('data-i')).not.toBe('0');
    expect(await modules.count()).toBeGreaterThan(0);
    await scroller.evaluate((el) => (el.scrollTop = 0));
    await expect.poll(() => modules.first().getAttribute('data-i')).toBe('0');
    await expect.poll(sameAsBefore).toBe(true);
    // …and the derivation, shown after the Stop.
    await page.getByTestId('tab-derivation').click();
    await expect.poll(() => page.getByTestId('derivation').textContent()).toBe(derivationBefore);
    expect(await rows.count()).toBe(6);
    // A module picked in the panel is still explained by the plant shown.
    await page.getByTestId('tab-string').click();
    await modules.nth(3).click();
    await expect.poll(() => page.getByTestId('explain-summary').textContent()).not.toBe('');
    expect(await editorText(page)).toBe(SLOW);

    // The next build is of the text now: the mark goes.
    await typeText(page, 'axiom: F+F+F');
    expect(await page.getByTestId('inspector-stale').isHidden()).toBe(true);
    expect(problems).toEqual([]);
    await context.close();
  });

  it('opened from a link, and after a reload, says it is building, not "Loading…"', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl') + linkOf(SLOW, 200_000), context, false);
    await stepShown(page);
    await page.getByTestId('build-stop').click();
    await expect.poll(() => status(page).textContent()).toBe('Build stopped — no plant yet; change the text or an option to build again');
    expect(await editorText(page)).toBe(SLOW);
    await page.waitForTimeout(600); // the link's text is autosaved
    await page.reload();
    await stepShown(page);
    expect(await editorText(page)).toBe(SLOW);
    await page.getByTestId('build-stop').click();
    await expect.poll(() => status(page).getAttribute('data-state')).toBe('stopped');
    expect(problems).toEqual([]);
    await context.close();
  });
});

/**
 * A cpfg file the importer takes a few seconds on (the test is about the page, not the importer):
 * 165 `#if`s, each nesting a macro of one argument 1,990 deep, which the preprocessor expands one
 * level at a time, parsing the rest of the line again each time. Measured in Node on 2026-11-30:
 * 4.8 s for its 987 KB (the studio opens files up to 1 MB). The importers used to be slower on
 * some files than the 10 s limit; now each cap is on the whole file too (issue 50), so the test
 * of the limit lowers it (`importTimeLimitMs`) rather than look for a slower file.
 */
function pathologicalCpfg(): Buffer {
  const nested = `${'R('.repeat(1990)}1${')'.repeat(1990)}`;
  const conditions = `#if ${nested}\n#endif\n`.repeat(165);
  return Buffer.from(`#define R(x) x\n${conditions}Lsystem: 1\nderivation length: 1\nAxiom: F\nendlsystem\n`);
}

describe('importing a pathological file', () => {
  it('runs off the page’s thread: the page answers, and Cancel stops it with the text as it was', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl'), context);
    await typeText(page, MINE);
    await page.getByTestId('file-input').setInputFiles({ name: 'slow.l', mimeType: 'text/plain', buffer: pathologicalCpfg() });
    await expect.poll(() => page.getByTestId('notice-text').textContent()).toBe('Importing slow.l…');
    // The page answers while the importer works: a round trip and typing in the editor are quick.
    const start = Date.now();
    await page.evaluate(() => 1 + 1);
    await page.getByTestId('editor').locator('.cm-content').click();
    await page.keyboard.press('Control+End');
    await page.keyboard.insertText('\n// still typing');
    expect(Date.now() - start).toBeLessThan(2000);
    await expect.poll(() => editorText(page)).toBe(`${MINE}\n// still typing`);
    await page.getByTestId('import-cancel').click();
    await expect.poll(() => page.getByTestId('notice-text').textContent()).toBe('Could not open slow.l: the import was cancelled; your text is as it was.');
    expect(await editorText(page)).toBe(`${MINE}\n// still typing`);
    expect(await page.getByTestId('confirm-replace').isVisible()).toBe(false);
    expect(problems).toEqual([]);
    await context.close();
  });

  it('stops an import that runs past its time limit, and says so', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl'), context);
    const text = await editorText(page);
    await page.evaluate(() => {
      if (window.__meristem) window.__meristem.importTimeLimitMs = 1000;
    });
    await page.getByTestId('file-input').setInputFiles({ name: 'slow.l', mimeType: 'text/plain', buffer: pathologicalCpfg() });
    await expect
      .poll(() => page.getByTestId('notice-text').textContent(), { timeout: 20_000 })
      .toMatch(/^Could not open slow\.l: importing it took longer than 1 s, so it was stopped .*; your text is as it was\.$/);
    expect(await editorText(page)).toBe(text);
    expect(problems).toEqual([]);
    await context.close();
  });
});

/** Grammars the old filter refused: each is shared with the Share button and its link opened. */
const LEGAL_GRAMMARS = [
  '// onset\n#define onset = 2\naxiom: F(onset)',
  '// a comment with javascript:alert(1) in it\naxiom: F+F+F',
  '// spans\n#module span\n#iterations 3\naxiom: span\nspan -> F[+span]F',
  '// contexts\n#ignore +-\naxiom: b<a>a F\nb < a -> b',
];

/** `n` characters of grammar comment that deflate cannot shrink much. */
function incompressible(n: number): string {
  let x = 12345;
  let text = '// too long for a link\naxiom: F\n// ';
  while (text.length < n) {
    x = (x * 48271) % 2147483647;
    text += String.fromCharCode(33 + (x % 90));
  }
  return text;
}

describe('sharing', () => {
  it('makes links of legal grammars the old filter refused, and each opens in another browser', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl'), context);
    for (const grammar of LEGAL_GRAMMARS) {
      await typeText(page, grammar);
      await page.getByTestId('share').click();
      // The dialog opens once the state is encoded (the codec loads on the first Share).
      await page.getByTestId('share-dialog').waitFor({ state: 'visible' });
      const link = await page.getByTestId('share-link').inputValue();
      expect(link).toMatch(/#s=1\./);
      expect(await page.getByTestId('share-too-long').isHidden()).toBe(true);
      await page.keyboard.press('Escape');
      const other = await newContext();
      const opened = await openAt(link, other);
      expect(await editorText(opened.page)).toBe(grammar);
      expect(await opened.page.getByTestId('notice').isHidden()).toBe(true);
      expect(opened.problems).toEqual([]);
      await other.close();
    }
    expect(problems).toEqual([]);
    await context.close();
  });

  it('warns the sender of a grammar too long for a link and offers the grammar as a file', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl'), context);
    const long = incompressible(120_000);
    await page.getByTestId('editor').locator('.cm-content').click();
    await page.keyboard.press('Control+A');
    await page.keyboard.insertText(long);
    await page.getByTestId('share').click();
    await page.getByTestId('share-too-long').waitFor();
    expect(await page.getByTestId('share-too-long-text').textContent()).toMatch(
      /^This plant cannot be shared as a link: the link would be [\d,]+ characters long, and a link holds at most 65,536\. Download the grammar and send the file instead/,
    );
    expect(await page.getByTestId('share-link').isHidden()).toBe(true);
    const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('share-download').click()]);
    expect(download.suggestedFilename()).toBe('too-long-for-a-link.lsys');
    expect(readFileSync(await download.path(), 'utf8')).toBe(long);
    // A short grammar is a link again.
    await page.keyboard.press('Escape');
    await typeText(page, 'axiom: F');
    await page.getByTestId('share').click();
    await expect.poll(() => page.getByTestId('share-link').inputValue()).toMatch(/#s=1\./);
    expect(await page.getByTestId('share-too-long').isHidden()).toBe(true);
    expect(problems).toEqual([]);
    await context.close();
  });
});

describe('the vocabulary (loaded after the first plant)', () => {
  it('when its fetch fails, the studio still starts, and the next edit fetches it for the sliders', async () => {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'block' });
    let asked = 0;
    await context.route(/\/vocabulary[^/]*\.json$/, (route) => (++asked === 1 ? route.abort() : route.continue()));
    const { page, problems } = await openAt(inject('studioUrl'), context);
    await page.evaluate(() => window.__meristem?.ready); // resolves without the vocabulary
    expect(asked).toBe(1);
    expect(await page.getByTestId('growth-lifetime').count(), 'no Growth panel without the vocabulary').toBe(0);
    // The text is there and editable (the editor stays the plain text box it started as).
    const box = page.getByTestId('editor').locator('textarea');
    const before = await generation(page);
    await box.click();
    await page.keyboard.press('Control+End');
    await page.keyboard.type('\n#define k 2\n');
    expect(await nextBuild(page, before)).toBe('ok');
    await expect.poll(() => page.getByTestId('growth-lifetime').count()).toBe(1);
    expect(asked).toBe(2);
    expect(await box.inputValue()).toContain('#define k 2');
    // Said in the console: the failed fetch, for the panels and for the editor.
    expect(problems.filter((p) => !/vocabulary|grammar editor could not load|ERR_FAILED/.test(p))).toEqual([]);
    await context.close();
  });
});

describe('the view', () => {
  it('draws the plant again when the browser takes its WebGL context away and gives it back', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl'), context);
    // The Tubes mode: the plant's buffers are the view's own, which three.js does not make again.
    const before = await generation(page);
    await page.getByTestId('render-lines').click();
    expect(await nextBuild(page, before)).toBe('ok');
    const shown = await canvasPicture(page, 'context-before-loss.png');
    await loseAndRestoreContext(page.locator(VIEW_CANVAS));
    const restored = await canvasPicture(page, 'context-restored.png');
    expect(foregroundShare(shown)).toBeGreaterThan(0.01);
    expect(foregroundOverlap(shown, restored), 'the same plant, drawn again').toBeGreaterThan(0.9);
    // The next plant goes to the restored context as well.
    await page.getByTestId('editor').locator('.cm-content').waitFor();
    expect(await pasteText(page, (await editorText(page)).replace('#angle 20', '#angle 30'))).toBe('ok');
    const edited = await canvasPicture(page, 'context-restored-edited.png');
    expect(foregroundShare(edited)).toBeGreaterThan(0.01);
    expect(foregroundOverlap(shown, edited), 'the edited plant').toBeLessThan(0.9);
    expect(problems).toEqual([]);
    await context.close();
  });
});

describe('a grammar error on a phone', () => {
  it('is read in full through Problems: a touch screen has no hover for the underline’s tooltip, and the status line has room for a few words', async () => {
    const context = await browser.newContext(PHONE);
    const { page, problems } = await openAt(inject('studioUrl'), context);
    await page.evaluate(() => window.__meristem?.ready);
    const showProblems = page.getByTestId('show-problems');
    expect(await showProblems.isVisible(), 'no problems with the example').toBe(false);
    // Two errors, typed in the grammar's pane; then back to the plant's.
    await page.getByTestId('pane-toggle').tap();
    expect(await replaceTextByTouch(page, '#angle 25\naxiom: X\nX -> F[+X]F[-X+X\nF -> F(F\n')).toBe('stale');
    const status = page.getByTestId('status');
    expect(await status.evaluate((s) => s.scrollWidth > s.clientWidth), 'the status line cuts its message short').toBe(true);
    await page.getByTestId('pane-toggle').tap();
    expect(await page.getByTestId('editor').isVisible()).toBe(false);
    // Problems: the grammar's pane again, with every message in full under the text.
    await showProblems.tap();
    const list = page.locator('[data-testid=editor] [data-testid=problems]');
    await list.waitFor();
    const items = list.locator('.cm-problem');
    await expect.poll(() => items.count()).toBe(2);
    expect(await items.allTextContents()).toEqual(["3:12'[' is never closed by a ']'E0109", "4:7'(' is never closed by a ')'E0116"]);
    for (const item of await items.all()) {
      const box = (await item.boundingBox())!;
      // (CodeMirror sets the coloured left border a pixel out.)
      expect(box.x >= -1 && box.x + box.width <= 390 && box.y >= 0 && box.y + box.height <= 844, `on screen: ${JSON.stringify(box)}`).toBe(true);
    }
    // Choosing one goes to it in the text, and shows its message whole (a row too narrow for it cuts it short).
    await items.nth(1).tap();
    const cursorLine = () => page.evaluate(() => document.querySelector('[data-testid=editor] .cm-activeLine')?.textContent);
    await expect.poll(cursorLine).toBe('F -> F(F');
    expect(await list.locator('.cm-problems-chosen').textContent()).toBe("4:7 '(' is never closed by a ')' (E0116)");
    // Mended, the button goes.
    expect(await replaceTextByTouch(page, '#angle 25\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF\n')).toBe('ok');
    expect(await showProblems.isVisible()).toBe(false);
    expect(problems).toEqual([]);
    await context.close();
  });
});
