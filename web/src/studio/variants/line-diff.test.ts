import { describe, expect, it } from 'vitest';
import { lineDiff, MAX_DIFF_CELLS } from './line-diff';

const PLANT = '#angle 20\n#define a 20\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF\n';

describe('the line diff of a variant against the first', () => {
  it('is empty for the same text, whatever its line endings', () => {
    expect(lineDiff(PLANT, PLANT)).toEqual([]);
    expect(lineDiff(PLANT, PLANT.replace(/\n/g, '\r\n'))).toEqual([]);
    expect(lineDiff(PLANT, PLANT.trimEnd()), 'a last newline is no line').toEqual([]);
  });

  it('says a changed line with its numbers in both texts', () => {
    expect(lineDiff(PLANT, PLANT.replace('#define a 20', '#define a 25'))).toEqual([
      { kind: 'changed', before: 2, after: 2, old: '#define a 20', new: '#define a 25' },
    ]);
  });

  it('says added and removed lines where they are', () => {
    const other = PLANT.replace('axiom: X\n', 'axiom: X\n#seed 4\n').replace('F -> FF\n', '');
    expect(lineDiff(PLANT, other)).toEqual([
      { kind: 'added', after: 4, new: '#seed 4' },
      { kind: 'removed', before: 5, old: 'F -> FF' },
    ]);
  });

  it('pairs a run of removed lines with the added run after it, the rest added', () => {
    const first = 'a\nb\nc\nz';
    const other = 'a\nB\nC\nD\nz';
    expect(lineDiff(first, other)).toEqual([
      { kind: 'changed', before: 2, after: 2, old: 'b', new: 'B' },
      { kind: 'changed', before: 3, after: 3, old: 'c', new: 'C' },
      { kind: 'added', after: 4, new: 'D' },
    ]);
  });

  it('finds the common lines between differences (not only at the ends)', () => {
    const diff = lineDiff('1\n2\n3\n4\n5\n6', '1\nx\n3\n4\ny\n6');
    expect(diff.map((d) => [d.kind, d.before, d.after])).toEqual([
      ['changed', 2, 2],
      ['changed', 5, 5],
    ]);
  });

  it('compares a text with an empty one', () => {
    expect(lineDiff('', 'a\nb')).toEqual([
      { kind: 'changed', before: 1, after: 1, old: '', new: 'a' },
      { kind: 'added', after: 2, new: 'b' },
    ]);
  });

  it('gives up comparing line by line past its budget, quickly, with every line said', () => {
    const lines = Math.ceil(Math.sqrt(MAX_DIFF_CELLS)) + 10;
    const first = Array.from({ length: lines }, (_, i) => `a${i}`).join('\n');
    const other = Array.from({ length: lines }, (_, i) => `b${i}`).join('\n');
    const started = performance.now();
    const diff = lineDiff(first, other);
    expect(performance.now() - started).toBeLessThan(2000);
    expect(diff).toHaveLength(lines);
    expect(diff.every((d) => d.kind === 'changed')).toBe(true);
  });
});
