// End-to-end: bark and leaf textures in the view. The shipped images load (relative to the page,
// no console errors, no failed requests), the plant's pixels differ with textures on and off, and
// a screenshot of a leafy plant with thick branches lands in test-results/.
import { describe, expect, it } from 'vitest';
import { changedShare, foregroundShare } from './pictures';
import { canvasPicture, openExample, savePage } from './studio-page';
import { page, problems, useStudio } from './session';

useStudio();

describe('textures', () => {
  it('loads the bark and leaf textures and shows them on the plant, with a toggle', async () => {
    expect(await openExample(page, 'abop-1.25-bush.lsys')).toBe('ok');
    const viewport = page.getByTestId('viewport');
    expect(await page.getByTestId('textures').getAttribute('aria-pressed')).toBe('true');
    // The images are served from the page's own folder (a failed request would be in `problems`).
    const served = await page.evaluate(async () => {
      const urls = ['textures/bark.png', 'textures/leaf.png'].map((u) => new URL(u, document.baseURI).href);
      return Promise.all(urls.map(async (u) => (await fetch(u)).headers.get('content-type')));
    });
    expect(served).toEqual(['image/png', 'image/png']);
    await expect.poll(() => viewport.getAttribute('data-textures')).toBe('true');
    expect(await viewport.getAttribute('data-textures-error')).toBeNull();
    const textured = await canvasPicture(page, 'textures-on-canvas.png');
    await savePage(page, 'textures-on.png');
    expect(foregroundShare(textured)).toBeGreaterThan(0.01);
    await page.getByTestId('textures').click();
    expect(await page.getByTestId('textures').getAttribute('aria-pressed')).toBe('false');
    expect(await viewport.getAttribute('data-textures')).toBe('false');
    const plain = await canvasPicture(page, 'textures-off-canvas.png');
    expect(changedShare(textured, plain), 'textured pixels differ from plain ones').toBeGreaterThan(0.02);
    await page.getByTestId('textures').click();
    expect(await viewport.getAttribute('data-textures')).toBe('true');
    expect(problems).toEqual([]);
  });

  it('shows bark on thick branches (a close-up screenshot of smooth-tree)', async () => {
    expect(await openExample(page, 'smooth-tree.lsys')).toBe('ok');
    const box = (await page.getByTestId('viewport').boundingBox())!;
    await page.mouse.move(box.x + box.width / 2, box.y + box.height * 0.7);
    for (let k = 0; k < 6; k++) await page.mouse.wheel(0, -300);
    await page.waitForTimeout(300);
    const close = await canvasPicture(page, 'textures-smooth-tree-canvas.png');
    expect(foregroundShare(close)).toBeGreaterThan(0.05);
    expect(problems).toEqual([]);
  });
});
