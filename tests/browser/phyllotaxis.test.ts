// End-to-end: ABOP chapters 3 and 4 in the studio. The sunflower head is drawn (brown disk florets
// darker towards the centre, yellow rays at the rim: read on the pixels), the gallery groups the
// new examples by chapter, the Learn panel counts a head's parastichies from the page's own build
// (the mesh the worker delivered), and Mycelis, Lychnis and the pine cone are opened at laptop
// size. Screenshots land in test-results/ for a person to look at.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { colourShare, distinctColours, foregroundShare } from './pictures';
import { canvasPicture, generation, nextBuild, openExample, savePage } from './studio-page';
import { page, problems, useStudio } from './session';

useStudio();

/** The sunflower's ray yellow (#color 24: 250 200 30, shaded) and its disk browns (#color 20–23). */
const rayYellow = (r: number, g: number, b: number) => r > 150 && g > 0.6 * r && b < 0.45 * g;
const diskBrown = (r: number, g: number, b: number) => r > 1.3 * g && g > 1.2 * b && r < 200;

describe('ABOP chapters 3 and 4 in the studio', () => {
  it('draws the sunflower head: many brown disk florets inside a ring of yellow rays', async () => {
    expect(await openExample(page, 'abop-sec-4.1-sunflower-head.lsys')).toBe('ok');
    await page.getByTestId('frame').click();
    const head = await canvasPicture(page, 'chapter4-sunflower-head.png');
    expect(foregroundShare(head)).toBeGreaterThan(0.15);
    expect(colourShare(head, rayYellow), 'the rays').toBeGreaterThan(0.15);
    expect(colourShare(head, diskBrown), 'the disk').toBeGreaterThan(0.15);
    expect(distinctColours(head), 'shaded florets of four browns').toBeGreaterThan(200);
    expect(problems).toEqual([]);
  });

  it('groups the new examples under chapters 3 and 4 of the gallery', async () => {
    await page.getByTestId('open-gallery').click();
    const group = (title: string) => page.locator('.gallery-group').filter({ has: page.getByRole('heading', { name: title }) });
    const herbs = group('ABOP chapter 3: developmental models of herbaceous plants');
    const phyllotaxis = group('ABOP chapter 4: phyllotaxis');
    expect(await herbs.locator('button.example-card').count()).toBeGreaterThanOrEqual(8);
    expect(await phyllotaxis.locator('button.example-card').count()).toBeGreaterThanOrEqual(7);
    // Every card's thumbnail is drawn (the gallery's renderer builds each example).
    for (const [group, picture] of [
      [herbs, 'chapter3-gallery.png'],
      [phyllotaxis, 'chapter4-gallery.png'],
    ] as const) {
      await group.scrollIntoViewIfNeeded();
      const images = group.locator('button.example-card img');
      await expect
        .poll(async () => (await images.evaluateAll((all) => all.map((i) => (i as HTMLElement).dataset.state))).filter((s) => s !== 'ready'), { timeout: 60_000, interval: 500 })
        .toEqual([]);
      await savePage(page, picture);
    }
    await page.keyboard.press('Escape');
  });

  it('counts a head’s parastichies in the Learn panel from the plant on screen', async () => {
    const lesson = JSON.parse(readFileSync(new URL('../../dist/lessons/19-vogel-golden-angle.json', import.meta.url), 'utf8')) as { title: string };
    await page.getByTestId('open-learn').click();
    await page.getByTestId('learn-contents').getByRole('button', { name: lesson.title }).click();
    const panel = page.getByTestId('learn-lesson');
    await panel.getByRole('heading', { name: lesson.title, level: 2 }).waitFor();
    const check = async () => {
      const box = panel.locator('.lesson-task-box').first();
      await box.getByTestId('task-check').click();
      await page.waitForFunction(() => ['pass', 'fail'].includes(document.querySelector<HTMLElement>('[data-testid=task-result]')?.dataset.state ?? ''));
      return (await box.getByTestId('task-result').textContent()) ?? '';
    };
    let before = await generation(page);
    await panel.locator('.lesson-task-box').first().getByRole('button', { name: /^Open the starting grammar/ }).click();
    const replace = page.getByTestId('confirm-replace-button');
    if (await replace.isVisible().catch(() => false)) await replace.click();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await check()).toMatch(/^Not yet: parastichies_m is 21, the task wants 34/);
    await panel.locator('.lesson-task-box').first().getByText('Show solution').click();
    before = await generation(page);
    await panel.locator('.lesson-task-box').first().getByRole('button', { name: /^Open solution/ }).click();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await check()).toBe('Passed: parastichies_m is 34; parastichies_n is 55.');
    await savePage(page, 'chapter4-lesson-parastichies.png');
    await page.getByTestId('open-learn').click();
    expect(problems).toEqual([]);
  });

  it('shows Mycelis, Lychnis and the pine cone at laptop size', async () => {
    // The least share of the picture each plant covers, framed: Lychnis at the book's n = 20 is
    // an open plant of thin stems (about 0.024 of the picture), the others fill more.
    for (const [file, picture, least] of [
      ['abop-ls-3.2-mycelis-muralis.lsys', 'chapter3-mycelis.png', 0.03],
      ['abop-3.14-lychnis-coronaria.lsys', 'chapter3-lychnis.png', 0.015],
      ['abop-sec-4.2-pine-cone.lsys', 'chapter4-pine-cone.png', 0.03],
      ['abop-sec-4.2-pineapple.lsys', 'chapter4-pineapple.png', 0.03],
    ] as const) {
      expect(await openExample(page, file), file).toBe('ok');
      await page.getByTestId('frame').click();
      const shot = await canvasPicture(page, picture);
      expect(foregroundShare(shot), file).toBeGreaterThan(least);
      await savePage(page, picture.replace('.png', '-page.png'));
    }
    expect(problems).toEqual([]);
  });
});
