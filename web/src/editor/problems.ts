// Every diagnostic of the text, however many (issue 50, finding 11: 100,000 of them as CodeMirror
// lint markers and lint-panel items blocked the page for 11 s). The Problems panel
// (problems-panel.ts) lists them all with only the rows in view in the page, F8 and Shift+F8 go to
// the next and the previous one, and the text carries markers (underline, gutter, tooltip) for the
// first MAX_MARKED only, with one more marker saying how many follow unmarked
// (problems-state.ts's markedDiagnostics).
import { type EditorState, type Extension, Prec } from '@codemirror/state';
import { type Command, keymap, showPanel } from '@codemirror/view';
import { createProblemsPanel } from './problems-panel';
import { goToProblem, problemRange, problemsField, problemsShown, type Problems } from './problems-state';

/** The first problem starting after `pos` (positions in order: mapping keeps it), or the count. */
function firstAfter(problems: Problems, pos: number): number {
  let low = 0;
  let high = problems.list.length;
  while (low < high) {
    const mid = (low + high) >> 1;
    if (problemRange(problems, mid).from > pos) high = mid;
    else low = mid + 1;
  }
  return low;
}

/** The problem the selection is on, when it was chosen as one. */
function chosen(state: EditorState): number {
  const problems = state.field(problemsField);
  if (problems.selected < 0 || problems.selected >= problems.list.length) return -1;
  const { from, to } = problemRange(problems, problems.selected);
  const { main } = state.selection;
  return main.from === from && main.to === to ? problems.selected : -1;
}

/** F8: the next problem after the cursor (after the last, the first). */
export const nextProblem: Command = (view) => {
  const problems = view.state.field(problemsField);
  const n = problems.list.length;
  if (n === 0) return false;
  const current = chosen(view.state);
  const next = current >= 0 ? current + 1 : firstAfter(problems, view.state.selection.main.from);
  goToProblem(view, next % n);
  return true;
};

/** Shift+F8: the problem before the cursor (before the first, the last). */
export const previousProblem: Command = (view) => {
  const problems = view.state.field(problemsField);
  const n = problems.list.length;
  if (n === 0) return false;
  const current = chosen(view.state);
  const before = current >= 0 ? current - 1 : firstAfter(problems, view.state.selection.main.from - 1) - 1;
  goToProblem(view, (before + n) % n);
  return true;
};

/** Opens the Problems panel and puts the keyboard in its list. */
export const openProblems: Command = (view) => {
  if (!view.state.field(problemsField).open) view.dispatch(problemsShown(true));
  view.dom.querySelector<HTMLElement>('.cm-problems-list')?.focus();
  return true;
};

/**
 * The problems' state and keys: Ctrl+Shift+M (on every platform; basicSetup's Mod-Shift-m is
 * Cmd+Shift+M on a Mac, which Chrome keeps for its profile menu) opens the panel, F8 and Shift+F8
 * go through every problem. Above basicSetup's lint keys, which know only the marked ones.
 */
export function problems(): Extension {
  return [
    problemsField,
    showPanel.compute([problemsField], (state) => (state.field(problemsField).open ? createProblemsPanel : null)),
    Prec.high(
      keymap.of([
        { key: 'Ctrl-Shift-m', run: openProblems, preventDefault: true },
        { key: 'Mod-Shift-m', run: openProblems, preventDefault: true },
        { key: 'F8', run: nextProblem, shift: previousProblem, preventDefault: true },
      ]),
    ),
  ];
}
