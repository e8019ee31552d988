// The text of a curve function's points: read as the core's parser reads them, rewritten in the
// line's own style (its separators, its decimals), points added and removed with the line's
// separators, and a drag of a point through a real CodeMirror history: one undo step restores the
// whole curve.
import { history, undo, undoDepth } from '@codemirror/commands';
import { EditorState, type Transaction } from '@codemirror/state';
import { describe, expect, it } from 'vitest';
import { curveDeclarationOn, curveDeclarations, type CurveDeclaration } from '../../editor/curve-lines';
import { curveNameOf } from '../../editor/surface-lines';
import type { TextChange } from '../../editor/growth-directives';
import { rangesTransaction } from '../../editor/grammar-editor';
import { PointEdit, type PointTextEditor } from '../surfaces/point-edit';
import { addPointChange, decimalsFor, fixedDecimals, numberText, removePointChange, writtenPoints } from './curve-text';

/** The one declaration of `text`. */
function only(text: string): CurveDeclaration {
  const found = curveDeclarations(text);
  expect(found.length).toBe(1);
  return found[0];
}

/** `text` with `change` made. */
function apply(text: string, change: TextChange): string {
  return text.slice(0, change.from) + change.insert + text.slice(change.to);
}

describe('a curve function as written', () => {
  it('is a name, then numbers separated by spaces or commas, up to a comment', () => {
    const text = 'axiom: F\n  #curve leaf 0 0, 0.3 0.1,0.7 .9, 1 1e0 // the leaf\n#table t -1 +2 3 4\n';
    const [leaf, t] = curveDeclarations(text);
    expect([leaf.kind, leaf.name, leaf.directive, leaf.problem]).toEqual(['curve', 'leaf', '#curve', null]);
    expect(leaf.numbers.map((n) => n.value)).toEqual([0, 0, 0.3, 0.1, 0.7, 0.9, 1, 1]);
    expect(leaf.numbers.map((n) => text.slice(n.from, n.to))).toEqual(['0', '0', '0.3', '0.1', '0.7', '.9', '1', '1e0']);
    expect(text.slice(leaf.argsTo)).toMatch(/^\/\/ the leaf/);
    expect(writtenPoints(leaf).map((p) => p.value)).toEqual([[0, 0], [0.3, 0.1], [0.7, 0.9], [1, 1]]);
    expect([t.kind, t.name, t.numbers.map((n) => n.value)]).toEqual(['table', 't', [-1, 2, 3, 4]]);
    expect(curveNameOf('#table t 0 0 1 1')).toBe('t');
    expect(curveNameOf('#define t 3')).toBeNull();
    expect(curveNameOf('// #curve c 0 0')).toBeNull();
  });

  it('says why a line cannot be edited as points', () => {
    expect(curveDeclarationOn('#curve c 0 0 1 x', 0)?.problem).toBe("'x' is not a number");
    expect(curveDeclarationOn('#table t 0 0 1', 0)?.problem).toBe('its 3 numbers are not pairs x y');
    expect(curveDeclarationOn('#table t 0 0 /* mid */ 1 1', 0)?.problem).toBe('a comment stands among its numbers');
    expect(curveDeclarationOn('#table t 0 0 1 sin(1)', 0)?.problem).toBe("'sin(1)' is not a number");
    expect(curveDeclarationOn('#table t 0 0 1 1', 0)?.problem).toBeNull();
  });
});

describe('a number as the editor writes it', () => {
  it('resolves a thousandth of the frame, without trailing zeros, never -0', () => {
    expect([decimalsFor(1), decimalsFor(100), decimalsFor(0.01), decimalsFor(1e6), decimalsFor(0)]).toEqual([3, 1, 5, 0, 3]);
    expect(numberText(0.30000000004, 3)).toBe('0.3');
    expect(numberText(0.12345, 3)).toBe('0.123');
    expect(numberText(-0.0001, 3)).toBe('0');
    expect(numberText(12, 3)).toBe('12');
    expect(numberText(-2.5, 0)).toBe('-3');
  });

  it("keeps the line's fixed decimals when it writes them", () => {
    expect(fixedDecimals(only('#curve c 0.00 0.00 0.25 0.50 0.75 0.90 1.00 1.00'))).toBe(2);
    expect(fixedDecimals(only('#curve c 0 0 0.25 0.5 0.75 0.9 1 1'))).toBeNull();
    expect(fixedDecimals(only('#curve c 0 0 0.250 0.50 0.75 0.9 1 1'))).toBeNull(); // mixed: as short as they go
    expect(numberText(0.5, 2, true)).toBe('0.50');
    expect(numberText(0, 2, true)).toBe('0.00');
  });
});

describe('a point added or removed', () => {
  it("is written with the line's separators, between its neighbours", () => {
    const commas = '#curve c 0 0, 0.3 0.1, 0.7 0.9, 1 1 // c\n';
    expect(apply(commas, addPointChange(commas, only(commas), 2, ['0.5', '0.5']))).toBe('#curve c 0 0, 0.3 0.1, 0.5 0.5, 0.7 0.9, 1 1 // c\n');
    expect(apply(commas, addPointChange(commas, only(commas), 4, ['2', '0']))).toBe('#curve c 0 0, 0.3 0.1, 0.7 0.9, 1 1, 2 0 // c\n');
    const spaces = '#table t 0 0  1 1';
    expect(apply(spaces, addPointChange(spaces, only(spaces), 1, ['0.5', '0.25']))).toBe('#table t 0 0  0.5 0.25  1 1');
    const pairs = '#table t 0,0 1,1';
    expect(apply(pairs, addPointChange(pairs, only(pairs), 1, ['0.5', '0.25']))).toBe('#table t 0,0 0.5,0.25 1,1');
  });

  it('takes its separator with it, and leaves the rest of the line as written', () => {
    const text = '#curve c 0 0, 0.3 0.1, 0.5 0.5, 0.7 0.9, 1 1 // c';
    expect(apply(text, removePointChange(only(text), 2))).toBe('#curve c 0 0, 0.3 0.1, 0.7 0.9, 1 1 // c');
    expect(apply(text, removePointChange(only(text), 0))).toBe('#curve c 0.3 0.1, 0.5 0.5, 0.7 0.9, 1 1 // c');
    expect(apply(text, removePointChange(only(text), 4))).toBe('#curve c 0 0, 0.3 0.1, 0.5 0.5, 0.7 0.9 // c');
  });
});

/** A grammar editor over an EditorState with history (no view: what the page's editor dispatches). */
function editorOn(doc: string): PointTextEditor & { state: EditorState; undo(): void } {
  const box = {
    state: EditorState.create({ doc, extensions: [history()] }),
    text: () => box.state.doc.toString(),
    replaceRanges: (changes: Parameters<PointTextEditor['replaceRanges']>[0], options?: Parameters<PointTextEditor['replaceRanges']>[1]) => {
      box.state = box.state.update(rangesTransaction(changes, options)).state;
    },
    undo: () => void undo({ state: box.state, dispatch: (t: Transaction) => (box.state = t.state) }),
  };
  return box;
}

describe('a drag of a curve point', () => {
  it('rewrites its x and y at every step, and is one undo step that restores the whole curve', () => {
    const grammar = 'axiom: A(0)\n#curve leaf 0 0, 0.3 0.1, 0.7 0.9, 1 1\n';
    const editor = editorOn(grammar);
    const depth = undoDepth(editor.state);
    const point = writtenPoints(only(grammar))[1];
    const edit = new PointEdit(editor, [point.x, point.y]);
    for (const [x, y] of [['0.31', '0.15'], ['0.35', '0.2'], ['0.4', '0.125']]) {
      expect(edit.write([x, y])).toBe(true);
      expect(editor.text()).toBe(`axiom: A(0)\n#curve leaf 0 0, ${x} ${y}, 0.7 0.9, 1 1\n`);
    }
    edit.end();
    expect(undoDepth(editor.state)).toBe(depth + 1);
    // Added and removed points are undo steps of their own.
    const moved = editor.text();
    editor.replaceRanges([addPointChange(moved, only(moved), 2, ['0.5', '0.5'])], { history: true });
    expect(editor.text()).toContain('0.4 0.125, 0.5 0.5, 0.7 0.9');
    editor.undo();
    expect(editor.text()).toBe(moved);
    editor.undo();
    expect(editor.text()).toBe(grammar);
  });

  it('stops when the text changed under it', () => {
    const grammar = '#table t 0 0 1 1 2 0\n';
    const editor = editorOn(grammar);
    const point = writtenPoints(only(grammar))[1];
    const edit = new PointEdit(editor, [point.x, point.y]);
    expect(edit.write(['1.5', '2'])).toBe(true);
    editor.replaceRanges([{ from: 13, to: 16, insert: '7' }]); // typed over the point's x
    expect(edit.write(['1.2', '2'])).toBe(false);
    expect(editor.text()).toBe('#table t 0 0 7 2 2 0\n');
  });
});
