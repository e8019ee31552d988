import { describe, expect, it } from 'vitest';
import { growthLabel } from './timeline-bar';

describe('the timeline’s label', () => {
  it('says the time and the step growing (⌈t⌉), or the whole plant at the end', () => {
    expect(growthLabel(2.5, 4)).toBe('t 2.50 of 4 · step 3 growing');
    expect(growthLabel(2, 4)).toBe('t 2.00 of 4 · step 2');
    expect(growthLabel(0.01, 4)).toBe('t 0.01 of 4 · step 1 growing');
    expect(growthLabel(4, 4)).toBe('t 4.00 of 4 · whole plant');
    expect(growthLabel(9, 4)).toBe('t 4.00 of 4 · whole plant');
    expect(growthLabel(1.5, null)).toBe('t 1.50');
  });
});
