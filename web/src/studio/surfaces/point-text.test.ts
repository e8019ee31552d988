import { describe, expect, it } from 'vitest';
import { coordinateText, copiesOf, movePoints, patchLines, pointText, replaceSpans } from './point-text';

const apply = (text: string, changes: { from: number; to: number; insert: string }[]) =>
  [...changes].sort((a, b) => b.from - a.from).reduce((t, c) => t.slice(0, c.from) + c.insert + t.slice(c.to), text);

describe('the text of a control point', () => {
  it('rounds to four decimals, drops trailing zeros and never writes -0', () => {
    expect(coordinateText(0.123456)).toBe('0.1235');
    expect(coordinateText(2.5)).toBe('2.5');
    expect(coordinateText(-0.00001)).toBe('0');
    expect(coordinateText(-3)).toBe('-3');
    expect(coordinateText(1e-4)).toBe('0.0001');
    expect(coordinateText(Number.NaN)).toBe('0');
    expect(coordinateText(1e30)).toBe('1000000'); // a drag toward the horizon stops at a number the core reads
    expect(pointText([0.1, -0.25, 1 / 3])).toBe('0.1 -0.25 0.3333');
  });

  it('rewrites each written copy of a point and gives the spans after the change', () => {
    const text = '#patch A 0 0 0, 1.5 2 3, 0 0 0';
    // The first and the third point (two copies of one point), from the first number to the last.
    const spans = [
      { from: 9, to: 14 },
      { from: 25, to: 30 },
    ];
    const { changes, spans: after } = movePoints(spans, [0.25, -1, 10]);
    const moved = apply(text, changes);
    expect(moved).toBe('#patch A 0.25 -1 10, 1.5 2 3, 0.25 -1 10');
    expect(after.map((s) => moved.slice(s.from, s.to))).toEqual(['0.25 -1 10', '0.25 -1 10']);
    // In any order of the spans.
    const reversed = movePoints([spans[1], spans[0]], [7, 7, 7]);
    const again = apply(text, reversed.changes);
    expect(reversed.spans.map((s) => again.slice(s.from, s.to))).toEqual(['7 7 7', '7 7 7']);
    expect(replaceSpans(spans, ['a', 'b']).changes.map((c) => c.insert)).toEqual(['a', 'b']);
  });

  it('finds the copies of a point where patches meet', () => {
    const w = (value: [number, number, number]) => ({ patch: 0, index: 0, value, from: 0, to: 0 });
    expect(copiesOf([w([0, 1, 0]), w([0.5, 1, 0]), w([0, 1, 0])], 0)).toEqual([0, 2]);
    expect(copiesOf([w([0, 1, 0])], 3)).toEqual([]);
  });

  it('writes a library shape out as patch lines of 16 points', () => {
    const net = Array.from({ length: 32 }, (_, k): [number, number, number] => [k, 0.5, 0]);
    const lines = patchLines('#patch', 'P', net);
    expect(lines).toHaveLength(2);
    expect(lines[0].startsWith('#patch P 0 0.5 0, 1 0.5 0,')).toBe(true);
    expect(lines[1].split(',')).toHaveLength(16);
  });
});
