import { describe, expect, it } from 'vitest';
import { growthKey } from './view-following';

const result = (iterations: number | undefined, grammarIterations: number, seed?: number) =>
  ({ source: 'axiom: F', options: { iterations, seed, sides: 6 }, build: { grammarIterations } }) as unknown as Parameters<typeof growthKey>[0];

describe('what Stages grows', () => {
  it("keys a plant by its text and options, whatever the iterations", () => {
    expect(growthKey(result(2, 7))).toBe(growthKey(result(undefined, 7)));
    expect(growthKey(result(2, 7, 1))).not.toBe(growthKey(result(2, 7, 2)));
  });
});
