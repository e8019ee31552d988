// End-to-end: the growth timeline (issue 45) in the built studio, headless Chromium, by pixels.
// ABOP 1.24a at n = 4 scrubbed to t = 2, 2.5 and 3 shows a plant growing between the steps (the
// frame at 2.5 is neither 2's nor 3's, and larger than 2's), at t = N the whole plant as before
// the timeline was used; Play changes the picture frame after frame without a build; a share
// link keeps the time, speed and range; the embed plays the growth; a timed grammar and an
// imported stepwise L-Py model are derived at the time shown.
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { decodeState, encodeState } from '../../web/src/share';
import { changedShare, differingShare, foregroundShare, type Picture } from './pictures';
import { canvasPicture, editorText, example, generation, nextBuild, openExample, openGrowing, openStudio, openTimelineMenu, savePage, scrubTo as scrubToTime, shownStats, twoFrames } from './studio-page';

let browser: Browser;
let page: Page;
let problems: string[];

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
  ({ page, problems } = await openStudio(browser));
  // The bar under the view loads after the first plant.
  await page.getByTestId('timeline-slider').waitFor();
});

afterAll(async () => {
  await browser?.close();
});

const growth = (p: Page = page) => p.evaluate(() => window.__meristem!.growth!());

/** Scrubs the timeline to `t` and waits for its frame. */
const scrubTo = (t: number) => scrubToTime(page, t);

/** The share of the view's pixels that are plant. */
const plantShare = (picture: Picture) => foregroundShare(picture);

describe('the growth timeline', () => {
  it('shows ABOP 1.24a growing between steps: t = 2.5 is neither step 2 nor step 3, and t = N is the whole plant', async () => {
    await openGrowing(page, 'abop-1.24a.lsys', 4);
    const whole = await canvasPicture(page, 'timeline-1.24a-whole.png');
    expect((await growth()).span, 'no growth arrays before the timeline is used').toBeNull();

    const before = await generation(page);
    await page.getByTestId('timeline-slider').fill('2');
    await nextBuild(page, before); // the first use asks for a build with growth arrays
    expect((await growth()).span).toBe(4);
    await scrubTo(2);
    const two = await canvasPicture(page, 'timeline-1.24a-t2.png');
    await scrubTo(2.5);
    const half = await canvasPicture(page, 'timeline-1.24a-t2.5.png');
    await scrubTo(3);
    const three = await canvasPicture(page, 'timeline-1.24a-t3.png');
    expect(await page.getByTestId('timeline-time').textContent()).toBe('t 3.00 of 4 · step 3');
    const [a, b, c] = [plantShare(two), plantShare(half), plantShare(three)];
    expect(a, 'something is drawn at t = 2 (step 2: a ninth of the height)').toBeGreaterThan(0.0002);
    expect(b, 't = 2.5 has grown past t = 2').toBeGreaterThan(a * 1.1);
    expect(c, 't = 3 has grown past t = 2.5').toBeGreaterThan(b * 1.05);
    expect(changedShare(two, half), 't = 2.5 is not step 2').toBeGreaterThan(0.001);
    expect(changedShare(half, three), 't = 2.5 is not step 3').toBeGreaterThan(0.001);

    await scrubTo(4);
    expect((await growth()).t, 'at t = N the plant is shown whole').toBeNull();
    const end = await canvasPicture(page, 'timeline-1.24a-t4.png');
    expect(differingShare(whole, end, 40), 't = N is the whole plant as before').toBeLessThan(0.002);
    expect(problems).toEqual([]);
  });

  it('plays: frames change while it plays, with no build, and Pause stops it', async () => {
    await openTimelineMenu(page);
    // A quarter of a step a second: slow screenshots (a loaded machine) do not reach the end,
    // where Play stops by itself and the Pause key would start it again.
    await page.getByTestId('timeline-speed').selectOption('0.25');
    await page.keyboard.press('Escape');
    await scrubTo(0.5);
    const generationBefore = await generation(page);
    await page.getByTestId('timeline-play').click();
    expect(await page.getByTestId('play').getAttribute('aria-pressed'), 'the toolbar’s Play is the same Play').toBe('true');
    const first = await canvasPicture(page, 'timeline-play-0.png');
    await page.waitForTimeout(1000);
    const second = await canvasPicture(page, 'timeline-play-1.png');
    await page.keyboard.press('Alt+p');
    expect(await page.getByTestId('timeline-play').getAttribute('aria-pressed')).toBe('false');
    expect(changedShare(first, second), 'a second of playing changed the picture').toBeGreaterThan(0.001);
    const { t } = await growth();
    expect(t).toBeGreaterThan(0.6);
    expect(t).toBeLessThan(4);
    expect(await generation(page), 'playing built nothing').toBe(generationBefore);
    await page.waitForTimeout(300);
    expect((await growth()).t, 'paused').toBe(t);
    expect(problems).toEqual([]);
  });

  it('steps with the keys on the slider: ← → a step, Shift a tenth', async () => {
    await scrubTo(2);
    await page.getByTestId('timeline-slider').focus();
    await page.keyboard.press('ArrowRight');
    expect((await growth()).t).toBe(3);
    await page.keyboard.press('Shift+ArrowLeft');
    expect((await growth()).t).toBeCloseTo(2.9, 9);
    await page.keyboard.press('Home');
    expect((await growth()).t).toBe(0);
    expect(problems).toEqual([]);
  });

  it('keeps the time, speed and range in a share link, and the link opens at that time', async () => {
    await scrubTo(2.5);
    await openTimelineMenu(page);
    await page.getByTestId('timeline-speed').selectOption('0.5');
    await page.getByTestId('timeline-from').fill('1');
    await page.getByTestId('timeline-from').dispatchEvent('change');
    await page.getByTestId('timeline-loop').check();
    await page.keyboard.press('Escape');
    await page.getByTestId('share').click();
    // The link is written once the state is encoded (asynchronously): wait for it.
    await expect.poll(() => page.getByTestId('share-link').inputValue()).toMatch(/#s=1\./);
    const link = await page.getByTestId('share-link').inputValue();
    await page.keyboard.press('Escape');
    const decoded = await decodeState(new URL(link).hash);
    expect(decoded.ok && decoded.state.growth).toEqual({ t: 2.5, speed: 0.5, from: 1, loop: true });

    const other = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    const opened: string[] = [];
    other.on('pageerror', (e) => opened.push(e.message));
    await other.goto(link);
    await other.waitForFunction(() => window.__meristem?.growth?.().t === 2.5, undefined, { timeout: 30_000 });
    expect(await other.getByTestId('timeline-speed').inputValue()).toBe('0.5');
    expect(await other.getByTestId('timeline-loop').isChecked()).toBe(true);
    await savePage(other, 'timeline-link.png');
    await other.close();
    expect(opened).toEqual([]);
    expect(problems).toEqual([]);
  });

  it('plays in embed.html from its query (animate loop speed)', async () => {
    const fragment = await encodeState({ text: example('abop-1.24a.lsys'), iterations: 3 });
    const embed = await browser.newPage({ viewport: { width: 480, height: 360 } });
    const errors: string[] = [];
    embed.on('pageerror', (e) => errors.push(e.message));
    await embed.goto(new URL(`embed.html?animate&loop&speed=2${fragment}`, inject('studioUrl')).href);
    await embed.waitForFunction(() => Number(document.querySelector('.mp')?.getAttribute('data-t') ?? 0) > 0.2, undefined, { timeout: 30_000 });
    const t1 = Number(await embed.locator('.mp').getAttribute('data-t'));
    await embed.waitForTimeout(500);
    const t2 = Number(await embed.locator('.mp').getAttribute('data-t'));
    expect(t2, 'the embed plays on').not.toBe(t1);
    await embed.close();
    expect(errors).toEqual([]);
  });
});

describe('a timed grammar on the timeline', () => {
  it('derives a timed grammar at the time scrubbed to (the Anabaena filament of ABOP 6.1)', async () => {
    expect(await openExample(page, 'abop-6.1-timed-anabaena.lsys')).toBe('ok');
    /** Scrubs to `t` and waits for the plant derived at t: `modules` modules. */
    const scrubTimed = async (t: number, modules: number) => {
      await page.getByTestId('timeline-slider').fill(String(t));
      await page.waitForFunction((n) => window.__meristem?.preview?.settled === true && window.__meristem.lastStats?.modules === n, modules, { timeout: 30_000 });
      await twoFrames(page);
    };
    await scrubTimed(2.5, 3); // b_l(0.5) a_r(0.5) a_r(0.5)
    expect(await page.getByTestId('timeline-time').textContent()).toMatch(/^t 2\.50 of 6/);
    const length = () => page.evaluate(() => window.__meristem!.lastStats!.bounds[1][0] - window.__meristem!.lastStats!.bounds[0][0]);
    // The filament is φ^(t+1) long (each cell grows between divisions): φ^3.5 at t = 2.5, φ^5 at 4.
    const phi = (1 + Math.sqrt(5)) / 2;
    expect(await length()).toBeCloseTo(phi ** 3.5, 3);
    const early = foregroundShare(await canvasPicture(page, 'timeline-anabaena-t2.5.png'));
    expect(early, 'the filament is drawn').toBeGreaterThan(0.0003);
    await scrubTimed(4, 8); // step 4 of the D0L-system
    expect(await length()).toBeCloseTo(phi ** 5, 3);
    // The camera stays on the whole filament (t = 6) it framed: the filament grows on screen.
    const later = foregroundShare(await canvasPicture(page, 'timeline-anabaena-t4.png'));
    expect(later, 'the filament at t = 4 is longer on screen than at 2.5').toBeGreaterThan(1.5 * early);
    await scrubTimed(6, 21); // the grammar's own iterations again
    expect(problems).toEqual([]);
  });
});

// A continuous-growth model of L-Py, imported as a user opens it, plays on the timeline (issue 45:
// "the import of an L-Py continuous-growth model plays"). The file is L-Py's own
// `07-continuous-growth.lpy` (crate/tests/import-corpus/SOURCES.md): an apex that lays down an
// internode every T = 0.5 in steps of dt = 0.1, internodes that lengthen with their age, 100 steps.
// Its import declares `#dt 0.1`, so it is stepwise (docs/LANGUAGE.md, "Growth in time"): the
// timeline shows its derivation at each whole step, as L-Py's Animate and the CLI's `--at` do,
// and not the whole plant's mesh grown in (its internodes would all be full length).
const LPY = new URL('../../crate/tests/import-corpus/lpy/07-continuous-growth.lpy', import.meta.url);

/** Scrubs the timeline to `t` and waits for the plant derived to step ⌊t⌋ to be drawn. */
async function scrubToStep(t: number): Promise<void> {
  await page.getByTestId('timeline-slider').fill(String(t));
  await page.waitForFunction((want) => window.__meristem!.lastStats?.iterations === want, Math.floor(t));
  await twoFrames(page);
}

describe('an imported L-Py continuous-growth model', () => {
  it('opens from the picker, shows its derivation at each whole step of the timeline, and plays it step after step', async () => {
    let before = await generation(page);
    await page.getByTestId('file-input').setInputFiles(LPY.pathname);
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await editorText(page)).toMatch(/^\/\/ Imported from L-Py/);
    await page.getByTestId('grid').click(); // only the plant differs from the background

    // The first use of the timeline asks for the studio core's build: the grammar is stepwise,
    // and the timeline spans its 100 steps.
    before = await generation(page);
    await page.getByTestId('timeline-slider').fill('20');
    await nextBuild(page, before);
    await page.waitForFunction(() => window.__meristem!.lastStats?.iterations === 20);
    // The CLI's counts (`meristem derive --at T --stats` of the imported text): 3 segments at
    // t = 20 (two internodes and the young one), 6 at t = 40; 40.5 is step 40.
    expect(await shownStats(page)).toMatchObject({ iterations: 20, segments: 3 });
    const twenty = await canvasPicture(page, 'import-growth-lpy-t20.png');
    await scrubToStep(40.5);
    expect(await shownStats(page)).toMatchObject({ iterations: 40, segments: 6 });
    const forty = await canvasPicture(page, 'import-growth-lpy-t40.png');
    await scrubToStep(45);
    const fortyFive = await canvasPicture(page, 'import-growth-lpy-t45.png');
    expect(foregroundShare(twenty), 'a plant is drawn at t = 20').toBeGreaterThan(0.0005);
    expect(foregroundShare(forty), 'the plant is larger at t = 40').toBeGreaterThan(foregroundShare(twenty));
    // The young internodes lengthen with their age at every step (the camera stays on the whole
    // plant: the top one, 0.5 of the plant's 8.8 longer by t = 45, is a few pixels of line).
    expect(differingShare(forty, fortyFive), 'step 45 is not step 40').toBeGreaterThan(0.00003);

    await openTimelineMenu(page);
    await page.getByTestId('timeline-speed').selectOption('4');
    await page.keyboard.press('Escape');
    await scrubToStep(10);
    await page.evaluate(() => {
      const w = window as unknown as { __continued: (number | null)[] };
      w.__continued = [];
      window.__meristem!.preview!.onDelivered((r) => w.__continued.push(r.build.continuedFrom ?? null));
    });
    await page.getByTestId('timeline-play').click();
    const first = await canvasPicture(page, 'import-growth-lpy-play-0.png');
    await page.waitForTimeout(1500);
    const second = await canvasPicture(page, 'import-growth-lpy-play-1.png');
    await page.keyboard.press('Alt+p');
    expect(changedShare(first, second), 'playing changed the picture').toBeGreaterThan(0.0005);
    // (The view's growth time stays null: a derived plant is shown whole; the slider has t.)
    expect(Number(await page.getByTestId('timeline-slider').inputValue())).toBeGreaterThan(13);
    // The steps of Play went on from the steps before them (incremental stepping), none from the axiom.
    const continued = await page.evaluate(() => (window as unknown as { __continued: (number | null)[] }).__continued);
    expect(continued.length).toBeGreaterThan(1);
    expect(continued, 'each build of Play went on from an earlier step').toEqual(continued.map((from) => (from !== null && from >= 10 ? from : 'from the axiom')));
    expect(problems).toEqual([]);
  });
});
