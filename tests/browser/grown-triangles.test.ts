// End-to-end: while the growth is shown at t, the view draws only the triangles that have begun to
// grow (web/src/view/grown-triangles.ts), and the picture is the one of all the triangles drawn,
// pixel for pixel. ABOP 1.24d at n = 5 in the Tubes mode, with its bark texture: at three times
// the frame is read, then every triangle is drawn at the same t and the frame read again.
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { canvasPicture, generation, nextBuild, openExample, openStudio, twoFrames, type StudioPage } from './studio-page';

let browser: Browser;
let studio: StudioPage;
let page: Page;

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
  studio = await openStudio(browser);
  page = studio.page;
  expect(await openExample(page, 'abop-1.24d.lsys')).toBe('ok');
  let before = await generation(page);
  await page.getByTestId('iterations').fill('5');
  await nextBuild(page, before);
  await page.getByTestId('render-lines').click(); // Tubes (the example is flat: Lines by default)
  await page.getByTestId('timeline-slider').waitFor();
  before = await generation(page);
  await page.getByTestId('timeline-slider').fill('0'); // the first use asks for growth arrays
  await nextBuild(page, before);
  await page.waitForFunction(() => window.__meristem?.growth?.().span === 5);
});

afterAll(async () => {
  await browser?.close();
});

/** The parts of the studio's view this test reads and sets (its own objects, reached through the test hook). */
interface ViewParts {
  renderer: { info: { render: { triangles: number } } };
  shown: { drawn: { geometry: { groups: { start: number; count: number }[]; drawRange: { count: number }; index: { count: number }; setDrawRange(start: number, count: number): void } } };
  requestRender(): void;
}

/** Triangles the last frame drew, and whether the plant's groups or draw range are cut. */
function drawnTriangles(): Promise<{ triangles: number; cut: boolean }> {
  return page.evaluate(() => {
    const v = (window.__meristem!.preview as unknown as { parts: { view: ViewParts } }).parts.view;
    const geometry = v.shown.drawn.geometry;
    const total = geometry.index.count;
    const groups = geometry.groups.reduce((sum, group) => sum + group.count, 0);
    return { triangles: v.renderer.info.render.triangles, cut: geometry.drawRange.count < total || (geometry.groups.length > 0 && groups < total) };
  });
}

/** Draws every triangle of the plant at the growth time shown (as before the cut), and waits for the frame. */
async function drawEveryTriangle(): Promise<void> {
  await page.evaluate(() => {
    const v = (window.__meristem!.preview as unknown as { parts: { view: ViewParts } }).parts.view;
    const geometry = v.shown.drawn.geometry;
    geometry.groups.forEach((group, k) => (group.count = (k + 1 < geometry.groups.length ? geometry.groups[k + 1].start : geometry.index.count) - group.start));
    geometry.setDrawRange(0, Infinity);
    v.requestRender();
  });
  await twoFrames(page);
}

describe('the triangles drawn while the plant grows', () => {
  it('are those begun by t, and the picture is that of every triangle drawn', async () => {
    for (const t of [1.6, 3.3, 4.8]) {
      await page.getByTestId('timeline-slider').fill(String(t));
      await page.waitForFunction((want) => window.__meristem?.growth?.().t === want, t);
      const cut = await canvasPicture(page, `grown-triangles-${t}.png`);
      const drawn = await drawnTriangles();
      expect(drawn.cut, `at t = ${t} some triangles have not begun`).toBe(true);
      await drawEveryTriangle();
      const whole = await canvasPicture(page, `grown-triangles-${t}-all.png`);
      const all = await drawnTriangles();
      expect(all.cut).toBe(false);
      expect(drawn.triangles, `at t = ${t} fewer triangles are drawn`).toBeLessThan(all.triangles);
      expect(cut.width).toBe(whole.width);
      let differing = 0;
      for (let i = 0; i < cut.data.length; i++) if (cut.data[i] !== whole.data[i]) differing += 1;
      expect(differing, `at t = ${t} the pictures are the same`).toBe(0);
    }
    expect(studio.problems).toEqual([]);
  });
});
