// End-to-end: a lecturer's own assignment (docs/ASSIGNMENTS.md), as a class uses it. The file is
// served by ANOTHER origin (a second static server, as the lecturer's site, sending CORS headers);
// the studio opens it from `?assignment=URL` and checks the file (no problems); a wrong answer
// fails its check and a right one passes; Submit… gives a link which, opened in another browser
// profile (the lecturer's, with their own text), reopens the same grammar with the same verdicts,
// computed there, marked as a submission, the lecturer's text kept. A server without CORS headers
// gets a message that names the header. Screenshots land in test-results/.
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { packText } from '../../web/src/share/codec';
import { serveStatic, type StaticSite } from './static-server';
import { editorText, generation, nextBuild, pasteText, savePage } from './studio-page';
import { browser, page, problems, useStudio } from './session';

useStudio();

const FILE = 'assignments/example-koch.md';
const START = readFileSync(new URL(`../../public/${FILE}`, import.meta.url), 'utf8').match(/```lsys\n([\s\S]*?)```/)![1];
let course: StaticSite;
let closed: StaticSite;

beforeAll(async () => {
  course = await serveStatic('/course/', { headers: { 'Access-Control-Allow-Origin': '*' } });
  closed = await serveStatic('/closed/');
});
afterAll(async () => {
  await course?.close();
  await closed?.close();
});

/** Opens the studio at `address` in `on` and waits for its first plant. */
async function openAt(on: Page, address: string): Promise<void> {
  await on.goto(address);
  await on.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
  await on.evaluate(() => window.__meristem?.ready);
}

/** Presses task `n`'s Check and returns its answer. */
async function check(n: number): Promise<{ state: string | null; text: string | null }> {
  const result = page.getByTestId('assignment-result').nth(n);
  await page.getByTestId('assignment-check').nth(n).click();
  await expect.poll(() => result.getAttribute('data-state'), { timeout: 30_000 }).not.toBe('busy');
  return { state: await result.getAttribute('data-state'), text: await result.textContent() };
}

describe('a lecturer’s assignment', () => {
  let link = '';
  const wrong = START.replace('#iterations 2', '#iterations 4');
  const right = START.replace('#iterations 2', '#iterations 3');

  it('opens from another origin, checks clean, fails a wrong answer and passes a right one', async () => {
    const url = `${course.base}${FILE}`;
    expect(new URL(url).origin).not.toBe(new URL(inject('studioUrl')).origin);
    await openAt(page, `${inject('studioUrl')}?assignment=${encodeURIComponent(url)}`);
    problems.splice(0); // the session's first page, left while it still loaded the studio core (net::ERR_ABORTED)
    const panel = page.getByTestId('assignment');
    await panel.getByRole('heading', { name: 'Koch islands, one step further', level: 2 }).waitFor({ timeout: 30_000 });
    expect(await panel.getByTestId('assignment-fingerprint').textContent()).toContain(`From ${url}`);
    // The file's checks run in the panel's own build worker: the example has no problem.
    await expect.poll(() => page.getByTestId('assignment-problems').getAttribute('data-state'), { timeout: 60_000 }).toBe('ok');
    // The starting grammar's picture, drawn by the gallery's thumbnail renderer.
    await page.waitForFunction(() => document.querySelector<HTMLImageElement>('[data-testid=assignment] .lesson-figure img')?.dataset.state === 'ready', null, { timeout: 60_000 });
    // The hidden solution is nowhere on the page.
    expect(await panel.textContent()).not.toContain('Koch island, n = 3');

    let before = await generation(page);
    await panel.getByRole('button', { name: /^Open in the editor: Quadratic Koch island/ }).click();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await editorText(page)).toBe(START);
    expect((await check(0)).state).toBe('fail');
    // The toolbar's Iterations box is not the student's work: the check says it read the text.
    before = await generation(page);
    await page.getByTestId('iterations').fill('3');
    await page.getByTestId('iterations').blur();
    expect(await nextBuild(page, before)).toBe('ok');
    const overridden = await check(0);
    expect(overridden.state).toBe('fail');
    expect(overridden.text).toContain('The check reads the grammar as written, at its #iterations 2; the plant on screen is at 3, set by the Iterations box.');
    await page.getByTestId('iterations').fill('');
    await page.getByTestId('iterations').blur();
    await page.waitForFunction(() => !document.querySelector('[data-testid=iterations-box]')?.hasAttribute('data-override'));

    expect(await pasteText(page, wrong)).toBe('ok');
    expect(await check(0)).toEqual({
      state: 'fail',
      text: 'Not yet: segments is 16384, the task wants 2048. Hint: #iterations says how many times every F is replaced; each step multiplies the edges by 8.',
    });
    before = await generation(page);
    expect(await pasteText(page, right)).toBe('ok');
    expect(await check(0)).toEqual({ state: 'pass', text: 'Passed: segments is 2048.' });
    expect((await check(1)).state).toBe('fail');
    await savePage(page, 'assignment-passed.png');
    // Closed, the Learn panel's list brings it back as it was (they share one column).
    await panel.getByRole('button', { name: 'Close the assignment' }).click();
    expect(await panel.isVisible()).toBe(false);
    await page.getByTestId('open-learn').click();
    await page.getByTestId('learn-back-to-assignment').click();
    expect(await page.getByTestId('learn').isVisible()).toBe(false);
    expect(await panel.isVisible()).toBe(true);
    expect(await page.getByTestId('assignment-result').first().textContent()).toBe('Passed: segments is 2048.');

    await page.getByTestId('submit-open').click();
    await page.getByTestId('submit-name').fill('Ada Student');
    await page.getByTestId('submit-make').click();
    await expect.poll(() => page.getByTestId('submit-link').inputValue()).toMatch(/#submission=1\./);
    link = await page.getByTestId('submit-link').inputValue();
    expect(link.startsWith(inject('studioUrl'))).toBe(true);
    expect(problems).toEqual([]);
  });

  it('reopens from the submission link with the same grammar and verdicts, computed anew, the lecturer’s text kept', async () => {
    const lecturer = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    const other = await lecturer.newPage();
    try {
      await openAt(other, inject('studioUrl'));
      const mine = '// My own lecture notes\naxiom: F+F\n';
      await other.evaluate(() => window.__meristem?.ready);
      await other.locator('[data-testid=editor] .cm-content').click();
      await other.keyboard.press('Control+A');
      await other.keyboard.insertText(mine);
      await other.waitForTimeout(1500); // autosaved
      await other.goto('about:blank');
      await other.goto(link);
      await other.getByTestId('confirm-replace').waitFor({ state: 'visible', timeout: 30_000 });
      await other.getByTestId('confirm-replace-button').click();
      const banner = other.getByTestId('submission-banner');
      await banner.waitFor({ timeout: 30_000 });
      expect(await banner.textContent()).toContain('Submission: Ada Student’s work');
      await expect.poll(() => other.getByTestId('submission-score').textContent(), { timeout: 60_000 }).toBe('1 of 3 tasks pass.');
      const verdicts = await other.getByTestId('submission-verdict').allTextContents();
      expect(verdicts).toEqual([
        'Submitted grammar: Passed: segments is 2048.',
        'Submitted grammar: Not yet: segments is 2048, the task wants 500.',
        'Submitted grammar: Not yet: branch_order is 0, the task wants at least 3.',
      ]);
      await expect.poll(() => other.evaluate(() => document.querySelector('[data-testid=editor] .cm-content')?.textContent ?? '')).toContain('#iterations 3');
      expect(await other.evaluate(() => location.hash)).toBe(''); // a reload shows the lecturer's page, not the submission again
      expect(await other.getByTestId('notice').textContent()).toMatch(/kept in My grammars/);
      const saved = await other.evaluate(() => JSON.stringify(Object.entries(localStorage)));
      expect(saved).toContain('My own lecture notes');
      await savePage(other, 'assignment-submission.png');
    } finally {
      await lecturer.close();
    }
  });

});

describe('a submission of an assignment changed since', () => {
  it('says so, and checks against the file as it is now', async () => {
    const link = await page.getByTestId('submit-link').inputValue();
    expect(link).toMatch(/#submission=1\./);
    const original = readFileSync(new URL(`../../public/${FILE}`, import.meta.url), 'utf8');
    course.replaced.set(FILE, original.replace('check: segments == 2048', 'check: segments == 16384'));
    try {
      await page.goto('about:blank');
      await openAt(page, link);
      const banner = page.getByTestId('submission-banner');
      await banner.waitFor({ timeout: 30_000 });
      expect(await banner.textContent()).toContain('The assignment has changed since the student worked on it');
      await expect.poll(() => page.getByTestId('submission-verdict').first().textContent(), { timeout: 60_000 }).toBe('Submitted grammar: Not yet: segments is 2048, the task wants 16384.');
      // The lecturer's changed file is checked too: its solution no longer passes its check.
      await expect.poll(() => page.getByTestId('assignment-problems').getAttribute('data-state'), { timeout: 60_000 }).toBe('problems');
      expect(await page.getByTestId('assignment-problems').textContent()).toContain('solution: the solution does not pass its own check: Not yet: segments is 2048, the task wants 16384.');
    } finally {
      course.replaced.delete(FILE);
    }
  });
});

describe('an assignment on a phone', () => {
  it('covers the screen without scrolling sideways, steps aside for the editor, and comes back from the Learn panel', async () => {
    const phone = await browser.newPage({ viewport: { width: 390, height: 844 } });
    try {
      await openAt(phone, `${inject('studioUrl')}?assignment=${encodeURIComponent(`${course.base}${FILE}`)}`);
      const panel = phone.getByTestId('assignment');
      await panel.getByRole('heading', { name: 'Koch islands, one step further', level: 2 }).waitFor({ timeout: 30_000 });
      expect(await panel.boundingBox()).toEqual({ x: 0, y: 0, width: 390, height: 844 });
      expect(await phone.getByTestId('assignment-body').evaluate((e) => e.scrollWidth - e.clientWidth)).toBeLessThanOrEqual(0);
      await savePage(phone, 'assignment-phone.png');
      await panel.getByRole('button', { name: /^Open in the editor: / }).click();
      await panel.waitFor({ state: 'hidden' });
      await phone.getByTestId('open-learn').click();
      await phone.getByTestId('learn-back-to-assignment').click();
      await panel.waitFor({ state: 'visible' });
      expect(await phone.getByTestId('learn').isVisible()).toBe(false);
    } finally {
      await phone.close();
    }
  });
});

describe('an assignment that cannot be opened as it is, or that is hostile', () => {
  it('says what the lecturer’s server needs when it sends no CORS header, and offers the file instead', async () => {
    const url = `${closed.base}${FILE}`;
    await openAt(page, `${inject('studioUrl')}?assignment=${encodeURIComponent(url)}`);
    const error = page.getByTestId('assignment-error');
    await error.waitFor({ timeout: 30_000 });
    expect(await error.textContent()).toContain('it must send the header “Access-Control-Allow-Origin: *”');
    expect(await page.getByTestId('assignment').getByRole('button', { name: 'Open an assignment file…' }).isVisible()).toBe(true);
    // The file, opened instead, shows the assignment.
    await page.getByTestId('assignment-file').setInputFiles(new URL(`../../public/${FILE}`, import.meta.url).pathname);
    await page.getByTestId('assignment').getByRole('heading', { name: 'Koch islands, one step further', level: 2 }).waitFor();
    expect(await page.getByTestId('assignment-fingerprint').textContent()).toContain('From the file example-koch.md');
    await savePage(page, 'assignment-no-cors.png');
  });

  it('opens a packed assignment whose Markdown holds HTML and scripts as text, running none of them', async () => {
    const hostile = [
      '---',
      'title: <img src=x onerror="window.hacked=1">Hostile',
      '---',
      '<script>window.hacked = 2</script> <img src="x" onerror="window.hacked=3">',
      '',
      'Text with [click](javascript:window.hacked=4), ![p](javascript:x) and [a page](https://example.org/).',
      '',
      '```lsys',
      '// Start',
      'axiom: F',
      '```',
      '',
      '```task',
      'Do <b onclick="window.hacked=5">this</b>.',
      'check: segments > 1',
      'solution:',
      'axiom: FF',
      '```',
      '',
    ].join('\n');
    await openAt(page, `${inject('studioUrl')}#assignment=1.${await packText(hostile)}`);
    problems.splice(0);
    const panel = page.getByTestId('assignment');
    await panel.getByRole('heading', { name: '<img src=x onerror="window.hacked=1">Hostile', level: 2 }).waitFor({ timeout: 30_000 });
    const body = panel.getByTestId('assignment-body');
    expect(await body.textContent()).toContain('<script>window.hacked = 2</script>');
    expect(await body.textContent()).toContain('Do <b onclick="window.hacked=5">this</b>.');
    expect(await body.locator('script, [onerror], [onclick], b').count()).toBe(0);
    const click = body.getByText('click', { exact: true });
    expect(await click.getAttribute('href')).toBeNull();
    expect(await body.getByText('a page').getAttribute('href')).toBe('https://example.org/');
    expect(await body.getByText('a page').getAttribute('rel')).toBe('noopener noreferrer');
    expect(await body.getByAltText('p', { exact: true }).getAttribute('src')).toBeNull();
    await click.click();
    expect(await page.evaluate(() => (window as { hacked?: number }).hacked)).toBeUndefined();
    expect(await page.getByTestId('assignment-fingerprint').textContent()).toContain('Packed in the link');
    expect(problems).toEqual([]);
  });
});

