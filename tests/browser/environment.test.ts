// End-to-end: the environment (issue 47; docs/LANGUAGE.md, "Environment") in the studio. A stand
// of nine plants typed into the editor is drawn as nine plants; a link to it opened as the first
// plant is left by the first plant's core (no environment in its first load) to the studio core,
// which plants all nine; a shoot pruned by a box stops where its `?E` finds the box.
// Screenshots land in test-results/ for a person to look at.
import { deflateRawSync } from 'node:zlib';
import { describe, expect, inject, it } from 'vitest';
import { foregroundShare } from './pictures';
import { canvasPicture, pasteText, savePage } from './studio-page';
import { browser, page, problems, useStudio } from './session';

useStudio();

// Nine plants of 3 segments each (a trunk and two branches), 3 apart on a grid.
const STAND = `#stand grid 3 3 spacing 3
#angle 30
#iterations 1
axiom: A
A -> F[+F][-F]
`;

// A shoot that grows a segment a step until its ?E stands inside the box (y from 2.5): 3 segments.
const SHOOT = `#environment obstacle box min -1 2.5 -1 max 1 10 1
#iterations 8
axiom: A ?E(1, 0)
A > ?E(f, d) : f == 1 -> F A
A > ?E(f, d) : f == 0 -> B
`;

const segments = () => window.__meristem?.lastStats?.segments ?? 0;

describe('the environment', () => {
  it('draws a stand of nine plants', async () => {
    expect(await pasteText(page, STAND)).toBe('ok');
    await page.waitForFunction((n) => (window.__meristem?.lastStats?.segments ?? 0) === n, 27, { timeout: 60_000 });
    const picture = await canvasPicture(page, 'environment-stand-canvas.png');
    await savePage(page, 'environment-stand.png');
    expect(foregroundShare(picture)).toBeGreaterThan(0.01);
    expect(problems).toEqual([]);
  }, 90_000);

  it('stops a shoot at the box its ?E asks about', async () => {
    expect(await pasteText(page, SHOOT)).toBe('ok');
    await page.waitForFunction((n) => (window.__meristem?.lastStats?.segments ?? 0) === n, 3, { timeout: 60_000 });
    expect(await page.evaluate(segments)).toBe(3);
    expect(problems).toEqual([]);
  }, 90_000);

  it("opens a link to a stand as the first plant: the studio core plants all nine", async () => {
    const fragment = `#s=1.${Buffer.from(deflateRawSync(Buffer.from(JSON.stringify({ v: 1, text: STAND })))).toString('base64url')}`;
    const fresh = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    const seen: string[] = [];
    fresh.on('pageerror', (e) => seen.push(e.message));
    await fresh.goto(inject('studioUrl') + fragment);
    await fresh.waitForFunction((n) => (window.__meristem?.lastStats?.segments ?? 0) === n, 27, { timeout: 60_000 });
    await canvasPicture(fresh, 'environment-stand-link-canvas.png');
    expect(seen).toEqual([]);
    await fresh.close();
  }, 90_000);
});
