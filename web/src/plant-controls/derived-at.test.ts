import { describe, expect, it } from 'vitest';
import { derivedBuildOptions, derivedTime } from './derived-at';

describe('a plant derived at the timeline’s t', () => {
  it('derives a timed grammar at t, a stepwise one at its whole steps ⌊t⌋', () => {
    expect(derivedTime(2.5, false)).toBe(2.5);
    expect(derivedTime(2.5, true)).toBe(2);
    expect(derivedTime(null, true)).toBeNull();
  });

  it('asks a timed grammar’s build for the time, a stepwise one’s for its steps without growth arrays', () => {
    expect(derivedBuildOptions(2.5, false, true)).toEqual({ growth: true, time: 2.5 });
    expect(derivedBuildOptions(2, true, true)).toEqual({ iterations: 2 });
    expect(derivedBuildOptions(null, true, true), 'at its own iterations: grown on the GPU as any plant').toEqual({ growth: true });
    expect(derivedBuildOptions(null, false, false)).toEqual({});
  });
});
