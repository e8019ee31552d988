// The grammar editor: CodeMirror 6 with the grammar language and the core's diagnostics.
import { basicSetup } from 'codemirror';
import { Decoration, EditorView, type DecorationSet } from '@codemirror/view';
import { StateEffect, StateField, Transaction } from '@codemirror/state';
import { forceLinting } from '@codemirror/lint';
import { isolateHistory } from '@codemirror/commands';
import type { Vocabulary } from '../core';
import { grammarCompletion } from './completion';
import { grammarSupport } from './language';
import { commandHover } from './hover';
import { grammarLinting, relint, type Diagnose } from './diagnostics';
import { studioEditorTheme } from './theme';

/** What {@link createGrammarEditor} needs. */
export interface GrammarEditorOptions {
  /** Element the editor is appended to. */
  parent: HTMLElement;
  /** Initial grammar text. */
  doc: string;
  /** Called with the new text after every change of the document. */
  onChange: (text: string) => void;
  /** Supplies the diagnostics shown for a text. */
  diagnose: Diagnose;
  /** The core's vocabulary: drives highlighting, completion and hover docs. */
  vocabulary: Vocabulary;
  /** Called with the cursor's position (UTF-16) whenever it moves or the text changes. */
  onCursor?: (pos: number) => void;
  /** Opens the language reference at a row (`referenceAnchor`): hover docs link to it. */
  openReference?: (anchor: string) => void;
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

/** A grammar editor on the page. */
export interface GrammarEditor {
  /** The CodeMirror view (for focus, tests, and future commands). */
  readonly view: EditorView;
  /** The current grammar text. */
  text(): string;
  /** Re-runs the diagnostics now, e.g. after an option that changes the build changed. */
  refreshDiagnostics(): void;
  /**
   * Replaces the whole text in one undoable transaction (Ctrl+Z brings the old text back), e.g.
   * when an example is opened; the cursor goes to the start.
   */
  replaceText(text: string): void;
  /**
   * Replaces `from`..`to` (UTF-16 offsets) with `insert`: an undoable step, or with `history:
   * false` a change undo skips (the steps of a slider drag, made one undo step at its end).
   */
  replaceRange(from: number, to: number, insert: string, options?: { history?: boolean }): void;
  /** Marks a range (a production picked elsewhere) and scrolls it into view; null clears the mark. */
  markProduction(range: { from: number; to: number } | null): void;
}

/** Creates the editor in `options.parent`. */
export function createGrammarEditor(options: GrammarEditorOptions): GrammarEditor {
  const view = new EditorView({
    parent: options.parent,
    doc: options.doc,
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
      EditorView.updateListener.of((update) => {
        if (update.docChanged) options.onChange(update.state.doc.toString());
        if (update.docChanged || update.selectionSet) options.onCursor?.(update.state.selection.main.head);
      }),
    ],
  });
  return {
    view,
    text: () => view.state.doc.toString(),
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
