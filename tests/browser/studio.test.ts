// End-to-end: the built studio in headless Chromium. It must show a plant, redraw it on an edit,
// mark errors in the editor while keeping the last good plant, and log no errors at all.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { changedShare, decodePng, distinctColours, foregroundExtent, foregroundOverlap, foregroundShare, type Picture } from './pictures';
import { openTubesMenu, PLANT_ONLY, VIEW_CANVAS } from './studio-page';
import { isSoftwareRendererName } from '../../web/src/view/rasterizer';

const RESULTS = new URL('../../test-results/', import.meta.url);
const EXAMPLE = readFileSync(new URL('../../public/examples/abop-1.24d.lsys', import.meta.url), 'utf8');

let browser: Browser;
let page: Page;
/** Console errors, uncaught exceptions, failed requests and HTTP errors seen so far. */
const problems: string[] = [];

function save(name: string, png: Buffer): void {
  writeFileSync(new URL(name, RESULTS), png);
}

/** Screenshots the 3D canvas (saved as `name`) and decodes it; overlays such as the stale badge are hidden. */
async function canvasPicture(name: string): Promise<Picture> {
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  const png = await page
    .locator(VIEW_CANVAS)
    .screenshot({ style: PLANT_ONLY });
  save(name, png);
  return decodePng(png);
}

async function savePage(name: string): Promise<void> {
  save(name, await page.screenshot({ fullPage: true }));
}

/** The build counter shown on the status line. */
async function generation(): Promise<number> {
  return Number((await page.getByTestId('status').getAttribute('data-generation')) ?? '0');
}

/**
 * Waits until a build after `previous` finished and the build of the text now in the editor is on
 * screen (builds of the keystrokes between may have come first), and returns the status state.
 */
async function nextBuild(previous: number): Promise<string | null> {
  await page.waitForFunction(
    (before) =>
      Number(document.querySelector('[data-testid=status]')?.getAttribute('data-generation') ?? 0) > before &&
      window.__meristem?.preview?.settled === true,
    previous,
  );
  return page.getByTestId('status').getAttribute('data-state');
}

/** The segment count of the plant on screen, from the page's test hook. */
function shownStats(): Promise<{ segments: number; iterations: number } | null> {
  return page.evaluate(() => window.__meristem?.lastStats ?? null);
}

beforeAll(async () => {
  mkdirSync(RESULTS, { recursive: true });
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
  page = await browser.newPage({ viewport: { width: 1280, height: 800 }, colorScheme: 'light' });
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('requestfailed', (request) => problems.push(`request failed: ${request.url()} ${request.failure()?.errorText}`));
  page.on('response', (response) => {
    if (response.status() >= 400) problems.push(`HTTP ${response.status()}: ${response.url()}`);
  });
  await page.goto(inject('studioUrl'));
});

afterAll(async () => {
  await browser?.close();
});

// eslint-disable-next-line max-lines-per-function -- Long because its steps are one story on one page, each starting where the last ended
describe('the studio', () => {
  let firstPicture: Picture;
  let afterEdit: Picture;

  it('loads the example grammar and shows its plant', async () => {
    await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
    await expect.poll(() => page.getByTestId('status').getAttribute('data-state')).toBe('ok');
    await expect(page.getByTestId('editor').locator('.cm-content').textContent()).resolves.toContain('axiom: X');
    const status = (await page.getByTestId('status').textContent()) ?? '';
    expect(status).toMatch(
      /^[\d,]+ modules · [\d,]+ segments · ([\d,]+ vertices · [\d,]+ triangles|drawn as lines) · parse\+resolve [\d.]+ · derive [\d.]+ · interpret [\d.]+ · mesh [\d.]+ ms · [\d.]+ ms round trip$/,
    );
    expect(await page.title()).toContain('Meristem');

    firstPicture = await canvasPicture('studio-canvas.png');
    await savePage('studio.png');
    const share = foregroundShare(firstPicture);
    expect(share, 'share of the canvas covered by the plant').toBeGreaterThan(0.01);
    expect(share, 'share of the canvas covered by the plant').toBeLessThan(0.6);
    // The example is drawn in one plane: lines of constant width, as in the book (tubes are shaded).
    expect(await page.getByTestId('viewport').getAttribute('data-render')).toBe('lines');
    // Multisampled where a GPU draws; not on a software rasterizer (as here), where it would double
    // every frame's cost (`viewRenderer` in web/src/view/plant-view.ts).
    const { multisampled, renderer } = await page.evaluate(() => {
      const gl = document.querySelector<HTMLCanvasElement>('[data-testid=viewport] canvas')!.getContext('webgl2')!;
      const debug = gl.getExtension('WEBGL_debug_renderer_info');
      return { multisampled: gl.getContextAttributes()?.antialias, renderer: String(debug && gl.getParameter(debug.UNMASKED_RENDERER_WEBGL)) };
    });
    expect(multisampled, renderer).toBe(!isSoftwareRendererName(renderer));
    expect(distinctColours(firstPicture), 'lines over the grid').toBeGreaterThan(multisampled ? 10 : 3);
    expect(foregroundExtent(firstPicture).height, 'the framed plant spans most of the view').toBeGreaterThan(0.6);
    expect(problems).toEqual([]);
  });

  it('shows the doc of a turtle command from the core table on hover', async () => {
    const production = page.getByTestId('editor').locator('.cm-line', { hasText: /^X\s*->/ });
    const draw = production.locator('span', { hasText: /^F$/ }).first();
    const box = await draw.boundingBox();
    expect(box).not.toBeNull();
    await page.mouse.move(box!.x + 1, box!.y + box!.height / 2);
    await page.mouse.move(box!.x + box!.width / 2, box!.y + box!.height / 2);
    const doc = page.locator('.cm-tooltip .cm-command-doc');
    await doc.waitFor({ state: 'visible' });
    expect(await doc.textContent()).toMatch(/^F(\(l = #step\))? — .*draw/);
    await page.mouse.move(900, 20);
    await doc.waitFor({ state: 'hidden' });
    // Directives have docs too, from the core's directive table.
    const angle = page.getByTestId('editor').locator('.cm-line', { hasText: /^#angle/ }).locator('span').first();
    const at = (await angle.boundingBox())!;
    await page.mouse.move(at.x + 2, at.y + at.height / 2);
    await page.mouse.move(at.x + at.width / 2, at.y + at.height / 2);
    await doc.waitFor({ state: 'visible' });
    expect(await doc.textContent()).toMatch(/^#angle degrees — .*turn angle/);
    await page.mouse.move(900, 20);
    await doc.waitFor({ state: 'hidden' });
    expect(problems).toEqual([]);
  });

  it('completes directives and commands from the core tables, and Escape leaves the text as typed', async () => {
    const content = page.getByTestId('editor').locator('.cm-content');
    await content.click();
    await page.keyboard.press('Control+End');
    const before = await generation();
    await page.keyboard.press('Enter');
    await page.keyboard.type('#tro');
    const list = page.locator('.cm-tooltip-autocomplete');
    await list.waitFor({ state: 'visible' });
    expect(await list.textContent()).toContain('#tropism');
    // CodeMirror ignores Enter for `interactionDelay` (75 ms) after the list opens, so that fast
    // typing never picks a completion by accident: a user's Enter comes later than that.
    await page.waitForTimeout(150);
    await page.keyboard.press('Enter'); // accept
    expect(await page.locator('.cm-line').last().textContent()).toBe('#tropism ');
    // Undo the experiment: the example is unchanged and builds as before.
    await page.keyboard.press('Control+z');
    await page.keyboard.press('Control+z');
    await page.keyboard.press('Control+z');
    await page.keyboard.press('Escape');
    await page.waitForFunction((text) => {
      const lines = [...document.querySelectorAll('[data-testid=editor] .cm-line')].map((l) => l.textContent ?? '');
      return lines.join('\n').trimEnd() === text.trimEnd();
    }, EXAMPLE);
    // The half-typed directive was an error (stale plant); the restored text builds again.
    await nextBuild(before);
    await page.waitForFunction(() => document.querySelector('[data-testid=status]')?.getAttribute('data-state') === 'ok');
    expect(problems).toEqual([]);
  });

  it('redraws the plant when the grammar is edited', async () => {
    const angle = /^#angle[ \t]+(\S+)[ \t]*$/m.exec(EXAMPLE);
    expect(angle, 'the example sets #angle').not.toBeNull();
    const before = await generation();
    // Put the caret at the end of the `#angle` line, delete the value and type a new one.
    await page.getByTestId('editor').locator('.cm-line', { hasText: '#angle' }).click();
    await page.keyboard.press('End');
    for (let i = 0; i < angle![1].length; i++) await page.keyboard.press('Backspace');
    await page.keyboard.type('45');
    expect(await nextBuild(before)).toBe('ok');
    await expect(page.getByTestId('editor').locator('.cm-content').textContent()).resolves.toContain('#angle 45');

    afterEdit = await canvasPicture('studio-after-edit-canvas.png');
    await savePage('studio-after-edit.png');
    expect(foregroundShare(afterEdit)).toBeGreaterThan(0.01);
    expect(changedShare(firstPicture, afterEdit), 'share of plant pixels that changed').toBeGreaterThan(0.3);
    expect(problems).toEqual([]);
  });

  it('marks an error in the editor and keeps the last good plant on screen', async () => {
    const goodStats = await shownStats();
    const before = await generation();
    await page.getByTestId('editor').locator('.cm-content').click();
    await page.keyboard.press('Control+End');
    await page.keyboard.insertText('\nY -> F[+Y');
    expect(await nextBuild(before)).toBe('stale');
    await expect(page.getByTestId('status').textContent()).resolves.toMatch(/^1 error — showing last good plant · line \d+: .+/);

    const mark = page.getByTestId('editor').locator('.cm-lintRange-error');
    await mark.first().waitFor({ state: 'visible' });
    expect(await mark.first().textContent()).toBe('[');
    await expect(page.getByTestId('editor').locator('.cm-lint-marker-error').count()).resolves.toBeGreaterThan(0);
    await expect(page.locator('#stale-badge').isVisible()).resolves.toBe(true);

    const stale = await canvasPicture('studio-error-canvas.png');
    await savePage('studio-error.png');
    expect(await shownStats()).toEqual(goodStats);
    expect(foregroundShare(stale), 'a plant is still drawn').toBeGreaterThan(0.01);
    expect(foregroundOverlap(afterEdit, stale), 'it is the last good plant').toBeGreaterThan(0.8);
    expect(problems).toEqual([]);
  });

  it('rebuilds with the iterations typed into the toolbar', async () => {
    // Remove the broken line again, then ask for fewer iterations than the grammar's.
    let before = await generation();
    for (let i = 0; i < '\nY -> F[+Y'.length; i++) await page.keyboard.press('Backspace');
    expect(await nextBuild(before)).toBe('ok');
    const full = await shownStats();

    before = await generation();
    await page.getByTestId('iterations').fill('3');
    expect(await nextBuild(before)).toBe('ok');
    const fewer = await shownStats();
    expect(fewer?.iterations).toBe(3);
    expect(fewer!.segments).toBeLessThan(full!.segments);

    await page.getByTestId('frame').click();
    const framed = await canvasPicture('studio-iterations-canvas.png');
    expect(foregroundShare(framed), 'the small plant is drawn').toBeGreaterThan(0.003);
    expect(foregroundExtent(framed).height, 'Frame fits the small plant to the view').toBeGreaterThan(0.6);
    expect(problems).toEqual([]);
  });

  it('meshes no tubes in the Lines mode, and builds them when the Tubes mode is chosen', async () => {
    const stats = async () =>
      (await page.evaluate(() => window.__meristem?.lastStats ?? null)) as { vertices: number; triangles: number; segments: number };
    // The flat example is drawn as lines (auto): its tubes are not meshed (it has no leaves).
    expect(await page.getByTestId('viewport').getAttribute('data-render')).toBe('lines');
    const lines = await stats();
    expect(lines.segments).toBeGreaterThan(0);
    expect([lines.vertices, lines.triangles], 'no tube meshed in the Lines mode').toEqual([0, 0]);
    let before = await generation();
    await page.getByTestId('render-lines').click();
    expect(await nextBuild(before)).toBe('ok');
    expect(await page.getByTestId('viewport').getAttribute('data-render')).toBe('tubes');
    const tubes = await stats();
    expect(tubes.segments).toBe(lines.segments);
    expect(tubes.vertices, 'the tubes, meshed when they are shown').toBeGreaterThan(10 * tubes.segments);
    await canvasPicture('studio-tubes-canvas.png');
    before = await generation();
    await page.getByTestId('render-lines').click();
    expect(await nextBuild(before)).toBe('ok');
    expect(await page.getByTestId('viewport').getAttribute('data-render')).toBe('lines');
    expect((await stats()).vertices, 'back to lines: no tubes').toBe(0);
    expect(problems).toEqual([]);
  });

  it('re-meshes with the view options: sides and smooth axes', async () => {
    const vertices = async () =>
      (await page.evaluate(() => window.__meristem?.lastStats ?? null)) as { vertices: number; segments: number };
    // In the Tubes mode: the Lines mode (the flat example's) meshes no tubes.
    let before = await generation();
    await page.getByTestId('render-lines').click();
    expect(await nextBuild(before)).toBe('ok');
    const six = await vertices();
    before = await generation();
    await openTubesMenu(page);
    await page.getByTestId('sides').selectOption('12');
    expect(await nextBuild(before)).toBe('ok');
    const twelve = await vertices();
    expect(twelve.segments).toBe(six.segments);
    expect(twelve.vertices, 'twice the sides, about twice the vertices').toBeGreaterThan(1.8 * six.vertices);

    before = await generation();
    await openTubesMenu(page);
    await page.getByTestId('smooth-all').check();
    expect(await nextBuild(before)).toBe('ok');
    const smooth = await vertices();
    expect(smooth.segments).toBe(six.segments);
    expect(smooth.vertices, 'smooth axes have rings between the joints').toBeGreaterThan(twelve.vertices);
    await canvasPicture('studio-smooth-all-canvas.png');

    before = await generation();
    await openTubesMenu(page);
    await page.getByTestId('smooth-all').uncheck();
    await page.getByTestId('sides').selectOption('6');
    await nextBuild(before);
    await page.waitForFunction((v) => window.__meristem?.lastStats?.vertices === v, six.vertices);
    // Back to the Lines mode the example was shown in.
    before = await generation();
    await page.getByTestId('render-lines').click();
    expect(await nextBuild(before)).toBe('ok');
    expect(await page.getByTestId('viewport').getAttribute('data-render')).toBe('lines');
    expect(problems).toEqual([]);
  });

  it('shows the plant first, on screen, on a narrow screen (the grammar is a button away)', async () => {
    await page.setViewportSize({ width: 800, height: 860 });
    await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
    const viewport = await page.getByTestId('viewport').boundingBox();
    expect(viewport).toBeTruthy();
    expect(viewport!.y + viewport!.height, 'the whole view is on screen').toBeLessThanOrEqual(860);
    expect(viewport!.width).toBeGreaterThan(760);
    expect(viewport!.height).toBeGreaterThan(300);
    expect(await page.getByTestId('editor').isVisible(), 'the grammar waits behind its button').toBe(false);
    expect(await page.getByTestId('pane-toggle').isVisible()).toBe(true);
    await savePage('studio-narrow.png');
    expect(foregroundShare(await canvasPicture('studio-narrow-canvas.png')), 'the thin brown plant is drawn').toBeGreaterThan(0.005);
    expect(problems).toEqual([]);
  });
});
