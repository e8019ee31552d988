// End-to-end: every example of the gallery opened through the gallery dialog, as a user does it:
// no console errors, the text in the editor, a plant on the canvas. And the gallery's own
// behaviour: thumbnails, keyboard use, and never losing the user's text.
import { describe, expect, it } from 'vitest';
import { decodePng, foregroundExtent, foregroundShare } from './pictures';
import { canvasPicture, editorText, example, exampleFiles, generation, nextBuild, openFromGallery, savePage } from './studio-page';
import { page, problems, useStudio } from './session';

useStudio();

describe('every gallery example, opened from the gallery', () => {
  it.each(exampleFiles())('%s opens and shows a plant', async (file) => {
    const before = await generation(page);
    await openFromGallery(page, file);
    await expect(page.getByTestId('gallery').isVisible()).resolves.toBe(false);
    expect(await nextBuild(page, before)).toBe('ok');
    await page.waitForFunction((text) => {
      const lines = [...document.querySelectorAll('[data-testid=editor] .cm-line')].map((l) => l.textContent ?? '');
      return lines.join('\n') === text.replace(/\r/g, '');
    }, example(file));
    const picture = await canvasPicture(page, `example-${file.replace(/\.lsys$/, '')}.png`);
    const extent = foregroundExtent(picture);
    expect(foregroundShare(picture), 'share of the canvas covered').toBeGreaterThan(0.002);
    expect(Math.max(extent.width, extent.height), 'the plant is framed to fill the view').toBeGreaterThan(0.4);
    expect(problems).toEqual([]);
  });
});

describe('the gallery dialog', () => {
  it('draws a thumbnail of every example', async () => {
    await page.getByTestId('open-gallery').click();
    const count = exampleFiles().length;
    await page.waitForFunction(
      (n) => document.querySelectorAll('[data-testid=gallery-list] img[data-state=ready]').length === n,
      count,
      { timeout: 60_000 },
    );
    await savePage(page, 'gallery-dialog.png');
    // Each picture shows a plant (read back by drawing the image on a canvas: the page's CSP lets
    // images, not fetches, load blob: URLs).
    const pngs = await page.$$eval('[data-testid=gallery-list] img', (images) =>
      images.map((image) => {
        const img = image as HTMLImageElement;
        const canvas = document.createElement('canvas');
        [canvas.width, canvas.height] = [img.naturalWidth, img.naturalHeight];
        canvas.getContext('2d')!.drawImage(img, 0, 0);
        return canvas.toDataURL('image/png').replace(/^data:image\/png;base64,/, '');
      }),
    );
    expect(pngs).toHaveLength(count);
    for (const png of pngs) expect(foregroundShare(decodePng(Buffer.from(png, 'base64')))).toBeGreaterThan(0.005);
    const titles = await page.$$eval('.example-title', (spans) => spans.map((s) => s.textContent));
    expect(titles).toContain('ABOP Fig 1.24d: a plant by node rewriting');
    await page.keyboard.press('Escape');
    await expect(page.getByTestId('gallery').isVisible()).resolves.toBe(false);
    expect(problems).toEqual([]);
  }, 90_000);

  it('works from the keyboard: Alt+G opens it, the arrows move, Enter opens an example', async () => {
    await page.locator('[data-testid=editor] .cm-content').click();
    await page.keyboard.press('Alt+g');
    await expect(page.getByTestId('gallery').isVisible()).resolves.toBe(true);
    const focused = () => page.evaluate(() => (document.activeElement as HTMLElement | null)?.dataset.file);
    const files = exampleFiles();
    const start = await focused();
    expect(start, 'the example in the editor has the focus').toBe(files.at(-1));
    await page.keyboard.press('Home');
    expect(await focused()).toBe(files[0]);
    await page.keyboard.press('ArrowRight');
    expect(await focused()).toBe(files[1]);
    const before = await generation(page);
    await page.keyboard.press('Enter');
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await editorText(page)).toBe(example(files[1]).replace(/\n$/, '\n'));
    expect(problems).toEqual([]);
  });

  it('asks before replacing changed text, keeps it on cancel, and Ctrl+Z brings it back after replacing', async () => {
    await openFromGallery(page, 'abop-1.24d.lsys');
    await page.waitForFunction(() => document.querySelector('[data-testid=editor] .cm-content')?.textContent?.includes('node rewriting'));
    // The user's change: a comment at the end.
    await page.locator('[data-testid=editor] .cm-content').click();
    await page.keyboard.press('Control+End');
    await page.keyboard.type('\n// my own idea');
    const mine = await editorText(page);
    expect(mine).toContain('// my own idea');

    await openFromGallery(page, 'abop-1.25-bush.lsys');
    const confirm = page.getByTestId('confirm-replace');
    await confirm.waitFor({ state: 'visible' });
    expect(await confirm.textContent()).toContain('ABOP Fig 1.25: a three-dimensional bush');
    await savePage(page, 'gallery-confirm.png');
    await page.getByTestId('confirm-cancel').click();
    await confirm.waitFor({ state: 'hidden' });
    expect(await editorText(page)).toBe(mine);

    // Escape is "keep my text" too.
    await openFromGallery(page, 'abop-1.25-bush.lsys');
    await confirm.waitFor({ state: 'visible' });
    await page.keyboard.press('Escape');
    await confirm.waitFor({ state: 'hidden' });
    expect(await editorText(page)).toBe(mine);

    const before = await generation(page);
    await openFromGallery(page, 'abop-1.25-bush.lsys');
    await page.getByTestId('confirm-replace-button').click();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await editorText(page)).toBe(example('abop-1.25-bush.lsys').replace(/\n$/, '\n'));

    await page.keyboard.press('Control+z');
    await expect.poll(() => editorText(page)).toBe(mine);
    expect(problems).toEqual([]);
  });
});
