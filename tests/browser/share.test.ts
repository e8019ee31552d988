// End-to-end: sharing by link, autosave, My grammars, and opening and saving files (issue 7), on
// the built studio in headless Chromium. A share link must reproduce the plant exactly (the same
// derived string, by its fingerprint) and the view (options and camera); hostile links are refused
// with a message while the studio opens as usual; the user's text survives a reload and the
// opening of a link; other dialects are imported with their notes, from the picker and by drop.
import { readdirSync, readFileSync } from 'node:fs';
import { deflateRawSync } from 'node:zlib';
import { chromium, type Browser, type BrowserContext, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { decodeState, MAX_FRAGMENT, type SharedState } from '../../web/src/share';
import { editorText, example, generation, nextBuild, openExample, openStudio, openTubesMenu, pasteText, savePage, twoFrames } from './studio-page';

let browser: Browser;

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
});

/** A browser context of its own (its own storage, as another browser or profile). */
const newContext = () => browser.newContext({ viewport: { width: 1280, height: 800 }, acceptDownloads: true });

/** Opens `url` in `context` (default: a fresh one) and waits for the first plant. */
async function openAt(url: string, context?: BrowserContext): Promise<{ page: Page; problems: string[] }> {
  const page = await (context ?? (await newContext())).newPage();
  const problems: string[] = [];
  page.on('console', (m) => m.type() === 'error' && problems.push(`console error: ${m.text()}`));
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  await page.goto(url);
  await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0, undefined, { timeout: 30_000 });
  await page.waitForFunction(() => window.__meristem?.preview?.settled === true);
  return { page, problems };
}

const derivedHash = (page: Page) => page.evaluate(() => window.__meristem!.derivedHash!());
const cameraPose = (page: Page) => page.evaluate(() => window.__meristem!.cameraPose!());

/** Replaces the editor's text by typing it in as a paste. */
async function typeText(page: Page, text: string): Promise<void> {
  await pasteText(page, text);
}

/** A fragment holding `payload` compressed as the studio compresses. */
const fragmentOf = (payload: string | Uint8Array, version = 1) =>
  `#s=${version}.${Buffer.from(deflateRawSync(typeof payload === 'string' ? Buffer.from(payload) : payload)).toString('base64url')}`;

describe('share links', () => {
  it('reproduce the plant (same derived string), its options and the camera, from a fresh browser', async () => {
    const { page, problems } = await openStudio(browser);
    // Waits for the example's own build: the first plant's also has segments, and an example that
    // arrives after the options below are set empties them (opening a text forgets its options).
    expect(await openExample(page, 'abop-1.27-stochastic.lsys')).toBe('ok');
    await page.waitForFunction(() => window.__meristem?.preview?.settled === true && (window.__meristem.lastStats?.segments ?? 0) > 0);
    let before = await generation(page);
    await page.getByTestId('iterations').fill('4');
    await nextBuild(page, before);
    before = await generation(page);
    await page.getByTestId('seed').fill('77');
    await nextBuild(page, before);
    before = await generation(page);
    await openTubesMenu(page);
    await page.getByTestId('sides').selectOption('8');
    await nextBuild(page, before);
    await page.getByTestId('grid').click();
    // Orbit the camera by dragging on the view.
    const box = (await page.getByTestId('viewport').boundingBox())!;
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 120, box.y + box.height / 2 - 40, { steps: 8 });
    await page.mouse.up();
    await twoFrames(page);
    const hash = await derivedHash(page);
    const pose = await cameraPose(page);
    const text = await editorText(page);
    expect(hash).toMatch(/^[0-9a-f]{16}$/);

    await page.getByTestId('share').click();
    await page.getByTestId('share-dialog').waitFor({ state: 'visible' });
    await expect.poll(() => page.getByTestId('share-link').inputValue()).toMatch(/#s=1\./); // written once encoded
    const link = await page.getByTestId('share-link').inputValue();
    expect(link.startsWith(inject('studioUrl'))).toBe(true);
    expect(link).toMatch(/#s=1\.[A-Za-z0-9_-]+$/);
    await expect.poll(() => page.getByTestId('share-status').textContent()).toMatch(/copied|copy it/);
    await savePage(page, 'share-dialog.png');
    await page.keyboard.press('Escape');
    expect(problems).toEqual([]);

    // Another browser (its own storage) opens the link.
    const other = await newContext();
    const opened = await openAt(link, other);
    expect(await editorText(opened.page)).toBe(text);
    expect(await derivedHash(opened.page)).toBe(hash);
    const openedPose = await cameraPose(opened.page);
    for (const key of ['position', 'target'] as const) {
      openedPose[key].forEach((v, i) => expect(v).toBeCloseTo(pose[key][i], 6));
    }
    expect(await opened.page.getByTestId('iterations').inputValue()).toBe('4');
    expect(await opened.page.getByTestId('seed').inputValue()).toBe('77');
    expect(await opened.page.getByTestId('sides').inputValue()).toBe('8');
    expect(await opened.page.getByTestId('grid').getAttribute('aria-pressed')).toBe('false');
    // The fragment is gone from the address: a reload shows the user's later edits, not the link again.
    expect(new URL(opened.page.url()).hash).toBe('');
    expect(await opened.page.getByTestId('notice').isHidden(), 'nothing to report: no earlier work').toBe(true);
    await savePage(opened.page, 'share-opened.png');
    expect(opened.problems).toEqual([]);
    await other.close();
    await page.close();
  });

  const hostile: [string, string, string?][] = [
    ['too long', '#s=1.' + 'A'.repeat(MAX_FRAGMENT + 1)],
    ['not base64url', '#s=1.%3Cscript%3E'],
    ['not compressed', '#s=1.AAAAAAAAAAAA'],
    ['a decompression bomb', fragmentOf(new Uint8Array(8 * 1024 * 1024))],
    ['a newer format', fragmentOf(JSON.stringify({ v: 9, text: 'axiom: F' }), 9)],
    ['a malformed camera', fragmentOf(JSON.stringify({ v: 1, text: 'axiom: F', camera: { position: 'x' } }))],
    // Checked by the codec's chunk, then the edits check's, both loaded on a fresh page by the link.
    ['malformed branch edits', fragmentOf(JSON.stringify({ v: 1, text: 'axiom: F', edits: { version: 1, edits: [{ path: 'x' }] } })), 'branch edits are malformed'],
  ];

  it.each(hostile)('refuse %s politely, and the studio opens as usual', async (_name, fragment, reason) => {
    const { page, problems } = await openAt(inject('studioUrl') + fragment);
    const notice = page.getByTestId('notice');
    expect(await notice.isVisible()).toBe(true);
    expect(await notice.getAttribute('data-kind')).toBe('error');
    expect(await notice.getAttribute('role')).toBe('alert');
    expect(await page.getByTestId('notice-text').textContent()).toMatch(/^This link could not be opened: .+\. The studio opened as usual\.$/);
    if (reason) expect(await page.getByTestId('notice-text').textContent()).toContain(reason);
    expect(await editorText(page)).toBe(example('abop-1.24d.lsys'));
    expect(await page.evaluate(() => document.querySelectorAll('script:not([src]), img[onerror]').length)).toBe(0);
    expect(problems).toEqual([]);
    await page.getByTestId('notice-close').click();
    expect(await notice.isHidden()).toBe(true);
    await page.close();
  });
});

/** Whether anything a grammar's HTML-like comments hold ran or became an element anywhere on `page`. */
function htmlTrace(page: Page): Promise<{ ran: unknown; elements: number }> {
  return page.evaluate(() => ({
    ran: (window as unknown as { __pwned?: unknown }).__pwned,
    elements:
      document.querySelectorAll('img[onerror], svg[onload], iframe[srcdoc], b[onmouseover]').length +
      [...document.scripts].filter((script) => script.textContent?.includes('__pwned')).length,
  }));
}

describe('a grammar with HTML in its comments', () => {
  // Legal grammar: the studio shows text only as text, so a link never refuses it (issue 19).
  const text = [
    '// <img src=x onerror="window.__pwned = \'title\'"> bush <script>window.__pwned = \'script\'</script>',
    '// <img src=x onerror=alert(1)> <script>alert(1)</script>',
    '/* <svg onload="window.__pwned = \'svg\'"></svg>',
    '   <iframe srcdoc="<script>parent.__pwned = \'iframe\'</script>"></iframe> */',
    '#define growth = 2 // <b onmouseover="window.__pwned = \'define\'">slider</b>',
    '#angle 22.5',
    '#iterations 3',
    'axiom: X',
    'X -> F[+X]F[-X]+X',
    'F -> FF',
  ].join('\n');

  it('is shared by the studio, opens from the link with the same plant, and nothing in it runs', async () => {
    const { page, problems } = await openStudio(browser);
    page.on('dialog', (d) => problems.push(`dialog: ${d.message()}`));
    expect(await pasteText(page, text)).toBe('ok');
    const hash = await derivedHash(page);
    await page.getByTestId('share').click();
    await page.getByTestId('share-dialog').waitFor({ state: 'visible' });
    await expect.poll(() => page.getByTestId('share-link').inputValue()).toMatch(/#s=1\./); // written once encoded
    const link = await page.getByTestId('share-link').inputValue();
    expect(link).toMatch(/#s=1\.[A-Za-z0-9_-]+$/);
    expect(await page.getByTestId('share-download').isVisible(), 'a link, not the download instead').toBe(false);
    expect(await decodeState(new URL(link).hash)).toMatchObject({ ok: true, state: { text } });
    await page.keyboard.press('Escape');
    expect(await htmlTrace(page)).toEqual({ ran: undefined, elements: 0 });

    // Another browser holding work of its own whose title is HTML too: the link opens over it.
    const context = await newContext();
    const first = await openAt(inject('studioUrl'), context);
    const mine = '// <img src=x onerror="window.__pwned = \'mine\'"> mine\naxiom: F+F+F';
    await typeText(first.page, mine);
    await first.page.waitForTimeout(500); // autosave waits for a pause in typing
    await first.page.close();
    const opened = await openAt(link, context);
    opened.page.on('dialog', (d) => opened.problems.push(`dialog: ${d.message()}`));
    expect(await editorText(opened.page)).toBe(text);
    expect(await derivedHash(opened.page)).toBe(hash);
    expect(await opened.page.getByTestId('notice-text').textContent()).toBe(
      'Opened a shared link. Your previous text is kept in My grammars as “Before a shared link: <img src=x onerror="window.__pwned = \'mine\'"> mine”.',
    );
    // The editor shows the comments as the characters they are.
    expect(await opened.page.getByTestId('editor').locator('.cm-content').textContent()).toContain('<script>window.__pwned = \'script\'</script>');
    await opened.page.getByTestId('file-menu').locator('summary').click();
    await opened.page.getByTestId('open-library').click();
    expect(await opened.page.getByTestId('library-list').locator('.library-name').first().textContent()).toBe(
      'Before a shared link: <img src=x onerror="window.__pwned = \'mine\'"> mine',
    );
    await opened.page.waitForTimeout(300); // an image that failed to load would have fired onerror by now
    expect(await htmlTrace(opened.page)).toEqual({ ran: undefined, elements: 0 });
    expect(opened.problems).toEqual([]);
    expect(problems).toEqual([]);
    await context.close();
    await page.close();
  });
});

describe('view options in links', () => {
  const view: NonNullable<SharedState['view']> = { sides: 12, smoothAll: true, byProduction: true, grid: false, lighting: false, projection: 'orthographic', render: 'tubes', lineWidth: 3 };
  const fragment = fragmentOf(JSON.stringify({ v: 1, text: '// from a link\n#angle 20\naxiom: F\nF -> F[+F]F[-F]F', iterations: 2, seed: 5, view }));

  /** Checks that the controls show the link's options (and Textures, which links do not hold, as it was). */
  async function expectLinkOptions(page: Page): Promise<void> {
    expect(await page.getByTestId('sides').inputValue()).toBe('12');
    expect(await page.getByTestId('smooth-all').isChecked()).toBe(true);
    expect(await page.getByTestId('by-production').isChecked()).toBe(true);
    expect(await page.getByTestId('grid').getAttribute('aria-pressed')).toBe('false');
    expect(await page.getByTestId('lighting').getAttribute('aria-pressed')).toBe('false');
    expect(await page.getByTestId('textures').getAttribute('aria-pressed')).toBe('true');
    expect(await page.getByTestId('projection').getAttribute('aria-pressed')).toBe('true');
    expect(await page.getByTestId('viewport').getAttribute('data-projection')).toBe('orthographic');
    expect(await page.getByTestId('render-lines').getAttribute('aria-pressed'), 'tubes, though the plant is flat').toBe('false');
    expect(await page.getByTestId('viewport').getAttribute('data-render')).toBe('tubes');
    expect(await page.getByTestId('line-width').inputValue()).toBe('3');
    expect(await page.getByTestId('iterations').inputValue()).toBe('2');
    expect(await page.getByTestId('seed').inputValue()).toBe('5');
    expect(new URL(page.url()).hash).toBe('');
    // Shared again, the link holds the same options.
    await page.getByTestId('share').click();
    await page.getByTestId('share-dialog').waitFor({ state: 'visible' });
    const decoded = await decodeState(new URL(await page.getByTestId('share-link').inputValue()).hash);
    await page.keyboard.press('Escape');
    expect(decoded.ok && decoded.state.view).toEqual(view);
    expect(decoded.ok && [decoded.state.iterations, decoded.state.seed]).toEqual([2, 5]);
  }

  it('are shown and kept when the studio opens with a link', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl') + fragment, context);
    await expectLinkOptions(page);
    expect(problems).toEqual([]);
    await context.close();
  });

  it('are shown and kept when a link is pasted into the address bar of an open studio', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl'), context);
    const before = await generation(page);
    await page.evaluate((hash) => (location.hash = hash), fragment);
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await editorText(page)).toMatch(/^\/\/ from a link/);
    expect(await page.getByTestId('confirm-replace').isVisible(), 'an untouched example is replaced without asking').toBe(false);
    await expectLinkOptions(page);
    expect(problems).toEqual([]);
    await context.close();
  });
});

describe('saving work', () => {
  it('autosaves the text: it survives a reload', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl'), context);
    const mine = '// my own bush\n#angle 30\naxiom: F\nF -> F[+F]F[-F]F';
    await typeText(page, mine);
    await page.waitForTimeout(500); // autosave waits for a pause in typing
    await page.reload();
    await page.waitForFunction(() => window.__meristem?.preview?.settled === true && (window.__meristem.lastStats?.segments ?? 0) > 0);
    expect(await editorText(page)).toBe(mine);
    expect(problems).toEqual([]);
    await context.close();
  });

  it('keeps the earlier work in My grammars when a link is opened over it', async () => {
    const context = await newContext();
    const first = await openAt(inject('studioUrl'), context);
    const mine = '// work in progress\naxiom: F+F+F';
    await typeText(first.page, mine);
    await first.page.waitForTimeout(500);
    await first.page.close();
    const link = fragmentOf(JSON.stringify({ v: 1, text: '// from a friend\naxiom: F-F-F', iterations: 0 }));
    const { page, problems } = await openAt(inject('studioUrl') + link, context);
    expect(await editorText(page)).toBe('// from a friend\naxiom: F-F-F');
    expect(await page.getByTestId('notice-text').textContent()).toBe(
      'Opened a shared link. Your previous text is kept in My grammars as “Before a shared link: work in progress”.',
    );
    await page.getByTestId('file-menu').locator('summary').click();
    await page.getByTestId('open-library').click();
    const item = page.getByTestId('library-list').locator('li');
    // The list fills once the dialog has read the kept grammars (and, on a first open, loaded: issue 22).
    await expect.poll(() => item.count()).toBe(1);
    await item.getByTestId('library-open').click();
    expect(await page.getByTestId('confirm-replace').isVisible(), 'the link’s text is the user’s now: asked first').toBe(true);
    await page.getByTestId('confirm-replace-button').click();
    await expect.poll(() => editorText(page)).toBe(mine);
    expect(problems).toEqual([]);
    await context.close();
  });

  it('My grammars: save, rename, duplicate, delete and open', async () => {
    const context = await newContext();
    const { page, problems } = await openAt(inject('studioUrl'), context);
    const library = page.getByTestId('library');
    const items = library.getByTestId('library-list').locator('li');
    await page.getByTestId('file-menu').locator('summary').click();
    await page.getByTestId('open-library').click();
    await expect.poll(() => library.isVisible()).toBe(true); // loaded with its first open (issue 22), or at once
    // The name field suggests the grammar's own title, its first comment line.
    expect(await page.getByTestId('library-name').inputValue()).toBe(example('abop-1.24d.lsys').split('\n')[0].replace(/^\/\/\s*/, ''));
    await page.getByTestId('library-name').fill('Bush <b>bold</b>');
    await page.getByTestId('library-save').click();
    expect(await items.count()).toBe(1);
    expect(await items.first().locator('.library-name').textContent()).toBe('Bush <b>bold</b>');
    expect(await items.first().locator('b').count(), 'names are text, never HTML').toBe(0);
    await items.first().getByTestId('library-duplicate').click();
    expect(await items.count()).toBe(2);
    expect(await items.allTextContents()).toEqual([expect.stringContaining('Bush <b>bold</b> (copy)'), expect.stringContaining('Bush <b>bold</b>')]);
    await items.first().getByTestId('library-rename').click();
    await library.getByTestId('library-rename-input').fill('Second bush');
    await page.keyboard.press('Enter');
    expect(await items.first().locator('.library-name').textContent()).toBe('Second bush');
    await items.nth(1).getByTestId('library-delete').click();
    expect(await items.count(), 'the first click only asks').toBe(2);
    await items.nth(1).getByTestId('library-delete').click();
    expect(await items.count()).toBe(1);
    // Saved grammars outlive the page.
    await page.keyboard.press('Escape');
    await typeText(page, 'axiom: FF');
    await page.reload();
    await page.waitForFunction(() => window.__meristem?.preview?.settled === true);
    await page.getByTestId('file-menu').locator('summary').click();
    await page.getByTestId('open-library').click();
    await expect.poll(() => items.count()).toBe(1); // after the reload, the dialog loads with this first open
    await savePage(page, 'my-grammars.png');
    await items.first().getByTestId('library-open').click();
    await page.getByTestId('confirm-replace-button').click();
    await expect.poll(() => editorText(page)).toBe(example('abop-1.24d.lsys'));
    expect(problems).toEqual([]);
    await context.close();
  });
});

describe('grammar files', () => {
  const lparser = new URL('../../crate/tests/import/lparser/abop-monopodial-tree.ls', import.meta.url);
  const cpfg = new URL('../../crate/tests/import/cpfg/monopodial.l', import.meta.url);

  it('imports an Lparser file from the picker, with its notes, and draws it', async () => {
    const { page, problems } = await openAt(inject('studioUrl'));
    const before = await generation(page);
    await page.getByTestId('file-input').setInputFiles(lparser.pathname);
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await editorText(page)).toMatch(/^\/\/ Imported from Lparser \(positional format\)/);
    expect(await page.getByTestId('notice').getAttribute('data-kind')).toBe('info');
    expect(await page.getByTestId('notice-text').textContent()).toMatch(/^Imported abop-monopodial-tree\.ls from Lparser\. Not translated, or only approximately \(\d+\):$/);
    expect(await page.getByTestId('notice-list').locator('li').allTextContents()).toContainEqual(expect.stringMatching(/^line 23: '~' without a value/));
    await savePage(page, 'imported-lparser.png');
    expect(problems).toEqual([]);
    await page.close();
  });

  it('imports a cpfg file dropped on the page (not inserted into the editor as text)', async () => {
    const { page, problems } = await openAt(inject('studioUrl'));
    const bytes = [...readFileSync(cpfg)];
    const before = await generation(page);
    const drop = await page.evaluateHandle((data) => {
      const transfer = new DataTransfer();
      transfer.items.add(new File([new Uint8Array(data)], 'monopodial.l', { type: 'text/plain' }));
      return transfer;
    }, bytes);
    await page.dispatchEvent('[data-testid=editor] .cm-content', 'dragenter', { dataTransfer: drop });
    expect(await page.locator('#studio').getAttribute('class')).toContain('drop-target');
    await page.dispatchEvent('[data-testid=editor] .cm-content', 'drop', { dataTransfer: drop });
    expect(await nextBuild(page, before)).toBe('ok');
    const text = await editorText(page);
    expect(text).toMatch(/^\/\/ Imported from cpfg/);
    expect(text).not.toContain('Lsystem:');
    expect(await page.getByTestId('notice-text').textContent()).toMatch(/^Imported monopodial\.l from cpfg/);
    expect(await page.locator('#studio').getAttribute('class')).not.toContain('drop-target');
    expect(problems).toEqual([]);
    await page.close();
  });

  it("imports a vlab object's files picked together: the view file's angle, the functions, the notes", async () => {
    const { page, problems } = await openAt(inject('studioUrl'));
    const dir = new URL('../../crate/tests/import-corpus/vlab/05-monopodial/', import.meta.url);
    const before = await generation(page);
    // Imported off the page's thread, in an import worker, as a single file is.
    const workers: string[] = [];
    page.on('worker', (worker) => workers.push(worker.url()));
    await page.getByTestId('file-input').setInputFiles(readdirSync(dir).map((f) => new URL(f, dir).pathname));
    expect(await nextBuild(page, before)).toBe('ok');
    expect(workers.filter((url) => /import-worker/.test(url)), `workers started: ${workers.join(', ')}`).toHaveLength(1);
    const text = await editorText(page);
    expect(text).toMatch(/^#angle 9$/m);
    expect(text).toMatch(/^#table internode /m);
    expect(await page.getByTestId('notice-text').textContent()).toBe('Imported leaf from cpfg. Not translated, or only approximately (1):');
    await savePage(page, 'imported-vlab-object.png');
    expect(problems).toEqual([]);
    await page.close();
  });

  it('saves the grammar as a .lsys file (Ctrl+S), and opens it back as it is', async () => {
    const { page, problems } = await openAt(inject('studioUrl'));
    const mine = '// Tiny fern\n#angle 25\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF';
    await typeText(page, mine);
    const [download] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('Control+S')]);
    expect(download.suggestedFilename()).toBe('tiny-fern.lsys');
    const saved = readFileSync(await download.path(), 'utf8');
    expect(saved).toBe(mine);
    await typeText(page, 'axiom: F');
    const before = await generation(page);
    await page.getByTestId('file-input').setInputFiles({ name: 'tiny-fern.lsys', mimeType: 'text/plain', buffer: Buffer.from(saved) });
    await page.getByTestId('confirm-replace-button').click();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await editorText(page)).toBe(mine);
    // The text it replaced was the user's: kept first, and said so.
    expect(await page.getByTestId('notice-text').textContent()).toBe('Opened tiny-fern.lsys. Your previous text is kept in My grammars as “Before “tiny-fern.lsys”: Untitled grammar”.');
    // A file that is not text is refused with a message; the text stays.
    await page.getByTestId('file-input').setInputFiles({ name: 'photo.lsys', mimeType: 'image/png', buffer: Buffer.from([0x89, 0x50, 0x4e, 0x47, 0, 0, 0]) });
    await expect.poll(() => page.getByTestId('notice-text').textContent()).toBe('Could not open photo.lsys: photo.lsys is not a text file.');
    expect(await editorText(page)).toBe(mine);
    expect(problems).toEqual([]);
    await page.close();
  });
});
