import { describe, expect, it } from 'vitest';
import { defineConstants } from '../editor/defines';
import { sliderRanges, type RememberedRange } from './sliders';

describe('sliderRanges', () => {
  it('keeps a default range while its slider moves the value, and renews it when it leaves', () => {
    const remembered = new Map<string, RememberedRange>();
    const [first] = sliderRanges(defineConstants('#define a 18.95'), remembered);
    expect(first).toEqual({ min: 0, max: 37.9, step: 0.01 });
    // Other edits of the text leave it.
    expect(sliderRanges(defineConstants('#define a 18.95\naxiom: F'), remembered)[0]).toEqual(first);
    // Dragged to 30 (the slider writes 30.00 and says so): [0, 60] would be the default now, but
    // the slider keeps [0, 37.9].
    remembered.get('a')!.text = '30.00';
    expect(sliderRanges(defineConstants('#define a 30.00'), remembered)[0]).toEqual(first);
    // Typed 100: outside, so a new default range.
    expect(sliderRanges(defineConstants('#define a 100'), remembered)[0]).toEqual({ min: 0, max: 200, step: 1 });
  });

  it('follows the number the text now has when another one replaces it (issue 50, finding 15)', () => {
    const remembered = new Map<string, RememberedRange>();
    expect(sliderRanges(defineConstants('#define a 1000'), remembered)[0]).toEqual({ min: 0, max: 2000, step: 1 });
    // Pasted over: 0.5 is inside [0, 2000], but the slider must not keep step 1 (it would write 0 or 1).
    expect(sliderRanges(defineConstants('#define a 0.5'), remembered)[0]).toEqual({ min: 0, max: 1, step: 0.01 });
    // A drag that ended at 0.80 keeps [0, 1]; then a pasted 0.25, inside it, gets its own default.
    remembered.get('a')!.text = '0.80';
    expect(sliderRanges(defineConstants('#define a 0.80'), remembered)[0]).toEqual({ min: 0, max: 1, step: 0.01 });
    expect(sliderRanges(defineConstants('#define a 0.25'), remembered)[0]).toEqual({ min: 0, max: 0.5, step: 0.01 });
  });

  it('always uses a written range', () => {
    const remembered = new Map<string, RememberedRange>([['a', { range: { min: 0, max: 1, step: 0.1 }, text: '0.5' }]]);
    expect(sliderRanges(defineConstants('#define a 0.5 // [0, 90]'), remembered)[0]).toMatchObject({ min: 0, max: 90 });
  });
});
