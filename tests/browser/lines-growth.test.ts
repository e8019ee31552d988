// End-to-end: the Lines mode grows (issue 45). A flat plant (ABOP 1.24c, a bush, n = 3) drawn as
// lines of constant width, scrubbed on the timeline to t = 2, 2.3, 2.7 and 3: it stays in the Lines
// mode (its lines as wide as chosen, no tubes in their place), the frames between the steps are
// neither step's and grow from one to the next, and at t = 0 only the axiom's segment is drawn
// (the segments not grown yet draw nothing, not a dot at each start).
import { beforeAll, describe, expect, it } from 'vitest';
import { changedShare, foregroundExtent, foregroundShare, strokeWidth, type Picture } from './pictures';
import { page, problems, useStudio } from './session';
import { canvasPicture, generation, nextBuild, openGrowing, scrubTo } from './studio-page';

useStudio();

beforeAll(async () => {
  await page.getByTestId('timeline-slider').waitFor(); // the bar under the view loads after the first plant
});

const growth = () => page.evaluate(() => window.__meristem!.growth!());
const render = () => page.getByTestId('viewport').getAttribute('data-render');

/** The picture at growth time `t`, in the Lines mode. */
async function linesAt(t: number): Promise<Picture> {
  await scrubTo(page, t);
  const picture = await canvasPicture(page, `lines-growth-t${t.toFixed(2)}.png`);
  expect(await render(), `t = ${t}: drawn as lines, not tubes`).toBe('lines');
  return picture;
}

describe('the Lines mode on the timeline', () => {
  it('grows a flat plant as lines: between steps n and n + 1 the frames are neither step, and grow', async () => {
    await openGrowing(page, 'abop-1.24c.lsys', 3);
    expect(await render(), 'a flat plant is drawn as lines').toBe('lines');
    const whole = await canvasPicture(page, 'lines-growth-whole.png');

    const before = await generation(page);
    await page.getByTestId('timeline-slider').fill('2');
    await nextBuild(page, before); // the first use asks for a build with growth times
    expect((await growth()).span).toBe(3);
    expect(await render(), 'the plant with growth times is still drawn as lines').toBe('lines');

    const two = await linesAt(2);
    const early = await linesAt(2.3);
    const late = await linesAt(2.7);
    const three = await linesAt(3);
    const shares = [two, early, late, three].map(foregroundShare);
    expect(shares[0], 'step 2 is drawn').toBeGreaterThan(0.001);
    for (let k = 1; k < shares.length; k++) expect(shares[k], `frame ${k} has grown past frame ${k - 1}`).toBeGreaterThan(shares[k - 1] * 1.05);
    for (const [name, frame] of [['2.3', early], ['2.7', late]] as const) {
      expect(changedShare(two, frame), `t = ${name} is not step 2`).toBeGreaterThan(0.001);
      expect(changedShare(frame, three), `t = ${name} is not step 3`).toBeGreaterThan(0.001);
    }
    expect(changedShare(early, late), 'the two frames between the steps differ').toBeGreaterThan(0.001);
    // Lines of the width chosen (2 CSS pixels), as the whole plant's: not tubes of the grammar's widths.
    expect(strokeWidth(late)).toBeCloseTo(strokeWidth(whole), 0);
    // t = N is the whole plant, drawn as before the timeline was used.
    expect(changedShare(whole, three), 't = 3 is the whole plant').toBeLessThan(0.002);
    expect(problems).toEqual([]);
  });

  it('draws nothing of a segment not grown yet: at t = 0 only the axiom’s segment', async () => {
    const whole = await linesAt(3);
    const start = await linesAt(0);
    const [all, first] = [foregroundExtent(whole), foregroundExtent(start)];
    expect(foregroundShare(start), 'the axiom’s segment is drawn').toBeGreaterThan(0);
    // The axiom's F is the trunk's first internode: a short upright line, not the bush's width
    // of dots (each segment not grown yet would be a round dot at its start).
    expect(first.width, 'as wide as a line').toBeLessThan(all.width / 10);
    expect(first.height).toBeLessThan(all.height / 4);
    expect(problems).toEqual([]);
  });
});
