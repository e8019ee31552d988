import { describe, expect, it } from 'vitest';
import { defineVariants, numericConstants, parseValues, seedVariants, valuesAround } from './variant-making';

const PLANT = '#define angle 20 // [0, 90]\n#define q angle * 2\n#angle angle\naxiom: X\nX -> F[+X]F[-X]+X\n';

describe('making variants', () => {
  it('reads a list of values as a lecturer types it', () => {
    expect(parseValues('20, 25, 30')).toEqual([20, 25, 30]);
    expect(parseValues(' 20 25;30 ')).toEqual([20, 25, 30]);
    expect(parseValues('-1.5, .5, 1e2')).toEqual([-1.5, 0.5, 100]);
    expect(parseValues('')).toBe('Type the values, e.g. 20, 25, 30.');
    expect(parseValues('20, abc')).toBe('“abc” is not a number.');
    expect(parseValues('Infinity')).toBe('“Infinity” is not a number.');
    expect(parseValues('1 2 3 4 5 6 7')).toBe('At most 6 values (7 given).');
  });

  it('lists the constants whose value is a number', () => {
    expect(numericConstants(PLANT)).toEqual([{ name: 'angle', value: 20 }]);
    expect(numericConstants('#define a 1\n#define a 2\n#define b -3')).toEqual([
      { name: 'a', value: 1 },
      { name: 'b', value: -3 },
    ]);
    expect(valuesAround(20)).toEqual([15, 20, 25]);
    expect(valuesAround(0)).toEqual([-1, 0, 1]);
  });

  it('sets one constant to each value, the rest of the text as it is', () => {
    const made = defineVariants(PLANT, 'angle', [20, 25, 30]);
    expect(typeof made).not.toBe('string');
    if (typeof made === 'string') return;
    expect(made.map((v) => v.caption)).toEqual(['angle = 20', 'angle = 25', 'angle = 30']);
    expect(made[1].text).toBe(PLANT.replace('#define angle 20', '#define angle 25'));
    expect(made[0].seed).toBeUndefined();
    expect(defineVariants(PLANT, 'q', [1, 2])).toBe('The grammar has no constant q with a number for its value.');
  });

  it('grows one text with several seeds', () => {
    expect(seedVariants(PLANT, [1, 2])).toEqual([
      { text: PLANT, seed: 1, caption: 'seed 1' },
      { text: PLANT, seed: 2, caption: 'seed 2' },
    ]);
    expect(seedVariants(PLANT, [1, 2.5])).toBe('A seed is a whole number from 0 (2.5 is not).');
  });
});
