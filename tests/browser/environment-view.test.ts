// End-to-end (issue 47, "Seeing the environment" and its browser tests): a grammar with
// `#environment light` and a box obstacle shows the View toolbar's Environment tools, the light
// grid's heat-map slice and the translucent box in the view (read from pixels: the heat map's
// colours and the box's blue present with the toggle on, absent with it off); moving the slice
// changes the picture; a picked segment shows its `?E`'s reply in words; a grammar without an
// environment hides the tools; a stand of 9 plants builds, shows all 9, and its glTF, downloaded
// from the Download menu, is valid by the Khronos validator. Screenshots land in test-results/.
import { readFileSync, writeFileSync } from 'node:fs';
import { deflateRawSync } from 'node:zlib';
import { validateBytes } from 'gltf-validator';
import type { Download } from 'playwright-core';
import { describe, expect, inject, it } from 'vitest';
import { foregroundExtent, type Picture } from './pictures';
import { canvasPicture, findPixel, pasteText, PHONE, RESULTS, savePage, shownStats } from './studio-page';
import { browser, page, problems, useStudio } from './session';

useStudio();

/** A small tree beside a box; each branch asks the light and the box with one `?E` after its first segment. */
const LIT = `#environment light
#environment obstacle box min 1.5 0 -1 max 3 3 1
#iterations 4
#angle 25
axiom: A
A -> F [ + F ?E(0, 0, 0, 0, 0, 0) A ] [ - F ?E(0, 0, 0, 0, 0, 0) A ] [ & F ?E(0, 0, 0, 0, 0, 0) A ] [ ^ F ?E(0, 0, 0, 0, 0, 0) A ]
`;

/** The same tree drawn flat (only + and -): seen face-on, with a vertical slice. */
const FLAT = `#environment light
#iterations 5
#angle 25
axiom: A
A -> F [ + F ?E(0, 0, 0, 0) A ] [ - F ?E(0, 0, 0, 0) A ]
`;

/** Pixels of `picture` that pass `test`. */
function count(picture: Picture, test: (r: number, g: number, b: number) => boolean): number {
  let n = 0;
  for (let i = 0; i < picture.data.length; i += 4) if (test(picture.data[i], picture.data[i + 1], picture.data[i + 2])) n++;
  return n;
}

// The heat map's colours (view/environment-layer.ts's HEAT_STOPS) at 70% over the background:
// its shade end, purple to deep blue-violet (red and blue both well above green: no bark, leaf
// or background is), and its light end, pale yellow (red and green high, blue clearly below).
const heatShade = (r: number, g: number, b: number) => r > g + 35 && b > g + 35;
const heatLight = (r: number, g: number, b: number) => r > 215 && g > 215 && b < g - 30 && b > 120;
/** The box's translucent steel blue over the background: blue well above red. */
const boxBlue = (r: number, g: number, b: number) => b > r + 35 && b > g + 10;

/** Does `act` with the Environment menu open, then closes it (its panel lies over the view). */
async function inMenu(act: () => Promise<unknown>): Promise<void> {
  const summary = page.getByTestId('environment-menu').locator('summary');
  await summary.click();
  await act();
  await summary.click();
}

async function environmentState(): Promise<string | null> {
  return page.getByTestId('viewport').getAttribute('data-environment');
}

describe('the environment in the view', () => {
  it('draws the light grid as a heat-map slice and the box, and hides them with the toggle', async () => {
    expect(await pasteText(page, LIT)).toBe('ok');
    const toggle = page.getByTestId('environment');
    await toggle.waitFor();
    await expect.poll(environmentState).toMatch(/^y:\d+$/);
    expect(await toggle.getAttribute('aria-pressed')).toBe('true');
    await page.getByTestId('frame').click();
    const on = await canvasPicture(page, 'environment-on.png');
    await savePage(page, 'environment-page.png');
    expect(count(on, heatShade), 'the heat map\'s shade colours').toBeGreaterThan(300);
    expect(count(on, heatLight), 'the heat map\'s light colours').toBeGreaterThan(300);
    // The box over the background (the slice, which it stands in, taken away).
    await inMenu(() => page.getByTestId('environment-axis').selectOption('none'));
    await expect.poll(environmentState).toBe('none:0');
    const box = await canvasPicture(page, 'environment-box.png');
    expect(count(box, boxBlue), 'the box').toBeGreaterThan(300);
    expect(count(box, heatShade) + count(box, heatLight), 'no slice').toBeLessThan(20);
    await inMenu(() => page.getByTestId('environment-axis').selectOption('y'));
    await expect.poll(environmentState).toMatch(/^y:\d+$/);

    await toggle.click();
    await expect.poll(environmentState).toBe('off');
    expect(await toggle.getAttribute('aria-pressed')).toBe('false');
    const off = await canvasPicture(page, 'environment-off.png');
    expect(count(off, heatShade), 'no heat map').toBeLessThan(20);
    expect(count(off, heatLight), 'no heat map').toBeLessThan(20);
    expect(count(off, boxBlue), 'no box').toBeLessThan(20);
    await toggle.click();
    await expect.poll(environmentState).toMatch(/^y:/);
    expect(problems).toEqual([]);
  });

  it('slices a flat plant upright, as it is seen', async () => {
    expect(await pasteText(page, FLAT)).toBe('ok');
    await expect.poll(environmentState).toMatch(/^z:\d+$/);
    const picture = await canvasPicture(page, 'environment-flat.png');
    expect(count(picture, heatShade) + count(picture, heatLight), 'the vertical slice, face-on').toBeGreaterThan(1000);
    expect(problems).toEqual([]);
  });

  it('moves the slice through the grid and turns it upright', async () => {
    expect(await pasteText(page, LIT)).toBe('ok');
    await expect.poll(environmentState).toMatch(/^y:\d+$/);
    const before = await canvasPicture(page, 'environment-slice-a.png');
    const layer = page.getByTestId('environment-layer');
    await inMenu(async () => {
      expect(Number(await layer.getAttribute('max')), 'the light grid has layers').toBeGreaterThan(4);
      await layer.fill('0'); // the ground layer, below the shade
      await expect.poll(environmentState).toBe('y:0');
      await expect.poll(() => page.getByTestId('environment-at').textContent()).toMatch(/^height y = -?[\d.]+ \(layer 1 of \d+\)$/);
    });
    const ground = await canvasPicture(page, 'environment-slice-b.png');
    expect(count(ground, heatShade) + count(ground, heatLight)).not.toBe(count(before, heatShade) + count(before, heatLight));
    await inMenu(() => page.getByTestId('environment-axis').selectOption('z'));
    await expect.poll(environmentState).toMatch(/^z:\d+$/);
    const upright = await canvasPicture(page, 'environment-slice-vertical.png');
    expect(count(upright, heatShade) + count(upright, heatLight), 'a vertical slice is drawn').toBeGreaterThan(300);
    await inMenu(() => page.getByTestId('environment-axis').selectOption('y'));
    expect(problems).toEqual([]);
  });

  it('shows a picked segment\'s ?E reply, named by the programs\' words', async () => {
    // Module 3 of the derived string F [ + F ?E(…) …: the first branch's F, whose ?E follows it.
    await page.getByTestId('string-panel').locator('.m[data-i="3"]').click();
    const reply = page.getByTestId('environment-reply');
    await expect.poll(() => reply.textContent()).toMatch(
      /^ Its \?E\((0\.\d+|1), -?[\d.]+, -?[\d.]+, -?[\d.]+, 1, [\d.]+\): exposure (0\.\d+|1), towards \(-?[\d.]+, -?[\d.]+, -?[\d.]+\), free 1, distance [\d.]+\.$/,
    );
    expect(await reply.getAttribute('data-module')).toBe('4');
    // The trunk's first segment: no ?E on its own branch (its children's are theirs).
    await page.getByTestId('string-panel').locator('.m[data-i="0"]').click();
    await expect.poll(() => reply.textContent()).toBe(' No ?E on this branch.');
    // In the 3D view: a click on a branch (the environment hidden, so that it lands on bark) picks
    // its segment, and the summary says its ?E's reply too.
    await page.getByTestId('environment').click();
    await expect.poll(environmentState).toBe('off');
    const summary = page.getByTestId('explain-summary');
    const before = await summary.textContent();
    const bark = (r: number, g: number, b: number) => r > 60 && r < 210 && r > g + 12 && g > b + 8;
    const spot = await findPixel(page, bark);
    expect(spot, 'a branch on screen').not.toBeNull();
    await page.mouse.click(spot!.x, spot!.y);
    await expect.poll(() => summary.textContent()).not.toBe(before);
    await expect.poll(() => reply.textContent()).toMatch(/^ (Its \?E\(.*\): exposure .*, towards \(.*\), free 1, distance [\d.]+\.|No \?E on this branch\.)$/);
    await page.getByTestId('environment').click();
    expect(problems).toEqual([]);
  });

  it("shows each step's ?E in the derivation view as the environment answered it", async () => {
    // docs/LANGUAGE.md's shoot: its apex rises 1 a step towards a box whose floor is at y = 2.5.
    const shoot = ['#environment obstacle box min -1 2.5 -1 max 1 10 1', '#iterations 4', 'axiom: A ?E(1, 0)', 'A > ?E(f, d) : f == 1 -> F A', 'A > ?E(f, d) : f == 0 -> B', ''].join('\n');
    expect(await pasteText(page, shoot)).toBe('ok');
    await page.getByTestId('tab-derivation').click();
    const rows = page.getByTestId('derivation').locator('.dv-row');
    await expect.poll(() => rows.count()).toBe(5); // steps 0 to 4
    const texts = await rows.allTextContents();
    ['?E(1,2.5)', '?E(1,1.5)', '?E(1,0.5)', '?E(0,-0.5)', '?E(0,-0.5)'].forEach((reply, step) => expect(texts[step], `step ${step}`).toContain(reply));
    await page.getByTestId('tab-string').click();
    expect(problems).toEqual([]);
  });

  it('hides the tools for a grammar without an environment', async () => {
    expect(await pasteText(page, '#iterations 3\naxiom: F\nF -> F[+F]F[-F]F\n')).toBe('ok');
    await expect.poll(() => page.getByTestId('environment').isVisible()).toBe(false);
    const picture = await canvasPicture(page, 'environment-none.png');
    expect(count(picture, heatShade) + count(picture, boxBlue)).toBeLessThan(20);
    expect(problems).toEqual([]);
  });
});

/** A stand of 9 plants, 3 × 3, sharing the light: each plant a small bush asking for it. */
const STAND = `#environment light
#stand grid 3 3 spacing 10
#iterations 4
#angle 30
axiom: A
A -> F [ + F ?E(1, 0, 0, 0) A ] [ - F ?E(1, 0, 0, 0) A ] [ & F ?E(1, 0, 0, 0) A ]
`;

/** Clicks a download of the Download menu and returns the file's bytes. */
async function downloaded(testId: string): Promise<Buffer> {
  const menu = page.getByTestId('downloads');
  if (!(await menu.evaluate((m) => (m as HTMLDetailsElement).open))) await menu.locator('summary').click();
  const [download]: [Download, unknown] = await Promise.all([page.waitForEvent('download'), page.getByTestId(testId).click()]);
  return readFileSync(await download.path());
}

describe('a stand of 9 plants', () => {
  it('builds, shows all 9, and exports a glTF the validator finds valid', async () => {
    expect(await pasteText(page, STAND)).toBe('ok');
    await page.getByTestId('frame').click();
    await page.getByTestId('environment').click(); // the plants alone
    await expect.poll(environmentState).toBe('off');
    await page.getByTestId('grid').click();
    const stats = await shownStats(page);
    // One plant: each A draws 4 segments and leaves 3 A, so 4 × (1 + 3 + 9 + 27) = 160 after 4
    // steps; the stand 9 times as many.
    expect(stats?.segments).toBe(9 * 160);
    // All 9 in the plant's box: the stand spans 2 × 10 between its outer plants in x and z.
    const bounds = await page.evaluate(() => window.__meristem?.lastStats?.bounds);
    expect(bounds![1][0] - bounds![0][0]).toBeGreaterThan(20);
    expect(bounds![1][2] - bounds![0][2]).toBeGreaterThan(20);
    // And on screen, framed: the plants fill most of the view's width.
    const picture = await canvasPicture(page, 'environment-stand.png');
    expect(foregroundExtent(picture).width).toBeGreaterThan(0.6);

    const glb = await downloaded('download-glb');
    const report = await validateBytes(new Uint8Array(glb));
    expect(report.issues.messages).toEqual([]);
    expect(report.issues.numErrors).toBe(0);
    await page.getByTestId('grid').click();
    expect(problems).toEqual([]);
  }, 90_000);
});

describe('the Environment tools at other sizes', () => {
  // A share link's fragment, compressed as the studio compresses (tests/browser/share.test.ts).
  const link = () => `${inject('studioUrl')}#s=1.${Buffer.from(deflateRawSync(Buffer.from(JSON.stringify({ v: 1, text: LIT })))).toString('base64url')}`;
  const sizes = {
    'laptop at 200 %': { viewport: { width: 640, height: 400 }, deviceScaleFactor: 2 },
    phone: PHONE,
  };
  for (const [name, options] of Object.entries(sizes)) {
    it(`are on screen and draw the slice: ${name}`, async () => {
      const context = await browser.newContext(options);
      const small = await context.newPage();
      const seen: string[] = [];
      small.on('pageerror', (e) => seen.push(e.message));
      await small.goto(link());
      // The studio core builds it (the first plant's core leaves environments to it), then the tools come.
      await small.waitForFunction(() => document.querySelector('[data-testid=viewport]')?.getAttribute('data-environment')?.startsWith('y:'), undefined, { timeout: 60_000 });
      // In the View toolbar, which scrolls sideways on a narrow screen: reached as its other tools are.
      const toggle = small.getByTestId('environment');
      await toggle.scrollIntoViewIfNeeded();
      const box = (await toggle.boundingBox())!;
      expect(box.x).toBeGreaterThanOrEqual(0);
      expect(box.x + box.width).toBeLessThanOrEqual(options.viewport.width);
      writeFileSync(new URL(`environment-${name.replace(/\W+/g, '-')}.png`, RESULTS), await small.screenshot());
      const picture = await canvasPicture(small, `environment-${name.replace(/\W+/g, '-')}-canvas.png`);
      expect(count(picture, heatShade) + count(picture, heatLight), 'the slice').toBeGreaterThan(200);
      expect(seen).toEqual([]);
      await context.close();
    }, 90_000);
  }
});
