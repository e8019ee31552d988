// End-to-end: the Download menu of the built studio. Each model download, clicked as a user would,
// must be byte for byte what `meristem export` writes for the same grammar, iterations and view
// options (OBJ: a zip of the tool's OBJ and MTL); the PNG must have the chosen size and show the plant.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { unzipSync } from 'fflate';
import { chromium, type Browser, type Download, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { exportWithCli, galleryDir, removeScratch, scratchDir } from '../export/tools';
import { decodePng, foregroundShare } from './pictures';
import { openTubesMenu, VIEW_CANVAS } from './studio-page';

const RESULTS = new URL('../../test-results/', import.meta.url);
/** A grammar with several colour indices and polygon leaves, at fewer iterations than its own. */
const EXAMPLE = 'abop-1.25-bush.lsys';
/** The name its downloads get: its title's (`// ABOP Fig 1.25: …`). */
const NAME = 'abop-1.25';
const ITERATIONS = '4';
/** The toolbar's view options, and the command-line tool's for the same mesh. */
const SIDES = '8';
const CLI_OPTIONS = ['--iterations', ITERATIONS, '--sides', SIDES, '--smooth-all'];
/** The Download menu's picture settings as it opens (1600 × 1200 at 150 DPI, white), for the SVG; the bush is 3D, so its tubes keep their widths. */
const SVG_LOOK = ['--background', 'white', '--size', '1600x1200', '--dpi', '150'];

let browser: Browser;
let page: Page;
const problems: string[] = [];
const dir = scratchDir('downloads');
const grammarFile = join(dir, 'grammar.lsys');

/** Opens the Download menu unless it is open. */
async function openMenu(): Promise<void> {
  if (!(await page.getByTestId('downloads').evaluate((menu) => (menu as HTMLDetailsElement).open))) {
    await page.getByTestId('downloads').locator('summary').click();
  }
  await page.getByTestId('download-glb').waitFor({ state: 'visible' });
}

/** Clicks a download button in the menu and returns the download the browser made. */
async function clickDownload(testId: string): Promise<Download> {
  await openMenu();
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId(testId).click()]);
  return download;
}

async function downloadedBytes(download: Download): Promise<Buffer> {
  return readFileSync(await download.path());
}

/** Waits for the next build after `previous` and returns the status state. */
async function nextBuild(previous: number): Promise<string | null> {
  await page.waitForFunction(
    (before) =>
      Number(document.querySelector('[data-testid=status]')?.getAttribute('data-generation') ?? 0) > before &&
      window.__meristem?.preview?.settled === true,
    previous,
    { timeout: 30_000 },
  );
  return page.getByTestId('status').getAttribute('data-state');
}

async function generation(): Promise<number> {
  return Number((await page.getByTestId('status').getAttribute('data-generation')) ?? '0');
}

beforeAll(async () => {
  mkdirSync(RESULTS, { recursive: true });
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
  page = await browser.newPage({ viewport: { width: 1280, height: 800 }, colorScheme: 'light', acceptDownloads: true });
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  await page.goto(inject('studioUrl'));
  await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);

  // The grammar, pasted as a user would, and the iterations typed into the toolbar.
  const source = readFileSync(join(galleryDir, EXAMPLE), 'utf8');
  writeFileSync(grammarFile, source);
  let before = await generation();
  await page.getByTestId('editor').locator('.cm-content').click();
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText(source);
  expect(await nextBuild(before)).toBe('ok');
  before = await generation();
  await page.getByTestId('iterations').fill(ITERATIONS);
  expect(await nextBuild(before)).toBe('ok');
  before = await generation();
  await openTubesMenu(page);
  await page.getByTestId('sides').selectOption(SIDES);
  expect(await nextBuild(before)).toBe('ok');
  before = await generation();
  await openTubesMenu(page);
  await page.getByTestId('smooth-all').check();
  expect(await nextBuild(before)).toBe('ok');
  await openMenu();
  writeFileSync(new URL('studio-downloads-menu.png', RESULTS), await page.screenshot());
});

afterAll(async () => {
  await browser?.close();
  removeScratch(dir);
});

// eslint-disable-next-line max-lines-per-function -- Long because its steps are one story on one page, each starting where the last ended
describe('the Download menu', () => {
  it.each(['wrl', 'glb', 'iv', 'svg'])('%s: the bytes of meristem export', async (format) => {
    const download = await clickDownload(`download-${format}`);
    expect(download.suggestedFilename()).toBe(`${NAME}.${format}`);
    const bytes = await downloadedBytes(download);
    const cli = exportWithCli(grammarFile, join(dir, `${NAME}.${format}`), [...CLI_OPTIONS, ...(format === 'svg' ? SVG_LOOK : [])]);
    expect(bytes.length).toBe(cli.length);
    expect(bytes.equals(cli), `${NAME}.${format} differs from the command-line tool's`).toBe(true);
    await expect.poll(() => page.getByTestId('export-status').textContent()).toMatch(new RegExp(`^Saved ${NAME.replace('.', '\\.')}\\.${format} · `));
    expect(problems).toEqual([]);
  });

  it('glb, growth animated: the bytes of meristem export --animate, with its animation', async () => {
    const download = await clickDownload('download-glb-growth');
    expect(download.suggestedFilename()).toBe(`${NAME}-growth.glb`);
    const bytes = await downloadedBytes(download);
    const cli = exportWithCli(grammarFile, join(dir, `${NAME}-growth.glb`), [...CLI_OPTIONS, '--animate']);
    expect(bytes.equals(cli), 'the animated glTF differs from the command-line tool\'s').toBe(true);
    // The JSON chunk (after the 12-byte header and the chunk's length and type) has the animation.
    const json = JSON.parse(bytes.subarray(20, 20 + bytes.readUInt32LE(12)).toString('utf8')) as { animations?: unknown[] };
    expect(json.animations?.length).toBe(1);
    expect(problems).toEqual([]);
  });

  it('obj: a zip of the OBJ and MTL that meristem export writes', async () => {
    const download = await clickDownload('download-obj');
    expect(download.suggestedFilename()).toBe(`${NAME}-obj.zip`);
    const entries = unzipSync(new Uint8Array(await downloadedBytes(download)));
    expect(Object.keys(entries)).toEqual([`${NAME}.obj`, `${NAME}.mtl`]);
    const obj = exportWithCli(grammarFile, join(dir, `${NAME}.obj`), CLI_OPTIONS);
    expect(Buffer.from(entries[`${NAME}.obj`]).equals(obj)).toBe(true);
    expect(Buffer.from(entries[`${NAME}.mtl`]).equals(readFileSync(join(dir, `${NAME}.mtl`)))).toBe(true);
    expect(problems).toEqual([]);
  });

  it('pov: a zip of the scene and the texture images that meristem export writes beside it', async () => {
    const download = await clickDownload('download-pov');
    expect(download.suggestedFilename()).toBe(`${NAME}-pov.zip`);
    const entries = unzipSync(new Uint8Array(await downloadedBytes(download)));
    const names = Object.keys(entries);
    expect(names[0]).toBe(`${NAME}.pov`);
    expect(names.slice(1).every((n) => n === 'bark.png' || n === 'leaf.png') && names.length > 1).toBe(true);
    const pov = exportWithCli(grammarFile, join(dir, `${NAME}.pov`), CLI_OPTIONS);
    expect(Buffer.from(entries[`${NAME}.pov`]).equals(pov)).toBe(true);
    for (const name of names.slice(1)) expect(Buffer.from(entries[name]).equals(readFileSync(join(dir, name)))).toBe(true);
    expect(problems).toEqual([]);
  });

  it('png: a picture of the view at the chosen size', async () => {
    await page.getByTestId('frame').click(); // the view still frames the studio's first plant
    await openMenu();
    await page.getByTestId('png-width').fill('640');
    await page.getByTestId('png-height').fill('360');
    const download = await clickDownload('download-png');
    expect(download.suggestedFilename()).toBe(`${NAME}.png`);
    const bytes = await downloadedBytes(download);
    writeFileSync(new URL('downloaded-view.png', RESULTS), bytes);
    const picture = decodePng(bytes);
    expect([picture.width, picture.height]).toEqual([640, 360]);
    expect(foregroundShare(picture), 'share of the picture covered by the plant').toBeGreaterThan(0.01);
    await expect.poll(() => page.getByTestId('export-status').textContent()).toMatch(/^Saved abop-1\.25\.png · 640 × 360 at 150 DPI · /);
    // The view on the page is back to its own size.
    const canvas = await page.locator(VIEW_CANVAS).boundingBox();
    const viewport = await page.getByTestId('viewport').boundingBox();
    expect(Math.round(canvas!.width)).toBe(Math.round(viewport!.width));
    expect(problems).toEqual([]);
  });

  it('png: a size out of range is refused with the range', async () => {
    await openMenu();
    await page.getByTestId('png-width').fill('8');
    await page.getByTestId('download-png').click();
    await expect.poll(() => page.getByTestId('export-status').getAttribute('data-state')).toBe('error');
    expect(await page.getByTestId('export-status').textContent()).toMatch(/^PNG size: width and height must be whole numbers from 16 to \d+$/);
    await expect(page.getByTestId('png-width').isVisible(), 'the menu stays open to fix the size').resolves.toBe(true);
    expect(problems).toEqual([]);
  });

  it('closes like a menu: after a choice, on Escape and on a click elsewhere', async () => {
    const isOpen = () => page.getByTestId('downloads').evaluate((menu) => (menu as HTMLDetailsElement).open);
    // (Not the SVG: the test before left the picture size out of range, so it is refused.)
    await clickDownload('download-iv');
    expect(await isOpen()).toBe(false);
    await openMenu();
    await page.keyboard.press('Escape');
    expect(await isOpen()).toBe(false);
    await openMenu();
    const view = (await page.getByTestId('viewport').boundingBox())!;
    await page.getByTestId('viewport').click({ position: { x: 40, y: view.height / 2 } });
    expect(await isOpen()).toBe(false);
    expect(problems).toEqual([]);
  });

  it('fits a phone’s width: every setting of the picture inside the menu, none cut off', async () => {
    const size = page.viewportSize()!;
    await page.setViewportSize({ width: 390, height: 844 });
    try {
      await openMenu();
      const menu = (await page.getByTestId('downloads').locator('.download-menu').boundingBox())!;
      expect(menu.x >= 0 && menu.x + menu.width <= 390, 'the menu is on screen').toBe(true);
      for (const id of ['png-width', 'png-height', 'png-paper', 'png-dpi', 'png-background', 'png-line-width']) {
        const box = (await page.getByTestId(id).boundingBox())!;
        expect(box.x + box.width, `${id} ends inside the menu`).toBeLessThanOrEqual(menu.x + menu.width);
      }
      await page.keyboard.press('Escape');
    } finally {
      await page.setViewportSize(size!);
    }
    expect(problems).toEqual([]);
  });

  it('writes a big model in an export worker, showing each stage, and Cancel stops one', async () => {
    // ABOP 1.24d at 10 iterations: 116,050 segments, about 950,000 vertices.
    const source = readFileSync(join(galleryDir, 'abop-1.24d.lsys'), 'utf8');
    let before = await generation();
    await page.getByTestId('editor').locator('.cm-content').click();
    await page.keyboard.press('Control+A');
    await page.keyboard.insertText(source);
    await page.getByTestId('iterations').fill('10');
    await openTubesMenu(page);
    await page.getByTestId('smooth-all').uncheck();
    expect(await nextBuild(before)).toBe('ok');
    before = await generation();
    const exportWorkers: string[] = [];
    page.on('worker', (worker) => {
      if (worker.url().includes('export-worker')) exportWorkers.push(worker.url());
    });
    // Every text the status line shows, as the page sets it.
    await page.evaluate(() => {
      const status = document.querySelector('[data-testid=export-status]')!;
      const seen: string[] = [];
      (window as unknown as { __exportTexts: string[] }).__exportTexts = seen;
      new MutationObserver(() => seen.push(status.textContent ?? '')).observe(status, { childList: true, characterData: true, subtree: true });
    });
    const download = await clickDownload('download-glb');
    const bytes = await downloadedBytes(download);
    const texts = await page.evaluate(() => (window as unknown as { __exportTexts: string[] }).__exportTexts);
    for (const stage of ['parsing (1 of 6)', 'deriving (2 of 6)', 'interpreting (3 of 6)', 'meshing (4 of 6)', 'writing (6 of 6)']) {
      expect(texts, `the status said "${stage}"`).toContain(`Exporting glTF 2.0 binary: ${stage}…`);
    }
    expect(texts.at(-1)).toMatch(/^Saved abop-1\.24d\.glb · \d+(\.\d)? MB$/);
    expect(exportWorkers.length, 'the file was written by an export worker').toBe(1);
    expect(bytes.subarray(0, 4).toString('latin1')).toBe('glTF');
    expect(await page.getByTestId('export-progress').isHidden()).toBe(true);

    // Cancel: the worker goes, no file comes, the menu works again.
    let downloads = 0;
    const count = () => downloads++;
    page.on('download', count);
    await openMenu();
    await page.getByTestId('download-wrl').click();
    await page.getByTestId('export-cancel').click();
    await expect.poll(() => page.getByTestId('export-status').getAttribute('data-state')).toBe('cancelled');
    expect(await page.getByTestId('export-status').textContent()).toBe('Export of VRML 2.0 cancelled');
    await page.waitForTimeout(1500);
    page.off('download', count);
    expect(downloads, 'a cancelled export saves nothing').toBe(0);
    expect(await page.getByTestId('export-cancel').isHidden()).toBe(true);
    await openMenu();
    expect(await page.getByTestId('download-wrl').isEnabled()).toBe(true);
    await page.keyboard.press('Escape');
    expect(problems).toEqual([]);
  });
});

