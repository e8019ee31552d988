// What the curve editor edits on a line: a table that `meristem import` sampled from a vlab
// function file (its control points in the comment above) is edited by those control points, and
// its samples are written again exactly as the importer writes them; any other line by its own
// points, the ends keeping their x.
import { describe, expect, it } from 'vitest';
import { curveDeclarations } from '../../editor/curve-lines';
import { curveSource, samplesText, sampleY } from './curve-source';

/** Three functions of vlab's 04-paintbrush as `meristem import` writes them (crate/tests/import-corpus). */
const IMPORTED = [
  'axiom: A',
  '// width: the function of width.func, control points 0 0.147913 0.454706 0.186737 0.72 0.278164 1 0.112564; cpfg reads it through 10 samples, as here',
  '#table width 0 0.147913 0.111111111111 0.158671 0.222222222222 0.1714461 0.333333333333 0.1850653 0.444444444444 0.1976611 0.555555555556 0.2064242 0.666666666667 0.2074151 0.777777777778 0.1956357 0.888888888889 0.1656137 1 0.112564',
  '// turn: the function of turn.func, control points 0 -0.585811 0.207103 -0.470859 0.207103 0.515172 0.74364 0.496447 0.74364 -0.691429 1 -0.632283; cpfg reads it through 10 samples, as here',
  '#table turn 0 -0.585811 0.111111111111 -0.4591392 0.222222222222 -0.05785818 0.333333333333 0.3440821 0.444444444444 0.4370529 0.555555555556 0.3933849 0.666666666667 0.1568499 0.777777777778 -0.4003809 0.888888888889 -0.609795 1 -0.632283',
  '// torque: the function of torque.func, control points 0 0.005608 0.4128 0.000808 0.7296 0.000808 1 0.000808; cpfg reads it through 10 samples, as here',
  '#table torque 0 0.005608 0.111111111111 0.004405574 0.222222222222 0.003384114 0.333333333333 0.002544726 0.444444444444 0.001885496 0.555555555556 0.001400173 0.666666666667 0.001076412 0.777777777778 0.0008934899 0.888888888889 0.0008194861 1 0.000808',
  '',
].join('\n');

/** `text` with `changes` made (offsets in `text`, not overlapping). */
function apply(text: string, changes: { from: number; to: number; insert: string }[]): string {
  return [...changes].sort((a, b) => b.from - a.from).reduce((t, c) => t.slice(0, c.from) + c.insert + t.slice(c.to), text);
}

describe("a table sampled from a function file's control points", () => {
  it('is edited by its control points, and its samples are the importer’s to the digit', () => {
    for (const declaration of curveDeclarations(IMPORTED)) {
      const source = curveSource(IMPORTED, declaration);
      expect(source.kind).toBe('curve');
      const table = IMPORTED.slice(declaration.numbers[0].from, declaration.numbers[declaration.numbers.length - 1].to);
      expect(samplesText(source.points.map((p) => p.value), 10), declaration.name).toBe(table);
    }
    const width = curveSource(IMPORTED, curveDeclarations(IMPORTED)[0]);
    expect(width.description).toContain('4 control points');
    expect(width.points.map((p) => p.value)).toEqual([[0, 0.147913], [0.454706, 0.186737], [0.72, 0.278164], [1, 0.112564]]);
  });

  it('rewrites the comment’s control points and the table’s samples at once', () => {
    const [width] = curveDeclarations(IMPORTED);
    const source = curveSource(IMPORTED, width);
    const spans = source.spansOf(2);
    const moved = apply(IMPORTED, spans.map((s, k) => ({ ...s, insert: source.insertsOf(2, ['0.72', '0.5'])[k] })));
    const lines = moved.split('\n');
    expect(lines[1]).toBe('// width: the function of width.func, control points 0 0.147913 0.454706 0.186737 0.72 0.5 1 0.112564; cpfg reads it through 10 samples, as here');
    const again = curveSource(moved, curveDeclarations(moved)[0]);
    expect(again.points[2].value).toEqual([0.72, 0.5]);
    expect(again.declaration.numbers.length).toBe(8);
    const samples = curveDeclarations(moved)[0].numbers.map((n) => n.value);
    expect(samples.length).toBe(20);
    expect(samples[0]).toBe(0);
    expect(samples[13]).toBeGreaterThan(0.3); // the function at x = 2/3, pulled up towards 0.5
    expect(lines.slice(3).join('\n')).toBe(IMPORTED.split('\n').slice(3).join('\n'));
  });

  it('adds and removes a control point, the samples following', () => {
    const [width] = curveDeclarations(IMPORTED);
    const added = apply(IMPORTED, curveSource(IMPORTED, width).addChanges(IMPORTED, 3, ['0.9', '0.2']));
    expect(added.split('\n')[1]).toContain('control points 0 0.147913 0.454706 0.186737 0.72 0.278164 0.9 0.2 1 0.112564;');
    const source = curveSource(added, curveDeclarations(added)[0]);
    expect(source.points.length).toBe(5);
    const removed = apply(added, source.removeChanges(3));
    expect(removed).toBe(IMPORTED);
  });

  it('is not taken for another table’s, nor when the samples do not match the count', () => {
    const renamed = IMPORTED.replace('#table width', '#table girth');
    expect(curveSource(renamed, curveDeclarations(renamed)[0]).kind).toBe('table');
    const fewer = IMPORTED.replace(' 1 0.112564\n', '\n');
    expect(curveSource(fewer, curveDeclarations(fewer)[0]).kind).toBe('table');
    expect([sampleY(-0), sampleY(0.00089348991), sampleY(-0.4003809123), sampleY(12345.678)]).toEqual(['0', '0.0008934899', '-0.4003809', '12345.68']);
  });
});

describe("a line's own points", () => {
  it('move as x and y, the ends their y alone', () => {
    const text = '#curve c 0 0, 0.3 0.1, 0.7 0.9, 1 1\n';
    const source = curveSource(text, curveDeclarations(text)[0]);
    expect(source.kind).toBe('curve');
    expect(source.spansOf(1).map((s) => text.slice(s.from, s.to))).toEqual(['0.3', '0.1']);
    expect(source.spansOf(0).map((s) => text.slice(s.from, s.to))).toEqual(['0']);
    expect(source.insertsOf(0, ['0', '0.25'])).toEqual(['0.25']);
    expect(source.spansOf(3).map((s) => text.slice(s.from, s.to))).toEqual(['1']);
  });
});
