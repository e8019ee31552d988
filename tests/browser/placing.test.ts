// L-Py's turtle frame and lines to points in the studio (issue 49; docs/LANGUAGE.md, "Turtle"):
// a grammar that writes `@Frame` and `@LineTo` is built again by the studio core (the first
// plant's core has no room for them) and drawn: the frame's three arms in red, green and blue,
// and a line to a point. Laptop, a projector's 200 % zoom and a phone; the pictures are kept.
import { chromium, type Browser } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { colourShare } from './pictures';
import { canvasPicture, PHONE, pasteText, replaceTextByTouch, savePage, shownStats, studioIn } from './studio-page';

/** The frame turned so that all three arms show, and a line from its origin to a point. */
const FRAME = [
  '// The turtle\'s frame: H red, L green, U blue; and a line to the point (-2, -1, 0)',
  '#width_unit 1',
  'axiom: !(0.2)&(35)/(35)@Frame(3)[@LineTo(-2,-1,0)]',
].join('\n');

const red = (r: number, g: number, b: number) => r > 120 && r > 1.8 * g && r > 1.8 * b;
const green = (r: number, g: number, b: number) => g > 90 && g > 1.25 * r && g > 1.25 * b;
const blue = (r: number, g: number, b: number) => b > 120 && b > 1.15 * r && b > 1.05 * g;

let browser: Browser;

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
});

afterAll(async () => {
  await browser?.close();
});

describe('the turtle’s frame and lines to points', () => {
  for (const [name, context] of [
    ['laptop', { viewport: { width: 1280, height: 800 } }],
    ['projector at 200 %', { viewport: { width: 960, height: 600 }, deviceScaleFactor: 2 }],
    ['phone', PHONE],
  ] as const) {
    it(`draws the frame's arms in red, green and blue and the line (${name})`, async () => {
      const context_ = await browser.newContext(context);
      try {
        const { page, problems } = await studioIn(await context_.newPage());
        if (name === 'phone') {
          // The grammar's pane, then back to the plant.
          await page.getByTestId('pane-toggle').tap();
          expect(await replaceTextByTouch(page, FRAME)).toBe('ok');
          await page.getByTestId('pane-toggle').tap();
        } else {
          expect(await pasteText(page, FRAME)).toBe('ok');
        }
        // Three arms and one line: four segments, as the core's own test counts them.
        expect((await shownStats(page))?.segments).toBe(4);
        const picture = await canvasPicture(page, `placing-frame-${name.split(' ')[0]}.png`);
        await savePage(page, `placing-page-${name.split(' ')[0]}.png`);
        for (const [colour, test] of [['red', red], ['green', green], ['blue', blue]] as const) {
          expect(colourShare(picture, test), `${colour} arm`).toBeGreaterThan(0.02);
        }
        expect(problems).toEqual([]);
      } finally {
        await context_.close();
      }
    });
  }
});
