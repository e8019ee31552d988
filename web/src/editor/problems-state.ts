// The text's diagnostics, however many, and the Problems panel's state (issue 50, finding 11):
// problems.ts wires them into the editor, problems-panel.ts shows them.
import type { Diagnostic as EditorDiagnostic } from '@codemirror/lint';
import { type ChangeDesc, StateEffect, StateField } from '@codemirror/state';
import type { Command, EditorView } from '@codemirror/view';
import { ProblemList } from './problem-list';

/** The most diagnostics the text is marked with (the panel and F8 reach every one). */
export const MAX_MARKED = 1000;

/** The text's diagnostics and the panel's state. */
export interface Problems {
  /** In document order (by start, then end), with positions in the text they were made for. */
  readonly list: ProblemList;
  /** The text's changes since then: positions are mapped through them when read (mapping 100,000 on every keystroke would cost). */
  readonly since: ChangeDesc | null;
  /** The panel is shown. */
  readonly open: boolean;
  /** The problem last chosen in the panel or by F8 (-1: none). */
  readonly selected: number;
}

const setProblems = StateEffect.define<ProblemList>();
const showProblems = StateEffect.define<boolean>();
const chooseProblem = StateEffect.define<number>();

export const problemsField = StateField.define<Problems>({
  create: () => ({ list: ProblemList.NONE, since: null, open: false, selected: -1 }),
  update(value, transaction) {
    let next = value;
    if (transaction.docChanged && value.list.length > 0) {
      const changes = transaction.changes.desc;
      next = { ...next, since: next.since ? next.since.composeDesc(changes) : changes };
    }
    for (const effect of transaction.effects) {
      if (effect.is(setProblems)) next = { ...next, list: effect.value, since: null, selected: -1 };
      else if (effect.is(showProblems)) next = { ...next, open: effect.value };
      else if (effect.is(chooseProblem)) next = { ...next, selected: effect.value };
    }
    return next;
  },
});

/**
 * The diagnostics the text is marked with, of a list in document order: the first
 * {@link MAX_MARKED}, and past them one note where the first unmarked one starts.
 */
export function markedDiagnostics(list: ProblemList): EditorDiagnostic[] {
  const marked = Array.from({ length: Math.min(list.length, MAX_MARKED) }, (_, i) => list.at(i));
  if (list.length <= MAX_MARKED) return marked;
  const rest = list.length - MAX_MARKED;
  const at = list.range(MAX_MARKED).from;
  const message =
    `${count(rest, 'more problem')} from here on ${rest === 1 ? 'is' : 'are'} not marked in the text: ` +
    `Problems (Ctrl+Shift+M) lists all ${list.length.toLocaleString('en')}, and F8 goes to the next one`;
  return [...marked, { from: at, to: at, severity: 'info', message }];
}

/** "1 problem", "100,000 problems". */
export function count(n: number, noun: string): string {
  return `${n.toLocaleString('en')} ${noun}${n === 1 ? '' : 's'}`;
}

/** The transaction that gives the text's diagnostics now (from the linter, in document order). */
export function problemsUpdate(list: ProblemList): { effects: StateEffect<unknown> } {
  return { effects: setProblems.of(list) };
}

/** The transaction that shows or hides the panel. */
export function problemsShown(shown: boolean): { effects: StateEffect<unknown> } {
  return { effects: showProblems.of(shown) };
}

/** Closes the Problems panel. */
export const closeProblems: Command = (view) => {
  if (!view.state.field(problemsField).open) return false;
  view.dispatch(problemsShown(false));
  return true;
};

/** Where problem `i` is in the text now. */
export function problemRange(problems: Problems, i: number): { from: number; to: number } {
  const { from, to } = problems.list.range(i);
  if (!problems.since) return { from, to };
  const start = problems.since.mapPos(from, 1);
  return { from: start, to: Math.max(start, problems.since.mapPos(to, -1)) };
}

/** Selects problem `i` in the text (scrolled into view) and in the panel. */
export function goToProblem(view: EditorView, i: number): void {
  const problems = view.state.field(problemsField);
  if (i < 0 || i >= problems.list.length) return;
  const { from, to } = problemRange(problems, i);
  view.dispatch({ selection: { anchor: from, head: to }, scrollIntoView: true, effects: chooseProblem.of(i) });
}

