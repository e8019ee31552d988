// The grammar editor: CodeMirror 6 with the grammar language and the core's diagnostics.
import { basicSetup } from 'codemirror';
import { Decoration, EditorView, type DecorationSet } from '@codemirror/view';
import { type Annotation, type EditorState, StateEffect, StateField, Transaction, type TransactionSpec } from '@codemirror/state';
import { forceLinting } from '@codemirror/lint';
import { isolateHistory } from '@codemirror/commands';
import { grammarCompletion } from './completion';
import { grammarSupport } from './language';
import { commandHover } from './hover';
import { grammarLinting, relint } from './diagnostics';
import { openProblems } from './problems';
import { studioEditorTheme } from './theme';
import { surfaceGutter } from './surface-gutter';
import type { GrammarEditor, GrammarEditorOptions, HistoryStep } from './grammar-text';
import type { TextChange } from './growth-directives';
import './grammar-editor.css';

export type { GrammarEditor, GrammarEditorOptions };

/**
 * The transaction of {@link GrammarEditor.replaceRanges}. A drag's steps are history events that
 * CodeMirror's history joins into one (a typing-like user event, adjacent changes, all stamped
 * with the drag's start time so that no pause splits them), isolated from what comes before the
 * first and after the last: no change is kept out of the history, since the history maps its older
 * events through such changes and an undo past them would then leave their text behind.
 */
export function rangesTransaction(changes: readonly TextChange[], { history = true }: { history?: HistoryStep } = {}): TransactionSpec {
  const spec = { changes: changes.map(({ from, to, insert }) => ({ from, to, insert })), userEvent: 'input' };
  if (history === true) return { ...spec, annotations: isolateHistory.of('full') };
  if (history === false) return { ...spec, annotations: Transaction.addToHistory.of(false) };
  const annotations: Annotation<unknown>[] = [Transaction.time.of(history.drag)];
  if (history.step === 'first') annotations.push(isolateHistory.of('before'));
  if (history.step === 'last') annotations.push(isolateHistory.of('after'));
  return { ...spec, userEvent: 'input.type.drag', annotations };
}

/** Sets (or clears, with null) the marked production range. */
const markProductionEffect = StateEffect.define<{ from: number; to: number } | null>();

/** The production marked by a pick in the 3D view or the string panel. */
const markedProduction = StateField.define<DecorationSet>({
  create: () => Decoration.none,
  update(marks, transaction) {
    let next = marks.map(transaction.changes);
    for (const effect of transaction.effects) {
      if (!effect.is(markProductionEffect)) continue;
      const range = effect.value;
      next =
        range && range.to > range.from
          ? Decoration.set([Decoration.mark({ class: 'cm-picked-production' }).range(range.from, range.to)])
          : Decoration.none;
    }
    return next;
  },
  provide: (field) => EditorView.decorations.from(field),
});

/** The grammar editor once CodeMirror has loaded: the page's {@link GrammarEditor} and its view. */
export interface CodeMirrorGrammarEditor extends GrammarEditor {
  /** The CodeMirror view (for tests and future commands). */
  readonly view: EditorView;
}

/**
 * Creates the editor in `options.parent`, with the text `options.doc` and, if given, `selection`
 * (UTF-16 offsets, e.g. where the cursor stood in the placeholder it replaces).
 */
export function createGrammarEditor(options: GrammarEditorOptions, selection?: { anchor: number; head: number }): CodeMirrorGrammarEditor {
  // The state an edit is about to give the view, while the page hears of its text: `text()` and
  // `cursor()` answer from it.
  let upcoming: EditorState | undefined;
  const view = new EditorView({
    parent: options.parent,
    doc: options.doc,
    selection,
    // The page hears of a new text before CodeMirror redraws for it, so the build worker starts on
    // it while the editor updates its lines (a few milliseconds of each keystroke's first frame).
    dispatchTransactions: (transactions, target) => {
      if (transactions.some((t) => t.docChanged)) {
        upcoming = transactions[transactions.length - 1].state;
        try {
          options.onChange(upcoming.doc.toString());
        } finally {
          upcoming = undefined;
          target.update(transactions);
        }
      } else target.update(transactions);
    },
    extensions: [
      basicSetup,
      grammarSupport(options.vocabulary),
      commandHover(options.vocabulary, options.openReference),
      grammarCompletion(options.vocabulary),
      grammarLinting(options.diagnose),
      studioEditorTheme,
      EditorView.lineWrapping,
      EditorView.contentAttributes.of({ 'aria-label': 'L-system grammar' }),
      markedProduction,
      options.openEditor ? surfaceGutter(options.openEditor) : [],
      EditorView.updateListener.of((update) => {
        if (update.docChanged || update.selectionSet) options.onCursor?.(update.state.selection.main.head);
      }),
    ],
  });
  return {
    view,
    text: () => (upcoming ?? view.state).doc.toString(),
    cursor: () => (upcoming ?? view.state).selection.main.head,
    focus: () => view.focus(),
    requestMeasure: () => view.requestMeasure(),
    showProblems: () => openProblems(view),
    loaded: Promise.resolve(),
    refreshDiagnostics: () => {
      view.dispatch({ effects: relint.of(null) });
      forceLinting(view);
    },
    replaceText: (text) =>
      view.dispatch({
        changes: { from: 0, to: view.state.doc.length, insert: text },
        selection: { anchor: 0 },
        scrollIntoView: true,
        userEvent: 'input.replace',
        annotations: isolateHistory.of('full'), // one undo step of its own, never joined to typing
      }),
    replaceRange: (from, to, insert, { history = true } = {}) =>
      view.dispatch({
        changes: { from, to, insert },
        userEvent: 'input',
        annotations: history ? [] : [Transaction.addToHistory.of(false)],
      }),
    replaceRanges: (changes, options) => view.dispatch(rangesTransaction(changes, options)),
    markProduction: (range) => {
      const length = view.state.doc.length;
      const clamped = range && { from: Math.min(range.from, length), to: Math.min(range.to, length) };
      view.dispatch({
        effects: [
          markProductionEffect.of(clamped),
          ...(clamped ? [EditorView.scrollIntoView(clamped.from, { y: 'nearest' })] : []),
        ],
      });
    },
  };
}
