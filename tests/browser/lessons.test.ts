// End-to-end: the Learn panel as a student uses it. A lesson opens from the list; its grammar opens
// in the editor with one click; the task's check fails on that starting grammar and says why in
// words; the solution, opened from behind "Show solution", passes. Also the keyboard, the user's own
// text (asked before it is replaced), and the panel on a phone. Screenshots land in test-results/.
import { readFileSync } from 'node:fs';
import type { Locator } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { editorText, generation, nextBuild, openStudio, savePage } from './studio-page';
import { browser, page, problems, useStudio } from './session';

useStudio();

const LESSON = '04-bracketed';
const lesson = JSON.parse(readFileSync(new URL(`../../dist/lessons/${LESSON}.json`, import.meta.url), 'utf8')) as {
  title: string;
  grammars: { title: string; text: string }[];
  tasks: { solution: string; start: number }[];
};

/** Clicks `button` and waits for the build of the text it opened. */
async function openAndBuild(button: Locator): Promise<string | null> {
  const before = await generation(page);
  await button.click();
  return nextBuild(page, before);
}

/** Clicks Check and returns the answer once it is given. */
async function check(): Promise<{ state: string | undefined; text: string }> {
  await page.getByTestId('task-check').click();
  const result = page.getByTestId('task-result');
  await page.waitForFunction(() => ['pass', 'fail'].includes(document.querySelector<HTMLElement>('[data-testid=task-result]')?.dataset.state ?? ''));
  return { state: (await result.getAttribute('data-state')) ?? undefined, text: (await result.textContent()) ?? '' };
}

describe('the Learn panel', () => {
  it('opens a lesson; its task fails on the starting grammar and passes on the solution', async () => {
    await page.getByTestId('open-learn').click();
    await expect(page.getByTestId('open-learn').getAttribute('aria-expanded')).resolves.toBe('true');
    const contents = page.getByTestId('learn-contents');
    await contents.getByRole('heading', { name: 'ABOP chapter 1: graphical modeling using L-systems' }).waitFor();
    expect(await contents.locator('.learn-entry').count()).toBeGreaterThanOrEqual(8);
    await contents.getByRole('button', { name: lesson.title }).click();
    const panel = page.getByTestId('learn-lesson');
    await panel.getByRole('heading', { name: lesson.title, level: 2 }).waitFor();

    // Every grammar's picture is drawn by the gallery's thumbnail renderer.
    await page.waitForFunction(
      (n) => [...document.querySelectorAll<HTMLImageElement>('.lesson-figure img')].filter((i) => i.dataset.state === 'ready').length >= n,
      lesson.grammars.length,
      { timeout: 60_000 },
    );

    // The starting grammar: the studio's text was the unchanged example, so it is replaced without asking.
    const start = lesson.grammars[lesson.tasks[0].start];
    expect(await openAndBuild(panel.getByRole('button', { name: `Open in the editor: ${start.title}` }))).toBe('ok');
    expect(await editorText(page)).toBe(start.text);
    const failed = await check();
    expect(failed.state).toBe('fail');
    expect(failed.text).toBe('Not yet: whorl is 2, the task wants 3. Hint: whorl counts branches written side by side at one node: F[+X][X][-X] has 3.');
    await savePage(page, 'lesson-task-failed.png');

    // The solution is hidden until asked for.
    const openSolution = panel.getByRole('button', { name: /^Open solution/ });
    expect(await openSolution.isVisible()).toBe(false);
    await panel.getByText('Show solution').click();
    expect(await openAndBuild(openSolution)).toBe('ok');
    expect(await editorText(page)).toBe(lesson.tasks[0].solution);
    const passed = await check();
    expect(passed).toEqual({ state: 'pass', text: 'Passed: whorl is 3.' });
    await page.getByTestId('task-result').scrollIntoViewIfNeeded();
    await savePage(page, 'lesson-task-passed.png');
    expect(problems).toEqual([]);
  });

  it('asks before a lesson replaces the user’s own text, and says so when the grammar has errors', async () => {
    await page.locator('[data-testid=editor] .cm-content').click();
    await page.keyboard.press('Control+End');
    const before = await generation(page);
    await page.keyboard.type('\nX -> F -> F');
    expect(await nextBuild(page, before)).toBe('stale');
    const failed = await check();
    expect(failed.state).toBe('fail');
    expect(failed.text).toMatch(/^Not yet: the grammar has errors/);

    const mine = await editorText(page);
    await page.getByTestId('learn-lesson').getByRole('button', { name: /^Open the starting grammar/ }).click();
    const confirm = page.getByTestId('confirm-replace');
    await confirm.waitFor({ state: 'visible' });
    await page.getByTestId('confirm-cancel').click();
    await confirm.waitFor({ state: 'hidden' });
    expect(await editorText(page)).toBe(mine);
    expect(problems).toEqual([]);
  });

  it('works from the keyboard: next and previous lesson, back to the list, Escape closes', async () => {
    const panel = page.getByTestId('learn-lesson');
    await panel.getByRole('button', { name: /^Next lesson: / }).focus();
    await page.keyboard.press('Enter');
    // The next lesson is fetched: wait for it rather than the title still shown.
    await expect.poll(() => panel.locator('.lesson-meta').textContent()).toContain('lesson 5 of');
    expect(await page.evaluate(() => document.activeElement?.classList.contains('lesson-title'))).toBe(true);
    await panel.getByRole('button', { name: /^Previous lesson: / }).focus();
    await page.keyboard.press('Enter');
    await panel.getByRole('heading', { name: lesson.title, level: 2 }).waitFor();
    await panel.getByRole('button', { name: 'All lessons' }).focus();
    await page.keyboard.press('Enter');
    // The list focuses the lesson shown last.
    expect(await page.evaluate(() => (document.activeElement as HTMLElement | null)?.dataset.slug)).toBe(LESSON);
    await page.keyboard.press('Escape');
    await expect(page.getByTestId('learn').isVisible()).resolves.toBe(false);
    expect(await page.evaluate(() => document.activeElement?.id)).toBe('open-learn');
    expect(problems).toEqual([]);
  });

  it('covers the studio on a phone, and gets out of the way when a grammar is opened', async () => {
    const phone = await openStudio(browser, 'light', { width: 390, height: 844 });
    try {
      await phone.page.getByTestId('open-learn').click();
      await phone.page.getByTestId('learn-contents').getByRole('button', { name: lesson.title }).click();
      await phone.page.waitForFunction(() => document.querySelector<HTMLImageElement>('.lesson-figure img')?.dataset.state === 'ready', null, { timeout: 60_000 });
      const box = await phone.page.getByTestId('learn').boundingBox();
      expect(box).toEqual({ x: 0, y: 0, width: 390, height: 844 });
      const overflow = await phone.page.getByTestId('learn-lesson').evaluate((e) => e.scrollWidth - e.clientWidth);
      expect(overflow, 'nothing wider than the phone').toBeLessThanOrEqual(0);
      await savePage(phone.page, 'lesson-phone.png');
      await phone.page.getByRole('button', { name: /^Open in the editor: / }).first().click();
      await phone.page.getByTestId('learn').waitFor({ state: 'hidden' });
      expect(phone.problems).toEqual([]);
    } finally {
      await phone.page.close();
    }
  });
});
