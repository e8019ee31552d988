// End-to-end: the Help panel (issue 17): the language reference, rendered at build time, opens from
// the toolbar, from F1 and from a hover doc's Reference link at that name's row; Escape closes it
// and gives the focus back; it is usable on a phone and at 200 % zoom. Screenshots land in
// test-results/.
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { openStudio, savePage } from './studio-page';
import { browser, page, problems, useStudio } from './session';

useStudio();

/** Hovers the first `token` on the editor line that contains `line` and clicks the hover's Reference link. */
async function referenceFromHover(on: Page, line: string, token: string): Promise<void> {
  const found = on.locator('[data-testid=editor] .cm-line', { hasText: line }).first();
  const box = await found.evaluate((element, word) => {
    const text = element.textContent ?? '';
    const at = text.indexOf(word);
    const range = document.createRange();
    const walker = document.createTreeWalker(element, NodeFilter.SHOW_TEXT);
    let offset = 0;
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      const length = node.textContent?.length ?? 0;
      if (at < offset + length) {
        range.setStart(node, at - offset);
        range.setEnd(node, at - offset + 1);
        break;
      }
      offset += length;
    }
    const r = range.getBoundingClientRect();
    return { x: r.x + r.width / 2, y: r.y + r.height / 2 };
  }, token);
  await on.mouse.move(box.x, box.y);
  const link = on.getByTestId('hover-reference');
  await link.waitFor({ state: 'visible' });
  await link.click();
}

/** The reference's marked row: its first cell, and whether it is in the panel's view. */
function markedRow(on: Page): Promise<{ first: string; inView: boolean; focused: boolean } | null> {
  return on.evaluate(() => {
    const row = document.querySelector<HTMLElement>('[data-testid=help-content] .reference-target');
    const content = document.querySelector('[data-testid=help-content]');
    if (!row || !content) return null;
    const r = row.getBoundingClientRect();
    const c = content.getBoundingClientRect();
    return { first: row.querySelector('td')?.textContent ?? '', inView: r.top >= c.top && r.bottom <= c.bottom, focused: document.activeElement === row };
  });
}

describe('the Help panel', () => {
  it('opens from the toolbar with the reference and its contents, and Escape gives the focus back', async () => {
    const help = page.getByTestId('help-panel');
    expect(await help.isVisible()).toBe(false);
    await page.getByTestId('open-help').focus();
    await page.getByTestId('open-help').press('Enter');
    await help.waitFor({ state: 'visible' });
    await page.locator('#ref-F').waitFor({ state: 'attached' });
    expect(await page.getByTestId('open-help').getAttribute('aria-expanded')).toBe('true');
    const content = page.getByTestId('help-content');
    expect(await content.evaluate((c) => document.activeElement === c)).toBe(true);
    expect(await content.locator('h2').first().textContent()).toContain('grammar language');
    // The contents list the sections, and a link moves within the panel, never the page's fragment.
    await content.locator('.reference-toc summary').click();
    await content.locator('.reference-toc a', { hasText: 'Directives' }).click();
    expect(await page.evaluate(() => location.hash)).toBe('');
    expect(await page.locator('#directives').evaluate((h) => h.getBoundingClientRect().top < 200)).toBe(true);
    await savePage(page, 'help-panel.png');
    await page.keyboard.press('Escape');
    await help.waitFor({ state: 'hidden' });
    expect(await page.evaluate(() => document.activeElement?.id)).toBe('open-help');
    expect(problems).toEqual([]);
  });

  it('opens with F1, also from the editor, and closes with its button', async () => {
    await page.locator('[data-testid=editor] .cm-content').click();
    await page.keyboard.press('F1');
    await page.getByTestId('help-panel').waitFor({ state: 'visible' });
    await page.getByTestId('help-close').click();
    await page.getByTestId('help-panel').waitFor({ state: 'hidden' });
    expect(await page.evaluate(() => document.activeElement?.closest('[data-testid=editor]') !== null)).toBe(true);
    expect(problems).toEqual([]);
  });

  it('opens at the row of a directive or a command from the Reference link of its hover doc', async () => {
    await referenceFromHover(page, '#iterations', '#');
    await page.getByTestId('help-panel').waitFor({ state: 'visible' });
    await expect.poll(() => markedRow(page)).toEqual({ first: '#iterations', inView: true, focused: true });
    expect(await page.getByTestId('hover-reference').count(), 'the hover closed').toBe(0);
    await savePage(page, 'help-at-directive.png');

    await referenceFromHover(page, 'F -> FF', 'F');
    await expect.poll(() => markedRow(page)).toEqual({ first: 'F', inView: true, focused: true });
    expect(await page.locator('[data-testid=help-content] .reference-target').count(), 'one row marked').toBe(1);
    await page.keyboard.press('Escape');
    await page.getByTestId('help-panel').waitFor({ state: 'hidden' });
    expect(await page.evaluate(() => document.activeElement?.closest('[data-testid=editor]') !== null), 'back in the editor').toBe(true);
    expect(problems).toEqual([]);
  });

  it('is usable on a phone and at 200 % zoom: the whole width, Close in view, the text scrolls', async () => {
    for (const [name, viewport] of [
      ['phone', { width: 390, height: 844 }],
      ['zoom-200', { width: 640, height: 400 }],
    ] as const) {
      const small = await openStudio(browser, 'light', viewport);
      await small.page.keyboard.press('F1');
      await small.page.locator('#ref-angle').waitFor({ state: 'attached' });
      const panel = (await small.page.getByTestId('help-panel').boundingBox())!;
      expect(panel.x, name).toBe(0);
      expect(panel.width, name).toBe(viewport.width);
      expect(await small.page.getByTestId('help-close').isVisible(), name).toBe(true);
      const close = (await small.page.getByTestId('help-close').boundingBox())!;
      expect(close.x + close.width, name).toBeLessThanOrEqual(viewport.width);
      const scroll = await small.page.getByTestId('help-content').evaluate((c) => ({ scrollable: c.scrollHeight > c.clientHeight, wide: c.scrollWidth > c.clientWidth + 1 }));
      expect(scroll, name).toEqual({ scrollable: true, wide: false });
      await small.page.keyboard.press('PageDown');
      await expect.poll(() => small.page.getByTestId('help-content').evaluate((c) => c.scrollTop), { message: name }).toBeGreaterThan(0);
      await savePage(small.page, `help-panel-${name}.png`);
      await small.page.keyboard.press('Escape');
      await small.page.getByTestId('help-panel').waitFor({ state: 'hidden' });
      expect(small.problems, name).toEqual([]);
      await small.page.close();
    }
  });
});
