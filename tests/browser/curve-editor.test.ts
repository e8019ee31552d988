// End-to-end: the curve editor (issue 48) in the built studio. A plant whose internodes' lengths
// are read from a `#curve`: the gutter's marker of the curve's line opens the editor; a drag of a
// control point with the mouse rewrites that point's y in the text (its x as written: the drag went
// straight up) and the plant's pixels change; one Ctrl+Z in the text restores the text and the
// plant. The chosen point nudged from the keyboard is one undo step; a point added and removed by
// the panel's buttons keeps the line's separators; a line that cannot be edited as points is said
// instead of opened; a table imported from a vlab .func is edited by the function's control points.
// On a phone the panel fits the screen, a finger drags a point, and axe finds no serious problem.
import { AxeBuilder } from '@axe-core/playwright';
import { describe, expect, it, vi } from 'vitest';
import type { Page } from 'playwright-core';
import { differingShare } from './pictures';
import { canvasPicture, editorText, generation, nextBuild, pasteText, PHONE, replaceTextByTouch, RESULTS, studioIn } from './studio-page';
import { browser, page, problems, useStudio } from './session';

vi.setConfig({ testTimeout: 120_000 });

/** A plant of five internodes, each as long as the curve says at its place, with side shoots. */
const PLANT = [
  '#curve len 0 1, 0.33 1, 0.66 1, 1 1',
  '#angle 30',
  '#iterations 5',
  'axiom: A(0)',
  'A(t) -> F(len(t)) [+F(len(t))] [-F(len(t))] A(t+0.25)',
  '',
].join('\n');

useStudio();

/** Opens the curve editor on `len` from its line's gutter marker. */
async function openEditor(p: Page = page, tap = false): Promise<void> {
  const marker = p.getByTestId('curve-marker-len');
  await marker.waitFor({ timeout: 20_000 });
  await (tap ? marker.tap() : marker.click());
  await p.getByTestId('curve-dialog').waitFor({ state: 'visible' });
  await expect.poll(() => p.getByTestId('curve-status').textContent(), { timeout: 20_000 }).toContain('4 control points');
}

/** The centre of control point `k` in the plot, on the page (measured in one go: the plot redraws its points). */
async function pointOnPage(k: number, p: Page = page): Promise<{ x: number; y: number }> {
  const found = await p.waitForFunction((k) => {
    const circle = document.querySelectorAll('[data-testid=curve-plot] circle.curve-point')[k];
    const box = circle?.getBoundingClientRect();
    return box && box.width > 0 ? { x: box.x + box.width / 2, y: box.y + box.height / 2 } : null;
  }, k);
  return (await found.jsonValue())!;
}

/**
 * Drags the mouse from `point` straight up by `pixels`, in steps of 10 or less; the plant follows
 * while the button is still down (a build is delivered before it is released). Waits for the
 * build of the text it wrote and returns its state.
 */
async function dragUp(point: { x: number; y: number }, pixels: number): Promise<string | null> {
  const built = await generation(page);
  await page.mouse.move(point.x, point.y);
  await page.mouse.down();
  for (let k = 1; k <= Math.ceil(pixels / 10); k++) await page.mouse.move(point.x, point.y - Math.min(pixels, 10 * k));
  await page.waitForFunction((before) => Number(document.querySelector('[data-testid=status]')?.getAttribute('data-generation') ?? 0) > before, built);
  await page.mouse.up();
  return nextBuild(page, built);
}

/** The curve's line of the editor's text. */
async function curveLine(p: Page = page): Promise<string> {
  return (await editorText(p)).split('\n')[0];
}

describe('the curve editor', () => {
  it('drags a point: the text and the plant follow, and one Ctrl+Z restores both', async () => {
    expect(await pasteText(page, PLANT)).toBe('ok');
    await openEditor();
    const before = await canvasPicture(page, 'curve-plant-before.png');
    const point = await pointOnPage(2);
    expect(await dragUp(point, 80)).toBe('ok');
    const dragged = await curveLine();
    // Only the point's y changed, written with at most 3 decimals; the rest of the line as typed.
    const match = /^#curve len 0 1, 0\.33 1, 0\.66 (\d+(?:\.\d{1,3})?), 1 1$/.exec(dragged);
    expect(match, dragged).not.toBeNull();
    expect(Number(match![1])).toBeGreaterThan(1.2);
    expect((await editorText(page)).split('\n').slice(1).join('\n')).toBe(PLANT.split('\n').slice(1).join('\n'));
    const after = await canvasPicture(page, 'curve-plant-after.png');
    expect(differingShare(before, after, 40), 'the plant changed').toBeGreaterThan(0.002);
    await page.screenshot({ path: new URL('curve-editor-dragged.png', RESULTS).pathname });

    // One undo in the text: the curve and the plant before the drag.
    const undone = await generation(page);
    await page.locator('[data-testid=editor] .cm-line').first().click(); // above the panel
    await page.keyboard.press('Control+z');
    expect(await editorText(page)).toBe(PLANT);
    expect(await nextBuild(page, undone)).toBe('ok');
    const restored = await canvasPicture(page, 'curve-plant-undone.png');
    expect(differingShare(before, restored, 40), 'the plant as before').toBeLessThan(0.0005);
    // The panel follows the text: the point is back on the level of the others, y = 1.
    await expect.poll(async () => Math.abs((await pointOnPage(2)).y - (await pointOnPage(1)).y)).toBeLessThan(0.5);
    expect(problems).toEqual([]);
  });

  it('nudges the chosen point from the keyboard, one undo step a nudge', async () => {
    await page.getByTestId('curve-plot').focus();
    await page.keyboard.press('Home'); // the first point
    await page.keyboard.press(']'); // the second
    await page.keyboard.press('ArrowUp'); // y + 0.01 (a hundredth of the frame, rounded to a power of ten)
    await expect.poll(() => curveLine()).toBe('#curve len 0 1, 0.33 1.01, 0.66 1, 1 1');
    await page.keyboard.press('ArrowLeft');
    await expect.poll(() => curveLine()).toBe('#curve len 0 1, 0.32 1.01, 0.66 1, 1 1');
    expect(await page.getByTestId('curve-x').inputValue()).toBe('0.32');
    // The first point's x bounds the function: arrows move only its y.
    await page.keyboard.press('['); // back to the first
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowDown');
    await expect.poll(() => curveLine()).toBe('#curve len 0 0.99, 0.32 1.01, 0.66 1, 1 1');
    await page.locator('[data-testid=editor] .cm-line').first().click(); // above the panel
    for (const line of ['#curve len 0 1, 0.32 1.01, 0.66 1, 1 1', '#curve len 0 1, 0.33 1.01, 0.66 1, 1 1', '#curve len 0 1, 0.33 1, 0.66 1, 1 1']) {
      await page.keyboard.press('Control+z');
      expect(await curveLine()).toBe(line);
    }
  });

  it("adds and removes a point with the line's separators; a curve keeps its 4", async () => {
    // In the middle of the widest gap (0.66 … 1), on the curve.
    await page.getByTestId('curve-add').click();
    await expect.poll(() => curveLine()).toBe('#curve len 0 1, 0.33 1, 0.66 1, 0.83 1, 1 1');
    await expect.poll(() => page.getByTestId('curve-status').textContent()).toContain('5 control points');
    expect(await page.getByTestId('curve-x').inputValue()).toBe('0.83');
    await page.getByTestId('curve-remove').click();
    await expect.poll(() => curveLine()).toBe(PLANT.split('\n')[0]);
    await page.getByTestId('curve-plot').focus();
    await page.keyboard.press('Home');
    await page.keyboard.press(']');
    expect(await page.getByTestId('curve-remove').isDisabled()).toBe(true);
    expect(await page.getByTestId('curve-remove').getAttribute('title')).toContain('at least 4 points');
    expect(problems).toEqual([]);
  });

  it('says why instead of opening when a line cannot be edited as points', async () => {
    await page.getByTestId('curve-close').click();
    const built = await generation(page);
    await page.locator('[data-testid=editor] .cm-line').first().click(); // above the panel
    await page.keyboard.press('Control+End');
    await page.keyboard.type('#table bad 0 0 1 size');
    await nextBuild(page, built);
    await page.getByTestId('curve-marker-bad').click();
    await expect.poll(() => page.getByTestId('notice').textContent()).toContain("#table bad (line 6) cannot be edited as points: 'size' is not a number");
    expect(await page.getByTestId('curve-dialog').isVisible()).toBe(false);
  });
});

describe('a function imported from a vlab .func file', () => {
  it("opens as the function's control points; a drag rewrites them and the table's samples", async () => {
    const width = [
      '// width: the function of width.func, control points 0 0.147913 0.454706 0.186737 0.72 0.278164 1 0.112564; cpfg reads it through 10 samples, as here',
      '#table width 0 0.147913 0.111111111111 0.158671 0.222222222222 0.1714461 0.333333333333 0.1850653 0.444444444444 0.1976611 0.555555555556 0.2064242 0.666666666667 0.2074151 0.777777777778 0.1956357 0.888888888889 0.1656137 1 0.112564',
      'axiom: A(0)',
      'A(t) -> F(1) [+F(10*width(t))] A(t+0.25)',
      '#iterations 5',
      '',
    ].join('\n');
    expect(await pasteText(page, width)).toBe('ok');
    await page.getByTestId('curve-marker-width').click();
    await expect.poll(() => page.getByTestId('curve-status').textContent()).toContain("4 control points of a function file's B-spline, written as the table's 10 samples");
    expect(await dragUp(await pointOnPage(2), 50)).toBe('ok');
    const [comment, table] = (await editorText(page)).split('\n');
    expect(comment).toMatch(/^\/\/ width: the function of width\.func, control points 0 0\.147913 0\.454706 0\.186737 0\.72 0\.(\d+) 1 0\.112564; cpfg reads/);
    expect(table).not.toBe(width.split('\n')[1]);
    expect(table.split(' ').length).toBe(2 + 20);
    await page.locator('[data-testid=editor] .cm-line').first().click(); // above the panel
    await page.keyboard.press('Control+z');
    expect(await editorText(page)).toBe(width);
    expect(problems).toEqual([]);
  });
});

describe('the curve editor on a phone', () => {
  it('fits the screen, and a finger drags a point', async () => {
    const context = await browser.newContext(PHONE);
    const opened = await studioIn(await context.newPage());
    const p = opened.page;
    await p.getByTestId('pane-toggle').tap();
    expect(await replaceTextByTouch(p, PLANT)).toBe('ok');
    await openEditor(p, true);
    const box = (await p.getByTestId('curve-dialog').boundingBox())!;
    const viewport = p.viewportSize()!;
    expect(box.width).toBeLessThanOrEqual(viewport.width + 1);
    expect(box.y + box.height).toBeLessThanOrEqual(viewport.height + 1);
    // A finger's drag, as Chromium's touch input gives it (pointer events of type touch).
    const point = await pointOnPage(1, p);
    const cdp = await context.newCDPSession(p);
    const touch = (type: 'touchStart' | 'touchMove' | 'touchEnd', y: number) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: type === 'touchEnd' ? [] : [{ x: point.x + 3, y }] });
    await touch('touchStart', point.y);
    for (let k = 1; k <= 6; k++) await touch('touchMove', point.y - 10 * k);
    await touch('touchEnd', point.y - 60);
    await expect.poll(() => curveLine(p)).toMatch(/^#curve len 0 1, 0\.33 1\.\d+, 0\.66 1, 1 1$/);
    await p.screenshot({ path: new URL('curve-editor-phone.png', RESULTS).pathname });
    // No serious or critical accessibility violation in the panel (axe, WCAG 2.1 AA).
    const audit = await new AxeBuilder({ page: p }).include('[data-testid=curve-dialog]').withTags(['wcag2a', 'wcag2aa', 'wcag21aa']).analyze();
    expect(audit.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`)).toEqual([]);
    expect(opened.problems).toEqual([]);
    await context.close();
  });
});
