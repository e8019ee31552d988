// End-to-end: the studio's controls around the editor and the view: #define sliders, step / play,
// the seed, 2D / 3D, grid and lighting, the camera kept across edits, the splitter, the shortcuts
// and their help, #define completion. Screenshots of the whole page land in test-results/.
import { describe, expect, it } from 'vitest';
import { changedShare, differingShare, foregroundOverlap, foregroundShare } from './pictures';
import {
  canvasPicture,
  editorText,
  generation,
  nextBuild,
  openExample,
  pasteText,
  savePage,
  shownStats,
  twoFrames,
  VIEW_CANVAS,
} from './studio-page';
import { page, problems, useStudio } from './session';

/** Opens an example from the gallery, replacing the text if the studio asks, and waits for it. */
async function open(file: string): Promise<void> {
  expect(await openExample(page, file)).toBe('ok');
}

useStudio();

describe('sliders for #define constants', () => {
  it('has one slider per numeric #define, and dragging one rewrites the text and the plant', async () => {
    await open('abop-2.08a-ternary-tree.lsys');
    const sliders = page.getByTestId('sliders').locator('input[type=range]');
    expect(await sliders.evaluateAll((inputs) => inputs.map((i) => (i as HTMLInputElement).dataset.define))).toEqual(['d1', 'd2', 'a', 'lr', 'vr']);
    const angle = page.locator('input[data-define=a]');
    expect(await angle.evaluate((i: HTMLInputElement) => [i.min, i.max, i.step, i.value])).toEqual(['0', '37.9', '0.01', '18.95']);
    const before = await canvasPicture(page, 'slider-before-canvas.png');

    const box = (await angle.boundingBox())!;
    const start = await generation(page);
    await page.mouse.move(box.x + box.width * 0.5, box.y + box.height / 2);
    await page.mouse.down();
    for (const share of [0.6, 0.7, 0.8, 0.9]) await page.mouse.move(box.x + box.width * share, box.y + box.height / 2, { steps: 3 });
    await page.mouse.up();
    const value = await angle.evaluate((i: HTMLInputElement) => Number(i.value));
    expect(value).toBeGreaterThan(30);
    await expect.poll(() => editorText(page)).toContain(`#define a ${value.toFixed(2)}\n`);
    expect(await nextBuild(page, start)).toBe('ok');
    await page.waitForFunction((text) => window.__meristem?.preview?.lastResult?.source.includes(text), `#define a ${value.toFixed(2)}\n`);
    const after = await canvasPicture(page, 'slider-after-canvas.png');
    await savePage(page, 'studio-sliders.png');
    expect(changedShare(before, after), 'a wider branching angle changes the tree').toBeGreaterThan(0.2);
    // The whole drag is one undo step.
    await page.locator('[data-testid=editor] .cm-content').click();
    await page.keyboard.press('Control+z');
    await expect.poll(() => editorText(page)).toContain('#define a 18.95\n');
    expect(problems).toEqual([]);
  });

  it('uses the range written in a comment, and the keyboard moves a slider', async () => {
    await page.locator('[data-testid=editor] .cm-line', { hasText: '#define a 18.95' }).click();
    await page.keyboard.press('End');
    await page.keyboard.type(' // [10, 60, 0.5]');
    const angle = page.locator('input[data-define=a]');
    await expect.poll(() => angle.evaluate((i: HTMLInputElement) => [i.min, i.max, i.step])).toEqual(['10', '60', '0.5']);
    await angle.focus();
    await page.keyboard.press('ArrowRight');
    await expect.poll(() => editorText(page)).toContain('#define a 19.5 // [10, 60, 0.5]');
    expect(problems).toEqual([]);
  });

  it('completes #define names inside expressions', async () => {
    await page.locator('[data-testid=editor] .cm-content').click();
    await page.keyboard.press('Control+End');
    await page.keyboard.type('\nB -> F(l');
    const list = page.locator('.cm-tooltip-autocomplete');
    await list.waitFor({ state: 'visible' });
    expect(await list.textContent()).toContain('lr');
    await page.keyboard.press('Escape');
    for (let i = 0; i < '\nB -> F(l'.length; i++) await page.keyboard.press('Backspace');
    expect(problems).toEqual([]);
  });

  it('gives a pasted number its own range and step (issue 50, finding 15)', async () => {
    const grammar = (a: string) => `#define a ${a}\n#angle 25\n#iterations 3\naxiom: F\nF -> F[+F]F[-F]F`;
    expect(await pasteText(page, grammar('1000'))).toBe('ok');
    const slider = page.locator('input[data-define=a]');
    await expect.poll(() => slider.evaluate((i: HTMLInputElement) => [i.min, i.max, i.step])).toEqual(['0', '2000', '1']);
    expect(await pasteText(page, grammar('0.5'))).toBe('ok');
    await expect.poll(() => slider.evaluate((i: HTMLInputElement) => [i.min, i.max, i.step])).toEqual(['0', '1', '0.01']);
    await slider.focus();
    await page.keyboard.press('ArrowRight');
    await expect.poll(() => editorText(page)).toContain('#define a 0.51\n');
    // The slider's own value keeps its range: one more step right.
    await page.keyboard.press('ArrowRight');
    await expect.poll(() => editorText(page)).toContain('#define a 0.52\n');
    expect(await slider.evaluate((i: HTMLInputElement) => [i.min, i.max, i.step])).toEqual(['0', '1', '0.01']);
    expect(problems).toEqual([]);
  });
});

describe('iterations: step and play', () => {
  it('steps one iteration back and forward, with the buttons and with Alt+, and Alt+.', async () => {
    await open('abop-1.24d.lsys');
    expect((await shownStats(page))?.iterations).toBe(7);
    let before = await generation(page);
    await page.getByTestId('step-back').click();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await page.getByTestId('iterations').inputValue()).toBe('6');
    expect((await shownStats(page))?.iterations).toBe(6);
    const six = (await shownStats(page))!.segments;

    before = await generation(page);
    await page.keyboard.press('Alt+Comma');
    expect(await nextBuild(page, before)).toBe('ok');
    expect((await shownStats(page))?.iterations).toBe(5);
    expect((await shownStats(page))!.segments).toBeLessThan(six);

    before = await generation(page);
    await page.keyboard.press('Alt+Period');
    await page.getByTestId('step-forward').click();
    await page.waitForFunction(() => window.__meristem?.lastStats?.iterations === 7);
    expect(await page.getByTestId('iterations').inputValue()).toBe('7');
    expect(problems).toEqual([]);
  });

  it('derives only the new step when stepping forward (the build worker continues the plant shown)', async () => {
    await open('abop-1.24d.lsys');
    let before = 0;
    for (const expected of [6, 5]) {
      before = await generation(page);
      await page.getByTestId('step-back').click();
      expect(await nextBuild(page, before)).toBe('ok');
      expect((await shownStats(page))?.iterations).toBe(expected);
    }
    await page.evaluate(() => {
      const w = window as unknown as { __continued: (number | null)[] };
      w.__continued = [];
      window.__meristem!.preview!.onDelivered((r) => w.__continued.push(r.build.continuedFrom ?? null));
    });
    for (const expected of [6, 7]) {
      before = await generation(page);
      await page.getByTestId('step-forward').click();
      expect(await nextBuild(page, before)).toBe('ok');
      expect((await shownStats(page))?.iterations).toBe(expected);
    }
    // Each step forward went on from the plant before it (the studio core has loaded by now).
    expect(await page.evaluate(() => (window as unknown as { __continued: (number | null)[] }).__continued)).toEqual([6, 7].map((n) => n - 1));
    expect(problems).toEqual([]);
  });

});

describe('the seed', () => {
  it('rerolls the choices of a stochastic grammar', async () => {
    await open('abop-1.27-stochastic.lsys');
    const first = await canvasPicture(page, 'seed-first-canvas.png');
    const before = await generation(page);
    await page.getByTestId('reroll').click();
    expect(await nextBuild(page, before)).toBe('ok');
    const seed = await page.getByTestId('seed').inputValue();
    expect(seed).toMatch(/^\d+$/);
    await page.getByTestId('frame').click();
    const second = await canvasPicture(page, 'seed-reroll-canvas.png');
    expect(foregroundOverlap(first, second), 'another seed, another plant').toBeLessThan(0.7);
    // Typing the same seed again gives the same plant.
    const again = await generation(page);
    await page.getByTestId('seed').fill('');
    await nextBuild(page, again);
    const back = await generation(page);
    await page.getByTestId('seed').fill(seed);
    await nextBuild(page, back);
    await page.getByTestId('frame').click();
    expect(foregroundOverlap(second, await canvasPicture(page, 'seed-again-canvas.png'))).toBeGreaterThan(0.95);
    expect(problems).toEqual([]);
  });
});

describe('the view', () => {
  it('shows a flat plant in 2D and a 3D plant in 3D by itself; the 2D button switches', async () => {
    await open('abop-1.24d.lsys');
    const viewport = page.getByTestId('viewport');
    expect(await viewport.getAttribute('data-projection')).toBe('orthographic');
    expect(await page.getByTestId('projection').getAttribute('aria-pressed')).toBe('true');
    const flat = await canvasPicture(page, 'view-2d-canvas.png');
    await page.getByTestId('projection').click();
    expect(await viewport.getAttribute('data-projection')).toBe('perspective');
    expect(await page.getByTestId('projection').getAttribute('aria-pressed')).toBe('false');
    const perspective = await canvasPicture(page, 'view-3d-canvas.png');
    expect(foregroundShare(perspective)).toBeGreaterThan(0.01);
    expect(changedShare(flat, perspective)).toBeGreaterThan(0.3);
    await page.keyboard.press('Alt+o');
    expect(await viewport.getAttribute('data-projection')).toBe('orthographic');

    await open('abop-2.08a-ternary-tree.lsys');
    expect(await viewport.getAttribute('data-projection')).toBe('perspective');
    expect(problems).toEqual([]);
  });

  it('toggles the grid and the lighting', async () => {
    const lit = await canvasPicture(page, 'view-lit-canvas.png');
    await page.getByTestId('lighting').click();
    expect(await page.getByTestId('lighting').getAttribute('aria-pressed')).toBe('false');
    const unlit = await canvasPicture(page, 'view-unlit-canvas.png');
    expect(changedShare(lit, unlit), 'unshaded colours differ from shaded ones').toBeGreaterThan(0.2);
    await page.getByTestId('lighting').click();

    await page.getByTestId('grid').click();
    expect(await page.getByTestId('grid').getAttribute('aria-pressed')).toBe('false');
    const bare = await canvasPicture(page, 'view-no-grid-canvas.png');
    await page.getByTestId('grid').click();
    const gridded = await canvasPicture(page, 'view-grid-canvas.png');
    // The grid is faint on purpose: count every pixel that changed at all.
    expect(differingShare(bare, gridded, 6), 'the grid lines are drawn').toBeGreaterThan(0.01);
    expect(problems).toEqual([]);
  });

  it('keeps the camera where the user put it across edits', async () => {
    const canvas = page.locator(VIEW_CANVAS);
    const box = (await canvas.boundingBox())!;
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 160, box.y + box.height / 2 + 40, { steps: 8 });
    await page.mouse.up();
    const orbited = await canvasPicture(page, 'camera-orbited-canvas.png');
    // Edit the text and edit it back: the same plant, seen from the same place.
    let before = await generation(page);
    await page.locator('[data-testid=editor] .cm-content').click();
    await page.keyboard.press('Control+End');
    await page.keyboard.type('\n// a note');
    await nextBuild(page, before);
    before = await generation(page);
    for (let i = 0; i < '\n// a note'.length; i++) await page.keyboard.press('Backspace');
    await nextBuild(page, before);
    const edited = await canvasPicture(page, 'camera-after-edit-canvas.png');
    expect(foregroundOverlap(orbited, edited)).toBeGreaterThan(0.97);
    // Frame puts it back in the default pose, which differs.
    await page.getByTestId('frame').click();
    expect(foregroundOverlap(orbited, await canvasPicture(page, 'camera-framed-canvas.png'))).toBeLessThan(0.9);
    expect(problems).toEqual([]);
  });
});

describe('layout and keyboard', () => {
  it('resizes the editor with the splitter: dragging and the arrow keys', async () => {
    const width = async () => (await page.getByTestId('editor').boundingBox())!.width;
    const splitter = page.getByTestId('splitter');
    const start = await width();
    await splitter.focus();
    for (let i = 0; i < 5; i++) await page.keyboard.press('ArrowRight');
    await twoFrames(page);
    expect(await width()).toBeGreaterThan(start + 100);
    expect(Number(await splitter.getAttribute('aria-valuenow'))).toBe(50);
    const box = (await splitter.boundingBox())!;
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(400, box.y + box.height / 2, { steps: 5 });
    await page.mouse.up();
    await twoFrames(page);
    expect(Math.abs((await width()) - 400)).toBeLessThan(20);
    await splitter.focus();
    await page.keyboard.press('Enter'); // back to the default
    await twoFrames(page);
    expect(Math.abs((await width()) - start)).toBeLessThan(2);
    // The view follows: the plant is still drawn at the new size.
    expect(foregroundShare(await canvasPicture(page, 'splitter-canvas.png'))).toBeGreaterThan(0.01);
    expect(problems).toEqual([]);
  });

  it('lists the keyboard shortcuts in the help', async () => {
    await page.getByTestId('help').click();
    const help = page.getByTestId('shortcuts');
    await help.waitFor({ state: 'visible' });
    const text = (await help.textContent()) ?? '';
    for (const keys of ['Alt+,', 'Alt+.', 'Alt+P', 'Alt+R', 'Alt+G', 'Alt+K', 'Alt+O']) expect(text).toContain(keys);
    await savePage(page, 'studio-help.png');
    await page.keyboard.press('Escape');
    await help.waitFor({ state: 'hidden' });
    expect(problems).toEqual([]);
  });
});
