import { describe, expect, it } from 'vitest';
import { DEFAULT_SHARE, MAX_SHARE, MIN_SHARE, clampShare, shareAfterKey } from './splitter';

describe('splitter', () => {
  it('keeps the editor share within bounds', () => {
    expect(clampShare(0.5)).toBe(0.5);
    expect(clampShare(0)).toBe(MIN_SHARE);
    expect(clampShare(2)).toBe(MAX_SHARE);
    expect(clampShare(Number.NaN)).toBe(DEFAULT_SHARE);
  });

  it('moves with the keys of the window-splitter pattern', () => {
    expect(shareAfterKey(0.4, 'ArrowRight')).toBeCloseTo(0.42);
    expect(shareAfterKey(0.4, 'ArrowLeft')).toBeCloseTo(0.38);
    expect(shareAfterKey(0.4, 'PageUp')).toBeCloseTo(0.5);
    expect(shareAfterKey(0.16, 'PageDown')).toBe(MIN_SHARE);
    expect(shareAfterKey(0.4, 'Home')).toBe(MIN_SHARE);
    expect(shareAfterKey(0.4, 'End')).toBe(MAX_SHARE);
    expect(shareAfterKey(0.7, 'Enter')).toBe(DEFAULT_SHARE);
    expect(shareAfterKey(0.4, 'a')).toBeUndefined();
  });
});
