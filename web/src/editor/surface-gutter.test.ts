import { Text } from '@codemirror/state';
import { describe, expect, it } from 'vitest';
import { markers } from './surface-gutter';

describe('the gutter’s markers of surfaces and curves', () => {
  it('mark each declaring line where it starts, reading the lines in one pass (a text of 100,000 lines: issue 50)', () => {
    const lines = ['#surface L 0 0 1', ...Array.from({ length: 20_000 }, () => '?'), '  #curve width 0 0 1 1', 'F', '#patch P', '# surface Q'];
    const doc = Text.of(lines);
    const expected = [1, 20_002, 20_004].map((n) => doc.line(n).from);
    let lookups = 0;
    const { line, lineAt } = doc;
    doc.line = (n) => (lookups++, line.call(doc, n));
    doc.lineAt = (pos) => (lookups++, lineAt.call(doc, pos));
    const found: { from: number; what: string; name: string }[] = [];
    const set = markers(doc);
    for (let cursor = set.iter(); cursor.value; cursor.next()) {
      const { what, name } = (cursor.value as unknown as { target: { what: string; name: string } }).target;
      found.push({ from: cursor.from, what, name });
    }
    expect(found).toEqual([
      { from: expected[0], what: 'surface', name: 'L' },
      { from: expected[1], what: 'curve', name: 'width' },
      { from: expected[2], what: 'surface', name: 'P' },
    ]);
    expect(lookups, 'lines looked up by number or position').toBe(0);
  });
});
