// End-to-end: the surface editor (issue 46) in the built studio. A flower whose petal is the
// library's: the Surfaces menu opens the editor, which writes the petal out as patch lines; a drag
// of a control point with the mouse rewrites its x y z in the text and the plant's pixels change;
// one Ctrl+Z in the text restores the text before the drag (Ctrl+Y brings the drag back); the
// glTF from the Download menu carries the moved point and passes the Khronos validator; the chosen
// point nudged from the keyboard; a broken patch line typed while the editor is open is an error it
// shows. Screenshots at laptop size, at 200 % and on a phone (touch), where axe finds no serious
// accessibility problem in the dialog. The editor's view shows the surface in the plant's colour:
// leaf green by default, the turtle's colour where the plant sets one, never a fixed pink.
import { readFileSync, writeFileSync } from 'node:fs';
import { AxeBuilder } from '@axe-core/playwright';
import { validateBytes } from 'gltf-validator';
import { describe, expect, it, vi } from 'vitest';
import { colourShare, decodePng, differingShare, type Picture } from './pictures';
import { canvasPicture, editorText, generation, nextBuild, pasteText, PHONE, replaceTextByTouch, RESULTS, studioIn, twoFrames } from './studio-page';
import { browser, page, problems, useStudio } from './session';

vi.setConfig({ testTimeout: 120_000 });

/** Three petals of the library's shape at 60° from a short stem. */
const FLOWER = '#surface P petal\naxiom: F(1) [&(60) ~P(2)] /(120) [&(60) ~P(2)] /(120) [&(60) ~P(2)]\n';

useStudio();

/** Opens the surface editor on ~P from the Surfaces menu of the view's tools. */
async function openEditor(p = page): Promise<void> {
  await p.getByTestId('surfaces-menu').locator('summary').click();
  await p.getByTestId('edit-surface-P').click();
  await p.getByTestId('surface-dialog').waitFor({ state: 'visible' });
  await expect.poll(() => p.getByTestId('surface-status').textContent(), { timeout: 20_000 }).toContain('~P');
}

/** The editor's 3D view as a picture (saved as `name`). */
async function editorView(name: string, p = page): Promise<Picture> {
  await twoFrames(p);
  const png = await p.getByTestId('surface-view').screenshot();
  writeFileSync(new URL(name, RESULTS), png);
  return decodePng(png);
}

/** Pixel tests: leaf green, the red of `#color 9 220 40 40` lit, and the pink the editor used to draw every surface in. */
const GREEN = (r: number, g: number, b: number) => g > r + 25 && g > b + 25;
const RED = (r: number, g: number, b: number) => r > 110 && g < 0.55 * r && b < 0.55 * r;
const PINK = (r: number, g: number, b: number) => r > 150 && b > 100 && g < r - 40 && b > g + 10;

/** The highest point of the plant in a GLB (its POSITION accessors' max y). */
function topOf(glb: Buffer): number {
  const json = JSON.parse(glb.subarray(20, 20 + glb.readUInt32LE(12)).toString('utf8')) as { meshes: { primitives: { attributes: { POSITION: number } }[] }[]; accessors: { max: number[] }[] };
  return Math.max(...json.meshes.flatMap((m) => m.primitives.map((p) => json.accessors[p.attributes.POSITION].max[1])));
}

/** Downloads the plant on screen as glTF from the Download menu; checks it with the validator. */
async function downloadGlb(): Promise<Buffer> {
  await page.getByTestId('downloads').locator('summary').click();
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('download-glb').click()]);
  const bytes = readFileSync(await download.path());
  const report = await validateBytes(new Uint8Array(bytes), { uri: 'flower.glb', maxIssues: 20 });
  const issues = report.issues.messages.map((m) => `${m.code}: ${m.message}`).join('\n');
  expect(report.issues.numErrors, issues).toBe(0);
  expect(report.issues.numWarnings, issues).toBe(0);
  return bytes;
}

describe('the surface editor', () => {
  let written = '';
  let plainTop = 0;

  it('opens from the Surfaces menu and writes a library petal out as patch lines', async () => {
    expect(await pasteText(page, FLOWER)).toBe('ok');
    await openEditor();
    expect(await page.getByTestId('surface-status').textContent()).toContain("the library's petal");
    // No colour is chosen before ~P: the plant draws the petal leaf green, and so does the editor.
    const view = await editorView('surface-editor-green.png');
    expect(colourShare(view, GREEN), 'leaf green').toBeGreaterThan(0.03);
    expect(colourShare(view, PINK), 'no pink').toBeLessThan(0.001);
    const before = await generation(page);
    await page.getByTestId('surface-write-out').click();
    expect(await nextBuild(page, before)).toBe('ok');
    written = await editorText(page);
    expect(written.match(/^#patch P /gm)?.length).toBe(2);
    await expect.poll(() => page.getByTestId('surface-status').textContent()).toContain('2 patches');
    plainTop = topOf(await downloadGlb());
    await page.screenshot({ path: new URL('surface-editor-laptop.png', RESULTS).pathname });
  });

  it('drags a control point: the text follows, the plant changes, one Ctrl+Z restores the text', async () => {
    const before = await canvasPicture(page, 'surface-plant-before.png');
    // The tip of the first patch's midrib (row 4, column 1), dragged up the screen (along the petal).
    const tip = (await page.evaluate(() => window.__meristem!.surfacePointOnPage!(12)))!;
    expect(tip).not.toBeNull();
    const built = await generation(page);
    await page.mouse.move(tip.x, tip.y);
    await page.mouse.down();
    for (let k = 1; k <= 8; k++) await page.mouse.move(tip.x, tip.y - 8 * k);
    await page.mouse.up();
    expect(await nextBuild(page, built)).toBe('ok');
    const dragged = await editorText(page);
    expect(dragged).not.toBe(written);
    // Only the tip's two copies changed, each written with at most 4 decimals.
    const changed = dragged.split('\n').filter((line, k) => line !== written.split('\n')[k]);
    expect(changed.length).toBe(2);
    expect(dragged).not.toMatch(/\d\.\d{5}/);
    await twoFrames(page);
    const after = await canvasPicture(page, 'surface-plant-after.png');
    expect(differingShare(before, after, 40), 'the plant changed').toBeGreaterThan(0.001);
    await page.screenshot({ path: new URL('surface-editor-dragged.png', RESULTS).pathname });

    // One undo in the text: the text before the drag.
    await page.locator('[data-testid=editor] .cm-content').click();
    await page.keyboard.press('Control+z');
    expect(await editorText(page)).toBe(written);
    await page.keyboard.press('Control+y'); // and the drag back, for the download
    expect(await editorText(page)).toBe(dragged);
    await page.waitForFunction((source) => window.__meristem?.preview?.lastResult?.source === source && window.__meristem.preview.settled, dragged);
  });

  it('exports the edited petal as valid glTF that carries the moved point', async () => {
    const top = topOf(await downloadGlb());
    expect(top).toBeGreaterThan(plainTop + 0.05);
    expect(problems).toEqual([]);
  });

  it('moves the chosen point from the keyboard, and says what is wrong when the text breaks', async () => {
    const before = await editorText(page);
    await page.getByTestId('surface-point').selectOption('0'); // the base of the midrib, 0 0 0
    await page.getByTestId('surface-view').focus();
    await page.keyboard.press('ArrowRight'); // x + 0.01 (a hundredth of the petal, rounded to a power of ten)
    await expect.poll(() => page.getByTestId('surface-x').inputValue()).toBe('0.01');
    const nudged = await editorText(page);
    expect(nudged.split('\n')[1].startsWith('#patch P 0.01 0 0, ')).toBe(true);
    expect(nudged.split('\n')[2]).toContain(', 0.01 0 0, -0.28'); // its copy in the other half: the seam stays closed
    // A patch line with too few numbers, typed while the editor is open: the error, no crash.
    await page.locator('[data-testid=editor] .cm-content').click();
    await page.keyboard.press('Control+End');
    await page.keyboard.type('\n#patch P 1 2');
    await expect.poll(() => page.getByTestId('surface-status').textContent()).toContain('E0220');
    expect(await page.getByTestId('surface-status').getAttribute('data-state')).toBe('error');
    for (let k = 0; k < 3 && (await editorText(page)) !== nudged; k++) await page.keyboard.press('Control+z');
    expect(await editorText(page)).toBe(nudged);
    await page.keyboard.press('Control+z'); // the nudge was one undo step
    expect(await editorText(page)).toBe(before);
    await expect.poll(() => page.getByTestId('surface-status').getAttribute('data-state')).toBe('ok');
    expect(problems).toEqual([]);
  });
});

describe("the surface editor's colours", () => {
  it("shows the surface in the turtle's colour at the plant's first ~P", async () => {
    const red = '#color 9 220 40 40\n#surface P petal\naxiom: F(1) ;(9) [&(60) ~P(2)] /(120) [&(60) ~P(2)]\n';
    expect(await pasteText(page, red)).toBe('ok');
    await openEditor();
    await expect.poll(async () => colourShare(await editorView('surface-editor-red.png'), RED), { timeout: 20_000 }).toBeGreaterThan(0.03);
    const view = await editorView('surface-editor-red.png');
    // Green only in the turtle's heading arrow (about 0.3 % of the view), none in the petal.
    expect(colourShare(view, GREEN), 'no leaf green').toBeLessThan(0.01);
    expect(colourShare(view, PINK), 'no pink').toBeLessThan(0.001);
    expect(problems).toEqual([]);
  });
});

describe('the surface editor at 200 % and on a phone', () => {
  it.each([
    ['200', { viewport: { width: 1280, height: 800 }, deviceScaleFactor: 2 }],
    ['phone', PHONE],
  ] as const)('at %s: the dialog fits and shows the petal', async (label, options) => {
    const context = await browser.newContext(options);
    const opened = await studioIn(await context.newPage());
    if (label === 'phone') {
      // The grammar and the plant take turns on a phone: the grammar's pane for the text, then the plant's.
      await opened.page.getByTestId('pane-toggle').tap();
      expect(await replaceTextByTouch(opened.page, FLOWER)).toBe('ok');
      await opened.page.getByTestId('pane-toggle').tap();
    } else expect(await pasteText(opened.page, FLOWER)).toBe('ok');
    await openEditor(opened.page);
    const box = (await opened.page.getByTestId('surface-dialog').boundingBox())!;
    const viewport = opened.page.viewportSize()!;
    expect(box.width).toBeLessThanOrEqual(viewport.width + 1);
    expect(box.y + box.height).toBeLessThanOrEqual(viewport.height + 1);
    await opened.page.screenshot({ path: new URL(`surface-editor-${label}.png`, RESULTS).pathname });
    // No serious or critical accessibility violation in the dialog (axe, WCAG 2.1 AA).
    const audit = await new AxeBuilder({ page: opened.page }).include('[data-testid=surface-dialog]').withTags(['wcag2a', 'wcag2aa', 'wcag21aa']).analyze();
    expect(audit.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`)).toEqual([]);
    expect(opened.problems).toEqual([]);
    await context.close();
  });
});
