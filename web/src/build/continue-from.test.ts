import { describe, expect, it } from 'vitest';
import { continuable, type KeptBuild } from './continue-from';

const A = 'axiom: A\nA -> AB\n';
const B = 'axiom: A\nA -> BA\n';

/** Kept builds, oldest first, named for the assertions. */
function kept(...entries: Array<KeptBuild & { name: string }>): Array<KeptBuild & { name: string }> {
  return entries;
}

describe('the kept build a new build goes on from', () => {
  const grammar = 5;
  it('is one of the same text and options with fewer steps, the most of them', () => {
    const list = kept(
      { name: 'n3', source: A, options: { iterations: 3, seed: 2 }, grammarIterations: grammar },
      { name: 'n6', source: A, options: { iterations: 6, seed: 2 }, grammarIterations: grammar },
      { name: 'n4', source: A, options: { iterations: 4, seed: 2 }, grammarIterations: grammar },
    );
    expect(continuable(list, A, { iterations: 7, seed: 2 })?.name).toBe('n6');
    expect(continuable(list, A, { iterations: 5, seed: 2 })?.name).toBe('n4');
    expect(continuable(list, A, { seed: 2, iterations: 4 })?.name).toBe('n3');
  });

  it('is none for a step back, the same steps, another text or other options', () => {
    const list = kept({ name: 'n4', source: A, options: { iterations: 4, sides: 8 }, grammarIterations: grammar });
    expect(continuable(list, A, { iterations: 3, sides: 8 })).toBeUndefined();
    expect(continuable(list, A, { iterations: 4, sides: 8 })).toBeUndefined();
    expect(continuable(list, B, { iterations: 6, sides: 8 })).toBeUndefined();
    expect(continuable(list, A, { iterations: 6, sides: 6 })).toBeUndefined();
    expect(continuable(list, A, { iterations: 6, sides: 8, seed: 1 })).toBeUndefined();
    expect(continuable(list, A, { iterations: 6, sides: 8 })?.name).toBe('n4');
  });

  it("reads a missing iterations as the grammar's own, and undefined options as absent", () => {
    const list = kept({ name: 'own', source: A, options: { seed: undefined }, grammarIterations: grammar });
    expect(continuable(list, A, { iterations: grammar + 1 })?.name).toBe('own');
    expect(continuable(list, A, { iterations: grammar })).toBeUndefined();
    const fewer = kept({ name: 'n2', source: A, options: { iterations: 2 }, grammarIterations: grammar });
    expect(continuable(fewer, A, {})?.name).toBe('n2');
  });
});
