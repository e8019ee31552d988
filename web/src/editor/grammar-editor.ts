// The grammar editor: CodeMirror 6 with the grammar language and the core's diagnostics.
import { basicSetup } from 'codemirror';
import { EditorView } from '@codemirror/view';
import { Transaction } from '@codemirror/state';
import { forceLinting } from '@codemirror/lint';
import { isolateHistory } from '@codemirror/commands';
import type { GrammarDirective, TurtleCommand } from '../core';
import { grammarCompletion } from './completion';
import { grammarSupport } from './language';
import { commandHover } from './hover';
import { grammarLinting, type Diagnose } from './diagnostics';
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
  /** The core's turtle command table: drives highlighting, completion and hover docs. */
  commands: readonly TurtleCommand[];
  /** The core's directive table: drives completion. */
  directives: readonly GrammarDirective[];
}

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
}

/** Creates the editor in `options.parent`. */
export function createGrammarEditor(options: GrammarEditorOptions): GrammarEditor {
  const view = new EditorView({
    parent: options.parent,
    doc: options.doc,
    extensions: [
      basicSetup,
      grammarSupport(options.commands),
      commandHover(options.commands),
      grammarCompletion(options.commands, options.directives),
      grammarLinting(options.diagnose),
      studioEditorTheme,
      EditorView.lineWrapping,
      EditorView.contentAttributes.of({ 'aria-label': 'L-system grammar' }),
      EditorView.updateListener.of((update) => {
        if (update.docChanged) options.onChange(update.state.doc.toString());
      }),
    ],
  });
  return {
    view,
    text: () => view.state.doc.toString(),
    refreshDiagnostics: () => forceLinting(view),
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
  };
}
