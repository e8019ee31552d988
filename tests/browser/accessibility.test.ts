// Accessibility audit (issue 22): axe-core run in Chromium on the built studio, in the light and the
// dark theme, on the page itself, the gallery, every dialog (share, my grammars, help, confirm), the
// download and file menus, the Learn panel, the list of a grammar's problems and the embed page
// (embed.html#s=…). No serious or
// critical violation anywhere, every control named (those rules fail at any impact), and the
// context highlighting of the string and derivation panels (written, left context, right context,
// picked) readable: axe's WCAG AA colour-contrast check must pass on those very elements.
import { AxeBuilder } from '@axe-core/playwright';
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it, vi } from 'vitest';
import { encodeState } from '../../web/src/share';
import { example, pasteText, savePage, studioIn, type StudioPage } from './studio-page';

/** The rules that say "every control has an accessible name": any violation of them fails. */
const NAMING_RULES = ['aria-command-name', 'aria-input-field-name', 'aria-toggle-field-name', 'button-name', 'input-button-name', 'label', 'link-name', 'select-name', 'summary-name', 'aria-dialog-name', 'frame-title'];
/** A context-sensitive production with both contexts: `a < b > c -> b` fires on the b of `abc`. */
const CONTEXTS = '// Both contexts\n#angle 30\n#iterations 1\naxiom: abcabc\na < b > c -> b\nhomomorphism:\na -> F\nb -> F+F\nc -> F-F';

// Each audit takes seconds on a loaded 2-core machine, and a test runs up to seven of them.
vi.setConfig({ testTimeout: 150_000 });

let browser: Browser;

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
});

interface Audit {
  /** The violations that fail the audit, one line each. */
  failures: string[];
  /** Selectors of the elements that passed the colour-contrast check. */
  contrastPasses: string[];
}

/**
 * A studio page in a context of its own (axe opens a page of its own in the same context to
 * gather the results of frames, which a page from `browser.newPage()` does not allow).
 */
async function openStudio(scheme: 'light' | 'dark'): Promise<StudioPage> {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, colorScheme: scheme });
  return studioIn(await context.newPage());
}

/** Runs axe (WCAG 2.x A and AA and best practice) on the page, or only inside `include`. */
async function audit(page: Page, include?: string): Promise<Audit> {
  let builder = new AxeBuilder({ page }).withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa', 'best-practice']);
  if (include) builder = builder.include(include);
  const results = await builder.analyze();
  const failures = results.violations
    .filter((v) => v.impact === 'serious' || v.impact === 'critical' || NAMING_RULES.includes(v.id))
    .flatMap((v) => v.nodes.map((n) => `${v.id} (${v.impact}): ${n.target.join(' ')} — ${n.failureSummary?.replace(/\s+/g, ' ')}`));
  const contrastPasses = results.passes.filter((p) => p.id === 'color-contrast').flatMap((p) => p.nodes.map((n) => n.target.join(' ')));
  return { failures, contrastPasses };
}

describe.each(['light', 'dark'] as const)('the %s theme', (scheme) => {
  it('the studio, its menus and its panels have no serious violations and name every control', async () => {
    const { page, problems } = await openStudio(scheme);
    expect((await audit(page)).failures, 'the studio').toEqual([]);

    await page.getByTestId('downloads').locator('summary').click();
    await page.locator('#model-downloads button').first().waitFor();
    expect((await audit(page, '[data-testid=downloads]')).failures, 'the download menu').toEqual([]);
    await page.getByTestId('download-movie').click(); // (closes the menu)
    await page.getByTestId('movie-dialog').waitFor({ state: 'visible' });
    await page.locator('[data-testid=movie-format] option[value=gif]').waitFor({ state: 'attached' });
    expect((await audit(page, '[data-testid=movie-dialog]')).failures, 'the movie dialog').toEqual([]);
    await page.getByTestId('movie-close').click();
    await page.getByTestId('file-menu').locator('summary').click();
    expect((await audit(page, '[data-testid=file-menu]')).failures, 'the file menu').toEqual([]);
    await page.getByTestId('file-menu').locator('summary').click();
    await page.getByTestId('help').click();
    await page.getByTestId('shortcuts').waitFor({ state: 'visible' });
    expect((await audit(page, '[data-testid=shortcuts]')).failures, 'the shortcuts').toEqual([]);
    await page.keyboard.press('Escape');

    await page.getByTestId('open-learn').click();
    await page.getByTestId('learn-contents').waitFor({ state: 'visible' });
    expect((await audit(page, '[data-testid=learn]')).failures, 'the Learn panel, contents').toEqual([]);
    await page.getByTestId('learn-contents').locator('button, a').first().click();
    await page.getByTestId('learn-lesson').waitFor({ state: 'visible' });
    expect((await audit(page, '[data-testid=learn]')).failures, 'the Learn panel, a lesson').toEqual([]);
    await savePage(page, `a11y-${scheme}-learn.png`);
    await page.getByTestId('learn-close').click();
    expect(problems).toEqual([]);
    await page.context().close();
  });

  it('a grammar with errors: the status bar and the list of problems have no serious violations', async () => {
    const { page, problems } = await openStudio(scheme);
    expect(await pasteText(page, '#angle 25\naxiom: X\nX -> F[+X]F[-X+X\nF -> F(F\n')).toBe('stale');
    expect((await audit(page, '.statusbar')).failures, 'the status bar, with Problems').toEqual([]);
    await page.getByTestId('show-problems').click();
    const list = page.getByTestId('editor').locator('.cm-panels');
    await list.locator('.cm-problem').nth(1).waitFor();
    await list.locator('.cm-problem').nth(1).click(); // a chosen row too
    const { failures, contrastPasses } = await audit(page, '[data-testid=editor] .cm-panels');
    expect(failures, 'the list of problems').toEqual([]);
    expect(contrastPasses.length, 'its messages were checked for contrast').toBeGreaterThan(0);
    await savePage(page, `a11y-${scheme}-problems.png`);
    expect(problems).toEqual([]);
    await page.context().close();
  });

  it('the gallery and the dialogs have no serious violations and name every control', async () => {
    const { page, problems } = await openStudio(scheme);
    await page.getByTestId('open-gallery').click();
    await page.locator('[data-testid=gallery-list] button[data-file]').first().waitFor();
    expect((await audit(page, '[data-testid=gallery]')).failures, 'the gallery').toEqual([]);
    await savePage(page, `a11y-${scheme}-gallery.png`);
    await page.keyboard.press('Escape');

    await page.getByTestId('share').click();
    await page.getByTestId('share-dialog').waitFor({ state: 'visible' });
    expect((await audit(page, '[data-testid=share-dialog]')).failures, 'the share dialog').toEqual([]);
    await page.keyboard.press('Escape');

    await page.getByTestId('file-menu').locator('summary').click();
    await page.getByTestId('open-library').click();
    await page.getByTestId('library').waitFor({ state: 'visible' });
    await page.getByTestId('library-save').click();
    await page.getByTestId('library-list').locator('li').first().waitFor();
    expect((await audit(page, '[data-testid=library]')).failures, 'my grammars').toEqual([]);
    await page.keyboard.press('Escape');

    await page.getByTestId('open-help').click();
    await page.getByTestId('help-panel').waitFor({ state: 'visible' });
    expect((await audit(page, '[data-testid=help-panel]')).failures, 'the help').toEqual([]);
    await page.keyboard.press('Escape');

    // The confirm dialog: the text is the user's, and another example is opened.
    await pasteText(page, `${example('abop-1.24d.lsys')}\n// mine`);
    await page.getByTestId('open-gallery').click();
    await page.locator('[data-testid=gallery-list] button[data-file]').nth(2).click();
    await page.getByTestId('confirm-replace').waitFor({ state: 'visible' });
    expect((await audit(page, '[data-testid=confirm-replace]')).failures, 'the confirm dialog').toEqual([]);
    await page.getByTestId('confirm-cancel').click();
    expect(problems).toEqual([]);
    await page.context().close();
  });

  it('the context highlighting in the string and derivation panels meets WCAG AA contrast', async () => {
    const { page, problems } = await openStudio(scheme);
    await pasteText(page, CONTEXTS);
    await page.getByTestId('editor').locator('.cm-line', { hasText: /^a < b/ }).click();
    const panel = page.getByTestId('string-panel');
    await expect.poll(() => panel.locator('.m-produced').count()).toBeGreaterThan(0);
    expect(await panel.locator('.m-left').count()).toBeGreaterThan(0);
    expect(await panel.locator('.m-right').count()).toBeGreaterThan(0);
    await panel.locator('.m-produced').first().click(); // picks it: the selected colour too
    await expect.poll(() => panel.locator('.m-selected').count()).toBe(1);
    await page.getByTestId('editor').locator('.cm-line', { hasText: /^a < b/ }).click();
    await expect.poll(() => panel.locator('.m-left').count()).toBeGreaterThan(0);
    expect((await audit(page, '[data-testid=string-panel]')).failures, 'the string panel').toEqual([]);
    for (const kind of ['m-produced', 'm-left', 'm-right', 'm-selected']) {
      const { failures, contrastPasses } = await audit(page, `[data-testid=string-panel] .${kind}`);
      expect(failures, kind).toEqual([]);
      expect(contrastPasses.length, `${kind} passes the contrast check`).toBeGreaterThan(0);
    }
    await savePage(page, `a11y-${scheme}-contexts.png`);

    await page.getByTestId('tab-derivation').click();
    const derivation = page.locator('#derivation-panel');
    await derivation.locator('.dv-m[data-step="1"]').first().hover(); // lights up its parent
    await derivation.locator('.dv-parent').first().waitFor();
    expect((await audit(page, '#derivation-panel')).failures, 'the derivation panel').toEqual([]);
    const rewritten = await audit(page, '#derivation-panel :is(.dv-hover, .dv-parent, .dv-child)');
    expect(rewritten.failures).toEqual([]);
    expect(rewritten.contrastPasses.length, 'the rewritten modules pass the contrast check').toBeGreaterThan(0);
    await savePage(page, `a11y-${scheme}-derivation.png`);
    expect(problems).toEqual([]);
    await page.context().close();
  });

  it('the embed page has no serious violations and names every control', async () => {
    const context = await browser.newContext({ viewport: { width: 860, height: 520 }, colorScheme: scheme });
    const page = await context.newPage();
    const fragment = await encodeState({ text: example('abop-1.24d.lsys'), iterations: 4 });
    await page.goto(new URL(`embed.html?controls=iterations,sliders${fragment}`, inject('studioUrl')).href);
    await expect.poll(() => page.locator('.mp').getAttribute('data-state'), { timeout: 30_000 }).toBe('ok');
    expect((await audit(page)).failures).toEqual([]);
    await page.context().close();
  });
});
