// A drag of a control point through a real CodeMirror state with its history, as the studio's
// editor dispatches it (`rangesTransaction`): the text follows every step, and one undo restores
// the text before the drag.
import { history, undo, undoDepth } from '@codemirror/commands';
import { EditorState, type Transaction } from '@codemirror/state';
import { describe, expect, it } from 'vitest';
import { rangesTransaction } from '../../editor/grammar-editor';
import { PointEdit, type PointTextEditor } from './point-edit';

/** A grammar editor over an EditorState with history (no view: what the page's editor dispatches). */
function editorOn(doc: string): PointTextEditor & { state: EditorState; undo(): void; type(at: number, text: string): void } {
  const box = {
    state: EditorState.create({ doc, extensions: [history()] }),
    text: () => box.state.doc.toString(),
    replaceRanges: (changes: Parameters<PointTextEditor['replaceRanges']>[0], options?: { history?: boolean }) => {
      box.state = box.state.update(rangesTransaction(changes, options)).state;
    },
    undo: () => {
      undo({ state: box.state, dispatch: (t: Transaction) => (box.state = t.state) });
    },
    type: (at: number, text: string) => {
      box.state = box.state.update({ changes: { from: at, insert: text }, userEvent: 'input.type' }).state;
    },
  };
  return box;
}

const GRAMMAR = 'axiom: ~A\n#patch A 0 0 0, 1 0 0, 0 0 0\n';
const FIRST = { from: 19, to: 24 };
const THIRD = { from: 33, to: 38 };

describe('a drag of a control point', () => {
  it('writes every step, and is one undo step that restores the text before it', () => {
    const editor = editorOn(GRAMMAR);
    editor.type(0, '// typed just before\n'); // joined with the drag it would undo both
    const shift = '// typed just before\n'.length;
    const spans = [FIRST, THIRD].map((s) => ({ from: s.from + shift, to: s.to + shift }));
    const typed = editor.text();
    const depth = undoDepth(editor.state);
    const edit = new PointEdit(editor, spans);
    for (const x of [0.1, 0.22, 0.333333, 0.5]) {
      expect(edit.move([x, 0.25, -0.125])).toBe(true);
      expect(editor.text()).toContain(`#patch A ${x === 0.333333 ? '0.3333' : x} 0.25 -0.125, 1 0 0, ${x === 0.333333 ? '0.3333' : x} 0.25 -0.125`);
    }
    edit.end();
    expect(editor.text()).toBe(typed.replace('0 0 0, 1 0 0, 0 0 0', '0.5 0.25 -0.125, 1 0 0, 0.5 0.25 -0.125'));
    expect(undoDepth(editor.state)).toBe(depth + 1); // the drag's steps made one history event
    editor.undo();
    expect(editor.text()).toBe(typed);
    editor.undo();
    expect(editor.text()).toBe(GRAMMAR);
  });

  it('leaves the text as it was when the point comes back where it began', () => {
    const editor = editorOn(GRAMMAR);
    const edit = new PointEdit(editor, [FIRST]);
    edit.move([2, 2, 2]);
    edit.move([0, 0, 0]);
    edit.end();
    expect(editor.text()).toBe(GRAMMAR);
    editor.undo();
    expect(editor.text()).toBe(GRAMMAR);
  });

  it('is one undo step, even inside text an earlier undo step wrote, and however long it pauses', async () => {
    // The patch line is written by one undo step (as the editor writes a library shape out), then
    // a point of it is dragged: undoing both gives back the text before either, nothing left over.
    const editor = editorOn('axiom: ~A\n');
    editor.replaceRanges([{ from: 10, to: 10, insert: '#patch A 0 0 0, 1 0 0, 0 0 0\n' }]);
    expect(editor.text()).toBe(GRAMMAR);
    const edit = new PointEdit(editor, [FIRST, THIRD]);
    edit.move([0.5, 0, 0]);
    await new Promise((resolve) => setTimeout(resolve, 600)); // longer than CodeMirror's pause between undo steps
    edit.move([0.75, 0, 0]);
    edit.end();
    editor.type(0, '// typed after\n');
    expect(undoDepth(editor.state)).toBe(3);
    editor.undo();
    editor.undo();
    expect(editor.text()).toBe(GRAMMAR);
    editor.undo();
    expect(editor.text()).toBe('axiom: ~A\n');
  });

  it('stops when the text changes under it, and never writes over what was typed', () => {
    const editor = editorOn(GRAMMAR);
    const edit = new PointEdit(editor, [FIRST]);
    edit.move([3, 3, 3]);
    editor.type(FIRST.from + 1, '9'); // the user types into the point
    const typed = editor.text();
    expect(edit.move([4, 4, 4])).toBe(false);
    expect(edit.live).toBe(false);
    edit.end();
    expect(editor.text()).toBe(typed);
  });
});
