// End-to-end (issue 17): what the studio shows of the derivation. The Iterations box is visibly an
// override of the grammar's #iterations (its placeholder the grammar's value, a mark and a × while it
// holds a number), gives way when the grammar's line is edited or another example opened, and the
// errors its number causes are told in the notice bar; the derived string shows numbers with 6
// significant digits, the exact text in the module's tooltip.
import { describe, expect, it } from 'vitest';
import { generation, nextBuild, openFromGallery, savePage, shownStats } from './studio-page';
import { page, problems, useStudio } from './session';

useStudio();

const box = () => page.getByTestId('iterations');

/** What the box shows: its value, its placeholder, and its override mark if shown. */
async function iterationsBox(): Promise<{ value: string; placeholder: string | null; mark: string | null }> {
  const tag = page.getByTestId('iterations-tag');
  return {
    value: await box().inputValue(),
    placeholder: await box().getAttribute('placeholder'),
    mark: (await tag.isVisible()) && (await page.getByTestId('iterations-reset').isVisible()) ? await tag.textContent() : null,
  };
}

/** Types `text` at the end of the editor's line holding `line`, after `erase` backspaces; waits for the build. */
async function editLine(line: string, erase: number, text: string): Promise<string | null> {
  const before = await generation(page);
  await page.locator('[data-testid=editor] .cm-line', { hasText: line }).click();
  await page.keyboard.press('End');
  for (let i = 0; i < erase; i++) await page.keyboard.press('Backspace');
  await page.keyboard.type(text);
  return nextBuild(page, before);
}

/** Puts `value` in the iterations box and waits for the build. */
async function fillBox(value: string): Promise<string | null> {
  const before = await generation(page);
  await box().fill(value);
  return nextBuild(page, before);
}

describe('the Iterations box', () => {
  it('shows the grammar’s value as its placeholder, and typing #iterations 4 with an empty box builds 4', async () => {
    expect(await iterationsBox()).toEqual({ value: '', placeholder: 'grammar: 7', mark: null });
    expect((await shownStats(page))?.iterations).toBe(7);
    expect(await editLine('#iterations 7', 1, '4')).toBe('ok');
    expect((await shownStats(page))?.iterations).toBe(4);
    expect(await iterationsBox()).toEqual({ value: '', placeholder: 'grammar: 4', mark: null });
    expect(problems).toEqual([]);
  });

  it('marks a number in the box as an override of the grammar’s, which × or editing the grammar’s line clears', async () => {
    expect(await fillBox('3')).toBe('ok');
    expect((await shownStats(page))?.iterations).toBe(3);
    expect(await iterationsBox()).toEqual({ value: '3', placeholder: 'grammar: 4', mark: 'overrides 4' });
    await savePage(page, 'iterations-override.png');
    // The grammar's own line edited: the user means its new value.
    expect(await editLine('#iterations 4', 1, '5')).toBe('ok');
    expect((await shownStats(page))?.iterations).toBe(5);
    expect(await iterationsBox()).toEqual({ value: '', placeholder: 'grammar: 5', mark: null });
    // The ×.
    expect(await fillBox('2')).toBe('ok');
    const before = await generation(page);
    await page.getByTestId('iterations-reset').click();
    expect(await nextBuild(page, before)).toBe('ok');
    expect((await shownStats(page))?.iterations).toBe(5);
    expect(await iterationsBox()).toEqual({ value: '', placeholder: 'grammar: 5', mark: null });
    expect(problems).toEqual([]);
  });

  it('is cleared when another example is opened', async () => {
    expect(await fillBox('2')).toBe('ok');
    const before = await generation(page);
    await openFromGallery(page, 'abop-2.06a-monopodial.lsys');
    await page.getByTestId('confirm-replace-button').click(); // the text was edited: the studio asks first
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await iterationsBox()).toEqual({ value: '', placeholder: 'grammar: 10', mark: null });
    expect((await shownStats(page))?.iterations).toBe(10);
    expect(problems).toEqual([]);
  });

  it('tells the module limit a number in the box hits in the notice bar, with the core’s message, and marks the box, not the text', async () => {
    expect(await fillBox('30')).toBe('stale');
    const notice = page.getByTestId('notice');
    await notice.waitFor({ state: 'visible' });
    expect(await page.getByTestId('notice-text').textContent()).toBe("30 iterations, from the Iterations box (the grammar's own: 10), are too many:");
    expect(await page.getByTestId('notice-list').textContent()).toMatch(/^E0400: step \d+ would make a string of \d+ modules or more, above the limit of 5000000/);
    // The box says it at the box; the grammar is not to blame, so its text has no mark (issue 48).
    const box = page.getByTestId('iterations');
    await expect.poll(() => box.getAttribute('aria-invalid')).toBe('true');
    expect(await page.locator('[data-testid=editor] .cm-lintRange-error').count()).toBe(0);
    await savePage(page, 'iterations-over-the-limit.png');
    // Back within the limit: the notice goes, and the box's mark.
    expect(await fillBox('9')).toBe('ok');
    expect(await notice.isVisible()).toBe(false);
    expect(await box.getAttribute('aria-invalid')).not.toBe('true');
    expect(await page.locator('[data-testid=editor] .cm-lintRange-error').count()).toBe(0);
    expect(problems).toEqual([]);
  });
});

describe('the derived string', () => {
  it('shows numbers with up to 6 significant digits, the exact text in the tooltip', async () => {
    expect(await fillBox('')).toBe('ok'); // the monopodial tree at its own 10 steps
    const exact = 'F(0.016796159999999997)';
    const index = await page.evaluate(async (text) => {
      const good = window.__meristem!.preview!.lastGood!;
      const texts = await good.inspector.moduleTexts(0, good.build.moduleCount);
      return texts.indexOf(text);
    }, exact);
    expect(index, `${exact} is in the string`).toBeGreaterThanOrEqual(0);
    await page.locator('[data-testid=string-panel]').evaluate((scroller, i) => (scroller.scrollTop = Math.floor(i / 40) * 22), index);
    const module = page.locator(`[data-testid=string-panel] [data-i="${index}"]`);
    await module.waitFor();
    expect(await module.textContent()).toBe('F(0.0167962)');
    expect(await module.getAttribute('title')).toBe(exact);
    // A module whose text is already short has no tooltip.
    expect(await page.locator('[data-testid=string-panel] .m', { hasText: /^F\(1\)$/ }).first().getAttribute('title')).toBeNull();
    await savePage(page, 'derived-string-numbers.png');
    expect(problems).toEqual([]);
  });
});
