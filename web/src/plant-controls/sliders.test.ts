import { describe, expect, it } from 'vitest';
import { defineConstants } from '../editor/defines';
import { sliderRanges, type SliderRange } from './sliders';

describe('sliderRanges', () => {
  it('keeps a default range while the value moves inside it, and renews it when it leaves', () => {
    const remembered = new Map<string, SliderRange>();
    const [first] = sliderRanges(defineConstants('#define a 18.95'), remembered);
    expect(first).toEqual({ min: 0, max: 37.9, step: 0.01 });
    // Dragged to 30: [0, 60] would be the default now, but the slider keeps [0, 37.9].
    expect(sliderRanges(defineConstants('#define a 30.00'), remembered)[0]).toEqual(first);
    // Typed 100: outside, so a new default range.
    expect(sliderRanges(defineConstants('#define a 100'), remembered)[0]).toEqual({ min: 0, max: 200, step: 1 });
  });

  it('always uses a written range', () => {
    const remembered = new Map<string, SliderRange>([['a', { min: 0, max: 1, step: 0.1 }]]);
    expect(sliderRanges(defineConstants('#define a 0.5 // [0, 90]'), remembered)[0]).toMatchObject({ min: 0, max: 90 });
  });
});
