// End-to-end: the Variants view (issue 48) in headless Chromium, read in pixels. ABOP 2.6a with its
// branching angle a0 at 20, 45 and 70 degrees: three plants side by side (three columns with a
// plant each), one camera (dragging on the figure turns all three: pixels change in every column),
// the figures and the diff of each, one PNG with the three plants, and a share link that reopens
// the three; a hostile link's variants are refused in words.
import { readFileSync, writeFileSync } from 'node:fs';
import { deflateRawSync } from 'node:zlib';
import { describe, expect, inject, it } from 'vitest';
import { decodePng, differingShare, foregroundShare, type Picture } from './pictures';
import { browser, page, problems, useStudio } from './session';
import { openExample, PHONE, RESULTS, twoFrames } from './studio-page';

useStudio();

async function download(testId: string): Promise<{ name: string; bytes: Buffer }> {
  const [file] = await Promise.all([page.waitForEvent('download'), page.getByTestId(testId).click()]);
  return { name: file.suggestedFilename(), bytes: readFileSync((await file.path())!) };
}

/** The `index`-th of `count` columns of a picture, its top `rows` share (above the captions). */
function column(picture: Picture, index: number, count: number, rows = 0.88): Picture {
  const x0 = Math.round((index * picture.width) / count);
  const width = Math.round(picture.width / count);
  const height = Math.round(picture.height * rows);
  const data = new Uint8Array(width * height * 4);
  for (let row = 0; row < height; row++) data.set(picture.data.subarray(4 * (row * picture.width + x0), 4 * (row * picture.width + x0 + width)), 4 * row * width);
  return { width, height, data };
}

const figureCanvas = () => page.getByTestId('variants-figure').locator('canvas');
const captions = () => page.getByTestId('variants-figure').locator('.stage-caption').allTextContents();
const status = () => page.getByTestId('variants-status');

describe('Variants', () => {
  it('draws a constant at three values side by side, turns them together and downloads them as one PNG', async () => {
    expect(await openExample(page, 'abop-2.06a-monopodial.lsys')).toBe('ok');
    await page.getByTestId('variants-toggle').click();
    await expect.poll(() => status().getAttribute('data-state'), { timeout: 60_000 }).toBe('done');
    expect(await captions(), 'opened with its first constant at three values').toEqual(['r1 = 0.675', 'r1 = 0.9', 'r1 = 1.13']);

    await page.getByTestId('variants-constant').selectOption('a0');
    await page.getByTestId('variants-values').fill('20, 45, 70');
    await page.getByTestId('variants-make-define').click();
    await expect.poll(captions, { timeout: 60_000 }).toEqual(['a0 = 20', 'a0 = 45', 'a0 = 70']);
    await expect.poll(() => status().getAttribute('data-state'), { timeout: 60_000 }).toBe('done');
    await twoFrames(page);

    // Each plant's figures (the angle changes no count) and its diff against the first: one line.
    const figures = await page.getByTestId('variant-figures').allTextContents();
    expect(figures).toHaveLength(3);
    for (const f of figures) expect(f).toMatch(/^[\d,]+ modules · [\d,]+ segments · height [\d.]+$/);
    expect(new Set(figures.map((f) => f.replace(/ · height.*/, ''))).size, 'the same counts').toBe(1);
    const diff = page.getByTestId('variant-diff').nth(2);
    expect(await diff.locator('p').textContent()).toBe('1 line differs from plant 1');
    expect(await diff.locator('li').allTextContents()).toEqual(['−was line 21#define a0 20', '+now line 21#define a0 70']);

    // Three columns, a plant in each.
    const before = decodePng(await figureCanvas().screenshot());
    writeFileSync(new URL('variants.png', RESULTS), await page.getByTestId('variants').screenshot());
    for (let c = 0; c < 3; c++) expect(foregroundShare(column(before, c, 3)), `column ${c + 1} holds a plant`).toBeGreaterThan(0.002);

    // Dragging on one plant turns the one camera: every column changes.
    const box = (await figureCanvas().boundingBox())!;
    await page.mouse.move(box.x + box.width / 6, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 6 + 160, box.y + box.height / 2 - 30, { steps: 8 });
    await page.mouse.up();
    await twoFrames(page);
    const after = decodePng(await figureCanvas().screenshot());
    writeFileSync(new URL('variants-turned.png', RESULTS), await figureCanvas().screenshot());
    for (let c = 0; c < 3; c++) {
      expect(differingShare(column(before, c, 3), column(after, c, 3), 40), `column ${c + 1} turned`).toBeGreaterThan(0.001);
      expect(foregroundShare(column(after, c, 3)), `column ${c + 1} still holds its plant`).toBeGreaterThan(0.002);
    }

    // The wheel over one plant zooms them all.
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.wheel(0, -400);
    await twoFrames(page);
    const zoomed = decodePng(await figureCanvas().screenshot());
    for (let c = 0; c < 3; c++) expect(differingShare(column(after, c, 3), column(zoomed, c, 3), 40), `column ${c + 1} zoomed`).toBeGreaterThan(0.001);

    // From the keyboard too: the arrow keys turn them all.
    await page.getByTestId('variants-figure').focus();
    await page.keyboard.press('ArrowLeft');
    await page.keyboard.press('ArrowLeft');
    await twoFrames(page);
    const keyed = decodePng(await figureCanvas().screenshot());
    for (let c = 0; c < 3; c++) expect(differingShare(column(zoomed, c, 3), column(keyed, c, 3), 40), `column ${c + 1} turned by a key`).toBeGreaterThan(0.001);

    // One PNG, a plant in each of its three columns.
    const png = await download('variants-png');
    expect(png.name).toBe('abop-2.6a-variants.png');
    writeFileSync(new URL('variants-download.png', RESULTS), png.bytes);
    const picture = decodePng(png.bytes);
    expect(picture.width).toBe(3 * 420);
    for (let c = 0; c < 3; c++) expect(foregroundShare(column(picture, c, 3)) * picture.width * picture.height, `the PNG's column ${c + 1} holds a plant`).toBeGreaterThan(200);

    const svg = (await download('variants-svg')).bytes.toString('utf8');
    expect([...svg.matchAll(/<text [^>]*>([^<]*)<\/text>/g)].map((m) => m[1])).toEqual(['a0 = 20', 'a0 = 45', 'a0 = 70']);

    // A caption typed in a card is under its plant at once.
    await page.getByTestId('variant-caption').nth(1).fill('book’s 45°');
    await expect.poll(captions).toEqual(['a0 = 20', 'book’s 45°', 'a0 = 70']);
    expect(problems).toEqual([]);
  });

  it('shares the row as one link that reopens it, and refuses a hostile one in words', async () => {
    await page.getByTestId('share').click();
    await page.getByTestId('share-dialog').waitFor({ state: 'visible' });
    await expect.poll(() => page.getByTestId('share-link').inputValue()).toMatch(/#s=1\./);
    const link = await page.getByTestId('share-link').inputValue();
    await page.keyboard.press('Escape');
    const other = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await other.goto(link);
    await expect.poll(() => other.getByTestId('variants-figure').locator('.stage-caption').allTextContents(), { timeout: 60_000 }).toEqual(['a0 = 20', 'book’s 45°', 'a0 = 70']);
    expect(await other.getByTestId('variants-toggle').getAttribute('aria-pressed')).toBe('true');

    const hostile = { v: 1, text: 'axiom: F', variants: Array.from({ length: 500 }, () => ({ text: 'F', caption: '<img src=x onerror=alert(1)>' })) };
    await other.goto(`${inject('studioUrl')}#s=1.${deflateRawSync(Buffer.from(JSON.stringify(hostile))).toString('base64url')}`);
    await expect.poll(() => other.getByTestId('notice').textContent(), { timeout: 30_000 }).toContain('the link’s variants are 500 plants; a link holds 2 to 6');
    await other.close();
  });

  it('stacks the cards under the row on a phone', async () => {
    const phone = await browser.newPage(PHONE);
    await phone.goto(inject('studioUrl'));
    await phone.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
    await phone.getByTestId('variants-toggle').click();
    await expect.poll(() => phone.getByTestId('variants-status').getAttribute('data-state'), { timeout: 60_000 }).toBe('done');
    await twoFrames(phone);
    writeFileSync(new URL('variants-phone.png', RESULTS), await phone.screenshot());
    const picture = decodePng(await phone.getByTestId('variants-figure').locator('canvas').screenshot());
    const count = await phone.getByTestId('variant-card').count();
    expect(count).toBeGreaterThanOrEqual(2);
    for (let c = 0; c < count; c++) expect(foregroundShare(column(picture, c, count)), `column ${c + 1} holds a plant`).toBeGreaterThan(0.001);
    const [first, second] = [await phone.getByTestId('variant-card').nth(0).boundingBox(), await phone.getByTestId('variant-card').nth(1).boundingBox()];
    expect(second!.y, 'one card under the other').toBeGreaterThanOrEqual(first!.y + first!.height);
    expect(first!.width, 'a card as wide as the screen, nearly').toBeGreaterThan(300);
    await phone.close();
  });

  it('stops a long growing at once, and grows again when asked', async () => {
    await page.getByTestId('variants-add-empty').click();
    const card = page.getByTestId('variant-card').nth(3);
    // 2^19 modules rewritten 180 more times: seconds of derivation with nothing to draw (a line-heavy
    // plant would be meshed, or refused by a limit, too fast for a click to land on a fast machine).
    await card.getByTestId('variant-text').fill('#iterations 200\naxiom: A(0)\nA(n) : n < 19 -> A(n+1)A(n+1)\nA(n) : n >= 19 -> A(n+1)\n');
    // Stop shows from the first key: it also cancels a growing still waiting for a pause in the typing.
    expect(await page.getByTestId('variants-stop').isVisible()).toBe(true);
    await expect.poll(() => status().textContent()).toMatch(/\(4 of 4\)/);
    await page.getByTestId('variants-stop').click();
    await expect.poll(() => status().textContent()).toMatch(/^Stopped/);
    expect(await page.getByTestId('variants-stop').isHidden()).toBe(true);
    await card.getByRole('button', { name: 'Remove plant 4' }).click();
    await expect.poll(() => status().textContent(), { timeout: 60_000 }).toMatch(/^3 plants at one scale/);
  });

  it('closes: the plant on screen is back', async () => {
    await page.getByTestId('variants-close').click();
    expect(await page.getByTestId('variants').isHidden()).toBe(true);
    expect(await page.getByTestId('variants-toggle').getAttribute('aria-pressed')).toBe('false');
  });
});
