import { describe, expect, it } from 'vitest';
import { growthKey, isLastStep } from './view-following';

const result = (iterations: number | undefined, grammarIterations: number, seed?: number) =>
  ({ source: 'axiom: F', options: { iterations, seed, sides: 6 }, build: { grammarIterations } }) as unknown as Parameters<typeof isLastStep>[0] &
    Parameters<typeof growthKey>[0];

describe('what Play frames', () => {
  it("keys a plant by its text and options, whatever the iterations", () => {
    expect(growthKey(result(2, 7))).toBe(growthKey(result(undefined, 7)));
    expect(growthKey(result(2, 7, 1))).not.toBe(growthKey(result(2, 7, 2)));
  });

  it("knows the grammar's last step: its own #iterations, asked or not", () => {
    expect(isLastStep(result(undefined, 7))).toBe(true);
    expect(isLastStep(result(7, 7))).toBe(true);
    expect(isLastStep(result(3, 7))).toBe(false);
    expect(isLastStep(result(9, 7))).toBe(false);
  });
});
