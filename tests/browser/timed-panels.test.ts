// End-to-end: a timed grammar (ABOP 6.1's Anabaena filament) on the timeline, in the built studio
// and in an embed, headless Chromium. The String, Derivation and context panels show the string at
// the timeline's t (its modules and their ages, the rounds up to t), follow Play at their pace and
// show the plant on screen at Pause; an embed and a share link at t derive the grammar at t as the
// studio does (the same modules, the same size, the same string).
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { decodeState, encodeState } from '../../web/src/share';
import { canvasPicture, editorText, example, generation, nextBuild, openStudioOn, savePage, twoFrames } from './studio-page';
import { foregroundShare } from './pictures';

const ANABAENA = 'abop-6.1-timed-anabaena.lsys';

let browser: Browser;
let page: Page;
let problems: string[];

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
  ({ page, problems } = await openStudioOn(browser, ANABAENA));
});

afterAll(async () => {
  await browser?.close();
});

/** Scrubs to `t` and waits for the plant derived at t (`modules` modules) and the panels' handing over. */
async function scrubTimed(p: Page, t: number, modules: number): Promise<void> {
  await p.getByTestId('timeline-slider').fill(String(t));
  await p.waitForFunction(
    ([t, n]) => window.__meristem?.preview?.settled === true && window.__meristem.lastStats?.modules === n && document.querySelector('[data-testid=explain-summary]')?.getAttribute('data-t') === String(t),
    [t, modules],
    { timeout: 30_000 },
  );
  await twoFrames(p);
}

/** The modules the String panel shows, as written there. */
function stringPanel(p: Page): Promise<string[]> {
  return p.getByTestId('string-panel').locator('.m').allTextContents();
}

/** The Derivation tab's row labels and its last row's modules. */
async function derivationRows(p: Page): Promise<{ labels: string[]; last: string[] }> {
  await p.getByTestId('tab-derivation').click();
  const rows = p.getByTestId('derivation').locator('.dv-row');
  await expect.poll(() => rows.count()).toBeGreaterThan(0);
  const labels = await rows.locator('.dv-step').allTextContents();
  const last = await rows.last().locator('.dv-m').allTextContents();
  await p.getByTestId('tab-string').click();
  return { labels, last };
}

describe('the panels of a timed grammar follow the timeline’s t', () => {
  it('show the string at t with each module’s age, and the rounds up to t (counted by hand)', async () => {
    // By hand: every cell divides or turns at age 1 (its terminal age), so rounds are at t = 1, 2, 3:
    // a_r → a_l b_r → b_l a_r a_r → a_l a_l b_r a_l b_r (ABOP's D0L words); at t = 2.5 the three
    // cells of round 2 are 0.5 old, at t = 3.25 the five cells of round 3 are 0.25 old.
    await scrubTimed(page, 2.5, 3);
    expect(await stringPanel(page)).toEqual(['b_l(0.5)', 'a_r(0.5)', 'a_r(0.5)']);
    expect(await page.getByTestId('explain-summary').textContent()).toMatch(/^The string at t = 2\.5 \(a timed module’s first parameter is its age\)\. Put the cursor/);
    expect(await derivationRows(page)).toEqual({ labels: ['ω', '⇒ t 1', '⇒ t 2', 't 2.5'], last: ['b_l(0.5)', 'a_r(0.5)', 'a_r(0.5)'] });

    await scrubTimed(page, 3.25, 5);
    expect(await stringPanel(page)).toEqual(['a_l(0.25)', 'a_l(0.25)', 'b_r(0.25)', 'a_l(0.25)', 'b_r(0.25)']);
    const rows = await derivationRows(page);
    expect(rows.labels).toEqual(['ω', '⇒ t 1', '⇒ t 2', '⇒ t 3', 't 3.25']);
    expect(rows.last).toEqual(await stringPanel(page));
    await savePage(page, 'timed-panels-t3.25.png');
    await page.getByTestId('tab-derivation').click();
    await savePage(page, 'timed-derivation-t3.25.png');
    await page.getByTestId('tab-string').click();

    // At a round's own time the last round is the string at t (ages 0), no row of ageing.
    await scrubTimed(page, 2, 3);
    expect(await stringPanel(page)).toEqual(['b_l(0)', 'a_r(0)', 'a_r(0)']);
    // The Derivation tab is filled after the String tab: wait for its rows of t = 2.
    await expect.poll(async () => (await derivationRows(page)).labels).toEqual(['ω', '⇒ t 1', '⇒ t 2']);
    expect(problems).toEqual([]);
  });

  it('follow Play at most four times a second, and show the plant on screen when Play pauses', async () => {
    await scrubTimed(page, 0.5, 1);
    // Each hand-over to the panels writes the summary's data-t: note when, while it plays.
    await page.evaluate(() => {
      const summary = document.querySelector('[data-testid=explain-summary]')!;
      const seen: number[] = [];
      (window as unknown as { handOvers: number[] }).handOvers = seen;
      new MutationObserver(() => seen.push(performance.now())).observe(summary, { attributes: true, attributeFilter: ['data-t'] });
    });
    const generationAt = () => page.evaluate(() => window.__meristem!.preview!.generation);
    const builtBefore = await generationAt();
    const playedAt = await page.evaluate(() => performance.now());
    await page.getByTestId('timeline-play').click();
    await page.waitForTimeout(2000);
    const pausedAt = await page.evaluate(() => performance.now());
    await page.getByTestId('timeline-play').click(); // Pause
    const builds = (await generationAt()) - builtBefore;
    const t = Number(await page.getByTestId('timeline').getAttribute('data-t'));
    expect(t, 'it played on').toBeGreaterThan(1.5);
    // The build at the paused t arrives, and the panels show it.
    await page.waitForFunction((t) => window.__meristem?.preview?.settled === true && document.querySelector('[data-testid=explain-summary]')?.getAttribute('data-t') === String(t), t, { timeout: 30_000 });
    const handOvers = await page.evaluate((pausedAt) => (window as unknown as { handOvers: number[] }).handOvers.filter((at) => at < pausedAt), pausedAt);
    expect(builds, 'Play derived the grammar at t again and again').toBeGreaterThan(4);
    expect(handOvers.length, 'the panels followed the plant while it played').toBeGreaterThanOrEqual(2);
    expect(builds, 'more builds than hand-overs').toBeGreaterThan(handOvers.length);
    // At most 4 a second (PANELS_EVERY_MS = 250), and one more at either end.
    expect(handOvers.length, `${builds} builds`).toBeLessThanOrEqual(Math.floor((pausedAt - playedAt) / 250) + 2);
    const modules = await page.evaluate(() => window.__meristem!.lastStats!.modules);
    const shown = await stringPanel(page);
    expect(shown).toHaveLength(modules);
    // Every cell was born at the last whole t: its age is t − ⌊t⌋.
    const age = Number((t - Math.floor(t)).toPrecision(6));
    for (const module of shown) expect(Number(/\(([^)]*)\)/.exec(module)![1])).toBeCloseTo(age, 5);
    expect(problems).toEqual([]);
  });

  it('reopen from a share link at t with the same plant and the same panels', async () => {
    await scrubTimed(page, 2.5, 3);
    const hash = await page.evaluate(() => window.__meristem!.derivedHash!());
    const bounds = await page.evaluate(() => window.__meristem!.lastStats!.bounds);
    await page.getByTestId('share').click();
    await expect.poll(() => page.getByTestId('share-link').inputValue()).toMatch(/#s=1\./);
    const link = await page.getByTestId('share-link').inputValue();
    await page.keyboard.press('Escape');

    const other = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    const errors: string[] = [];
    other.on('pageerror', (e) => errors.push(e.message));
    await other.goto(link);
    await other.waitForFunction(
      () => window.__meristem?.preview?.settled === true && window.__meristem.lastStats?.modules === 3 && document.querySelector('[data-testid=explain-summary]')?.getAttribute('data-t') === '2.5',
      undefined,
      { timeout: 30_000 },
    );
    expect(await other.evaluate(() => window.__meristem!.derivedHash!())).toBe(hash);
    expect(await other.evaluate(() => window.__meristem!.lastStats!.bounds)).toEqual(bounds);
    expect(await stringPanel(other)).toEqual(['b_l(0.5)', 'a_r(0.5)', 'a_r(0.5)']);
    expect((await derivationRows(other)).labels).toEqual(['ω', '⇒ t 1', '⇒ t 2', 't 2.5']);
    await other.close();
    expect(errors).toEqual([]);
  });
});

describe('an embedded timed grammar', () => {
  /** Opens embed.html on `text` (the Anabaena's by default) with `query`; returns the page. */
  async function openEmbed(query: string, text = example(ANABAENA)): Promise<{ embed: Page; errors: string[] }> {
    const fragment = await encodeState({ text });
    const embed = await browser.newPage({ viewport: { width: 480, height: 360 } });
    const errors: string[] = [];
    embed.on('pageerror', (e) => errors.push(e.message));
    embed.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    await embed.goto(new URL(`embed.html?${query}${fragment}`, inject('studioUrl')).href);
    return { embed, errors };
  }

  it('at t shows the plant the studio derives at t: the same modules and the same size', async () => {
    await scrubTimed(page, 2.5, 3);
    const studio = await page.evaluate(() => window.__meristem!.lastStats!);
    const { embed, errors } = await openEmbed('t=2.5');
    await embed.waitForFunction(() => document.querySelector('.mp')?.getAttribute('data-modules') === '3', undefined, { timeout: 30_000 });
    const bounds = (await embed.locator('.mp').getAttribute('data-bounds'))!.split(' ').map(Number);
    // The same filament along x (across it the embed's tubes are wider than the studio's lines:
    // a flat plant stays in the Lines mode on the studio's timeline).
    expect(bounds[0]).toBeCloseTo(studio.bounds[0][0], 6);
    expect(bounds[3]).toBeCloseTo(studio.bounds[1][0], 6);
    // The filament is φ^(t+1) long (ABOP 6.1; crate/tests/timed.rs): φ^3.5 at t = 2.5.
    const phi = (1 + Math.sqrt(5)) / 2;
    expect(bounds[3] - bounds[0]).toBeCloseTo(phi ** 3.5, 3);
    const picture = await embed.locator('canvas').first().screenshot();
    expect(picture.length).toBeGreaterThan(0);
    await savePage(embed, 'timed-embed-t2.5.png');
    // "Open in Meristem" keeps the time: the studio opens on the same plant at t = 2.5.
    await expect.poll(async () => (await embed.locator('.mp-open').getAttribute('href')) ?? '').toMatch(/#s=1\./);
    const href = (await embed.locator('.mp-open').getAttribute('href'))!;
    const decoded = await decodeState(new URL(href).hash);
    expect(decoded.ok && decoded.state.growth?.t).toBe(2.5);
    await embed.close();
    const opened = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await opened.goto(href);
    await opened.waitForFunction(
      () => window.__meristem?.preview?.settled === true && window.__meristem.lastStats?.modules === 3 && document.querySelector('[data-testid=explain-summary]')?.getAttribute('data-t') === '2.5',
      undefined,
      { timeout: 30_000 },
    );
    const reopened = await opened.evaluate(() => window.__meristem!.lastStats!.bounds.flat());
    expect(reopened[0]).toBeCloseTo(bounds[0], 6);
    expect(reopened[3]).toBeCloseTo(bounds[3], 6);
    await opened.close();
    expect(errors).toEqual([]);
    // (The camera holds on the whole plant of t = 6, φ^3.5 times the filament's length at 2.5.)
    expect(foregroundShare(await canvasPicture(page, 'timed-studio-t2.5.png')), 'the studio draws it').toBeGreaterThan(0.0003);
  });

  it('plays by deriving at t (the cells divide as it plays), not by growing the whole plant', async () => {
    const { embed, errors } = await openEmbed('animate&loop&speed=2');
    await embed.waitForFunction(() => document.querySelector('.mp')?.hasAttribute('data-modules'), undefined, { timeout: 30_000 });
    const counts = new Set<string>();
    const deadline = Date.now() + 20_000; // 3 s of growth, on a machine that may be busy
    while (Date.now() < deadline && counts.size < 4) {
      counts.add((await embed.locator('.mp').getAttribute('data-modules')) ?? '');
      await embed.waitForTimeout(100);
    }
    counts.delete('');
    // Grown on the GPU, the plant of t = 6 (21 cells) would be shown at every t.
    expect(counts.size, `module counts seen: ${[...counts].join(', ')}`).toBeGreaterThanOrEqual(4);
    await embed.close();
    expect(errors).toEqual([]);
  });

  it('of a stepwise grammar (L-Py’s continuous growth, imported) at t shows the studio’s step ⌊t⌋', async () => {
    // crate/tests/import-corpus/lpy/07-continuous-growth.lpy imports with `#dt 0.1`: stepwise, its
    // plant at t is its derivation's at step ⌊t⌋ (3 segments at step 20, as the CLI counts).
    const before = await generation(page);
    await page.getByTestId('file-input').setInputFiles(new URL('../../crate/tests/import-corpus/lpy/07-continuous-growth.lpy', import.meta.url).pathname);
    expect(await nextBuild(page, before)).toBe('ok');
    await page.getByTestId('timeline-slider').fill('20.5');
    await page.waitForFunction(() => window.__meristem?.preview?.settled === true && window.__meristem.lastStats?.iterations === 20, undefined, { timeout: 30_000 });
    const studio = await page.evaluate(() => window.__meristem!.lastStats!);
    expect(studio.segments).toBe(3);
    const { embed, errors } = await openEmbed('t=20.5', await editorText(page));
    await embed.waitForFunction(() => document.querySelector('.mp')?.getAttribute('data-iterations') === '20', undefined, { timeout: 30_000 });
    expect(await embed.locator('.mp').getAttribute('data-modules')).toBe(String(studio.modules));
    // (Not the bounds: the studio's flat plant in the Lines mode has no tubes meshed to measure.)
    await embed.close();
    expect(errors).toEqual([]);
  });
});
