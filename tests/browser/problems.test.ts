// The Problems panel with 100,000 problems (issue 50, finding 11): CodeMirror's lint panel made a
// list item for each and blocked the page for 11 s when opened, and the text carried 100,000
// markers. Now the panel makes only the rows in view, says how many there are, and reaches every
// one (scrolled, End, F8); the text is marked for the first thousand, with a note saying how many
// follow; the page keeps answering.
import { describe, expect, it } from 'vitest';
import { generation, nextBuild, savePage } from './studio-page';
import { page, problems, useStudio } from './session';

useStudio();

/** 100,001 lines: an axiom and 100,000 lines the parser refuses (E0105 each). */
const MANY = `axiom: F\n${'?\n'.repeat(100_000)}`;

/** The longest main-thread task since the last call (the observer installed by `watchLongTasks`). */
function longestTask(): Promise<number> {
  return page.evaluate(() => Math.max(0, ...(window as unknown as { __long: number[] }).__long.splice(0)));
}

async function watchLongTasks(): Promise<void> {
  await page.evaluate(() => {
    const w = window as unknown as { __long: number[] };
    w.__long = [];
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) w.__long.push(entry.duration);
    }).observe({ type: 'longtask' });
  });
}

/** Whether the editor's cursor line is inside the editor's scrolled area, and its text. */
function cursorLine(): Promise<{ shown: boolean; text: string | null }> {
  return page.evaluate(() => {
    const line = document.querySelector('[data-testid=editor] .cm-activeLine');
    const scroller = document.querySelector('[data-testid=editor] .cm-scroller')!.getBoundingClientRect();
    const box = line?.getBoundingClientRect();
    return { shown: !!box && box.top >= scroller.top - 1 && box.bottom <= scroller.bottom + 1, text: line?.textContent ?? null };
  });
}

describe('a text with 100,000 problems', () => {
  it('opens Problems at once with only the rows in view, and every problem reachable', async () => {
    const panel = page.getByTestId('problems');
    const before = await generation(page);
    await page.getByTestId('file-input').setInputFiles({ name: 'many-problems.lsys', mimeType: 'text/plain', buffer: Buffer.from(MANY) });
    expect(await nextBuild(page, before, 60_000)).toBe('stale');
    await page.waitForTimeout(1000); // the linter's turn
    await watchLongTasks();
    await page.getByTestId('show-problems').click();
    await expect.poll(() => panel.locator('.cm-problems-count').textContent()).toBe('100,000 problems');
    // The page answers: a key typed in the list is handled (it chooses the next problem), and no
    // task held the page (generous: opening the old panel took 11 s).
    await page.keyboard.press('ArrowDown');
    await expect.poll(() => panel.locator('.cm-problem[aria-selected=true] .cm-problem-at').textContent()).toBe('2:1');
    expect(await longestTask(), 'the longest task since Problems was pressed (ms)').toBeLessThan(1500);
    const rows = panel.locator('.cm-problem');
    expect(await rows.count(), 'rows made').toBeLessThanOrEqual(30);

    // Scrolled to its end, the list shows the last problem (line 100,001).
    await panel.locator('.cm-problems-list').evaluate((list) => (list.scrollTop = list.scrollHeight));
    await expect.poll(() => rows.last().locator('.cm-problem-at').textContent()).toBe('100001:1');
    expect(await rows.count()).toBeLessThanOrEqual(30);
    await rows.last().click();
    await expect.poll(cursorLine).toEqual({ shown: true, text: '?' });
    await expect.poll(() => panel.locator('.cm-problems-chosen').textContent()).toMatch(/^100001:1 expected a production .* \(E0105\)$/);

    // Home, then F8 in the text goes from problem to problem.
    await panel.locator('.cm-problems-list').press('Home');
    await expect.poll(() => panel.locator('.cm-problem[aria-selected=true] .cm-problem-at').textContent()).toBe('2:1');
    await page.getByTestId('editor').locator('.cm-content').focus();
    await page.keyboard.press('F8');
    await expect.poll(() => panel.locator('.cm-problem[aria-selected=true] .cm-problem-at').textContent()).toBe('3:1');

    // The text is marked for the first thousand problems: past them a note says how many more.
    await panel.locator('.cm-problems-list').focus();
    for (let i = 0; i < 6; i++) await page.keyboard.press('PageDown');
    const at = async () => Number((await panel.locator('.cm-problem[aria-selected=true] .cm-problem-at').textContent())!.split(':')[0]);
    while ((await at()) < 1002) await page.keyboard.press('PageDown');
    const marked = await page.evaluate(() => {
      // Each line's number: the line-number gutter's element at the same height.
      const numbers = [...document.querySelectorAll('[data-testid=editor] .cm-lineNumbers .cm-gutterElement')].map((e) => ({ top: Math.round(e.getBoundingClientRect().top), n: Number(e.textContent) }));
      return [...document.querySelectorAll('[data-testid=editor] .cm-line')].map((line) => ({
        line: numbers.find((g) => g.top === Math.round(line.getBoundingClientRect().top))?.n ?? 0,
        underlined: line.querySelector('.cm-lintRange-error') !== null,
        note: line.querySelector('.cm-lintPoint-info') !== null,
      }));
    });
    expect(marked.find((l) => l.line === 1001)?.underlined, 'line 1001 (problem 1,000) is underlined').toBe(true);
    expect(marked.find((l) => l.line === 1002), 'line 1002: the note, no underline').toMatchObject({ underlined: false, note: true });
    expect(marked.filter((l) => l.line > 1002).some((l) => l.underlined || l.note), 'nothing marked after').toBe(false);
    await savePage(page, 'problems-100k.png');
    expect(problems).toEqual([]);
  }, 120_000);
});
