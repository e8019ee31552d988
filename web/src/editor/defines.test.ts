import { describe, expect, it } from 'vitest';
import { decimalsForStep, defaultRange, defaultStep, defineConstants, defineNames, formatNumber } from './defines';

describe('defineConstants', () => {
  it('finds plain-number #defines with the offsets of their numbers', () => {
    const text = '#tropism 0 -1 0 0.22\n#define d1 94.74\n#define a 18.95 // [0, 90]\n#define q c - p\naxiom: A';
    const constants = defineConstants(text);
    expect(constants.map((c) => c.name)).toEqual(['d1', 'a']);
    const [d1, a] = constants;
    expect(text.slice(d1.from, d1.to)).toBe('94.74');
    expect(text.slice(a.from, a.to)).toBe('18.95');
    expect(a).toMatchObject({ value: 18.95, line: 3, min: 0, max: 90, step: 0.01, ranged: true });
    expect(d1).toMatchObject({ value: 94.74, min: 0, max: 189.48, step: 0.01, ranged: false });
  });

  it('reads a step from the comment and tolerates spaces, indentation, CRLF and negatives', () => {
    const text = '  #define  t   -2.5   // tilt [ -45 , 45 , 0.5 ] degrees\r\n#define z 0\r\n';
    const [t, z] = defineConstants(text);
    expect(t).toMatchObject({ name: 't', value: -2.5, min: -45, max: 45, step: 0.5, ranged: true });
    expect(text.slice(t.from, t.to)).toBe('-2.5');
    expect(z).toMatchObject({ value: 0, min: -10, max: 10, step: 1, line: 2 });
    expect(text.slice(z.from, z.to)).toBe('0');
  });

  it('ignores a reversed range and widens a range that does not hold the value', () => {
    expect(defineConstants('#define a 5 // [10, 0]')[0]).toMatchObject({ min: 0, max: 10, ranged: false });
    expect(defineConstants('#define a 120 // [0, 90]')[0]).toMatchObject({ min: 0, max: 120, ranged: true });
  });

  it('skips expressions and defines inside other text', () => {
    expect(defineConstants('#define h (p*q)^0.5\n#define r 1e3\n// #define x 1\nX -> F')).toEqual([]);
  });
});

describe('slider ranges and steps', () => {
  it('defaults to [0, 2·value], [2·value, 0] or [-10, 10]', () => {
    expect(defaultRange(45)).toEqual([0, 90]);
    expect(defaultRange(-3)).toEqual([-6, 0]);
    expect(defaultRange(0)).toEqual([-10, 10]);
  });

  it('steps as finely as the number was written, with at least 20 positions', () => {
    expect(defaultStep('45', 0, 90)).toBe(1);
    expect(defaultStep('18.95', 0, 37.9)).toBe(0.01);
    expect(defaultStep('1', 0, 2)).toBeCloseTo(0.1);
    expect(defaultStep('137.5', 0, 275)).toBeCloseTo(0.1);
    expect(defaultStep('1.070', 0, 2.14)).toBeCloseTo(0.001);
  });
});

describe('formatNumber', () => {
  it('writes a value rounded to the step with the step’s decimals', () => {
    expect(formatNumber(18.951234, 0.01)).toBe('18.95');
    expect(formatNumber(45.4, 1)).toBe('45');
    expect(formatNumber(2.25, 0.5)).toBe('2.5');
    expect(formatNumber(1.1, 0.001)).toBe('1.100');
    expect(formatNumber(-0.0001, 0.01)).toBe('0.00');
    expect(formatNumber(0.1 + 0.2, 0.1)).toBe('0.3');
    expect(decimalsForStep(0.25)).toBe(2);
  });
});

describe('defineNames', () => {
  it('lists every #define, expressions included, without comments', () => {
    expect(defineNames('#define c 1\n#define q c - p // the rest\nA -> B')).toEqual([
      { name: 'c', value: '1', line: 1 },
      { name: 'q', value: 'c - p', line: 2 },
    ]);
  });
});
