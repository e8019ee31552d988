// End-to-end: the Growth panel (issue 8, seed 002's particle attributes) writes its directives into
// the text, one undoable change each, and the plant follows.
import { describe, expect, it } from 'vitest';
import { editorText, generation, nextBuild, savePage, shownStats } from './studio-page';
import { page, problems, useStudio } from './session';

useStudio();

describe('the Growth panel', () => {
  it('switches lifetime on and off, edits its values, and the plant follows', async () => {
    const plain = (await shownStats(page))!.segments;
    await page.getByTestId('growth').locator('summary').click();
    expect(await page.getByTestId('growth-lifetime-mb').isDisabled()).toBe(true);

    let before = await generation(page);
    await page.getByTestId('growth-lifetime').check();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await editorText(page)).toContain('\n#lifetime 34 32\naxiom: X');
    const living = (await shownStats(page))!.segments;
    expect(living, 'apices stop growing: fewer segments').toBeLessThan(plain);

    before = await generation(page);
    await page.getByTestId('growth-lifetime-mb').fill('2');
    await page.getByTestId('growth-lifetime-vb').fill('0');
    await page.getByTestId('growth-lifetime-vb').press('Tab');
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await editorText(page)).toContain('\n#lifetime 2 0\n');
    expect((await shownStats(page))!.segments).toBeLessThan(living);

    // What the core would not read is marked, and not written.
    await page.getByTestId('growth-lifetime-mb').fill('two apices');
    await page.getByTestId('growth-lifetime-mb').press('Tab');
    expect(await page.getByTestId('growth-lifetime-mb').getAttribute('aria-invalid')).toBe('true');
    expect(await editorText(page)).toContain('\n#lifetime 2 0\n');
    await savePage(page, 'growth-panel.png');

    before = await generation(page);
    await page.getByTestId('growth-lifetime').uncheck();
    expect(await nextBuild(page, before)).toBe('ok');
    expect(await editorText(page)).not.toContain('#lifetime');
    expect((await shownStats(page))!.segments).toBe(plain);
    expect(problems).toEqual([]);
  });

  it('sets the sun and the season together with gravity', async () => {
    let before = await generation(page);
    await page.getByTestId('growth-sun').check();
    expect(await nextBuild(page, before)).toBe('ok');
    before = await generation(page);
    await page.getByTestId('growth-sun-season').selectOption('winter');
    expect(await nextBuild(page, before)).toBe('ok');
    before = await generation(page);
    await page.getByTestId('growth-gravity').check();
    expect(await nextBuild(page, before)).toBe('ok');
    const text = await editorText(page);
    expect(text).toContain('#sun 38 winter 2\n#gravity 5 3\naxiom: X');
    // Typing in the editor updates the panel.
    await page.locator('[data-testid=editor] .cm-line', { hasText: '#gravity' }).click();
    await page.keyboard.press('End');
    await page.keyboard.type('0'); // #gravity 5 30
    await expect.poll(() => page.getByTestId('growth-gravity-variation').inputValue()).toBe('30');
    expect(problems).toEqual([]);
  });

  it('labels each field in plain words beside the paper’s name, and says in a sentence what each switch and field does', async () => {
    // The field's <label>: its words and the paper's name, its tooltip.
    const field = (testid: string) =>
      page.getByTestId(testid).evaluate((input) => {
        const label = input.closest('label');
        return { text: label?.querySelector('.growth-field-label')?.textContent, title: label?.title ?? '' };
      });
    expect(await field('growth-lifetime-mb')).toEqual({ text: 'at least MB', title: expect.stringMatching(/^MB: How many branch tips keep growing at each step, at least/) });
    expect((await field('growth-lifetime-vb')).text).toBe('+ random VB');
    expect((await field('growth-lifetime-pu')).text).toBe('upper third pu');
    expect(await field('growth-speed-pfu')).toEqual({ text: 'upper third PFu', title: expect.stringMatching(/positional factor\)\. Default 2\.$/) });
    expect((await field('growth-speed-sm')).text).toBe('extra rewritings SM');
    expect((await field('growth-shape-vr')).text).toBe('± random VR');
    expect((await field('growth-sun-season')).text).toBe('season');
    expect(await page.getByTestId('growth-lifetime-mb').getAttribute('aria-label')).toBe('Lifetime of tips: at least (MB)');
    const toggle = page.getByTestId('growth-lifetime');
    expect(await toggle.getAttribute('title')).toMatch(/^#lifetime MB VB \[pu pm pl\] — Growth: only some branch tips/);
    // Every switch and every field says what it does, in a sentence.
    const titles = await page.getByTestId('growth-rows').evaluate((rows) =>
      [...rows.querySelectorAll<HTMLElement>('.growth-toggle, .growth-field')].map((element) => element.title),
    );
    expect(titles.length).toBeGreaterThan(25);
    expect(titles.filter((title) => !/^\S.{20,}[.)]$/.test(title))).toEqual([]);
    await page.getByTestId('growth-rows').scrollIntoViewIfNeeded();
    await savePage(page, 'growth-labels.png');
    expect(problems).toEqual([]);
  });
});
