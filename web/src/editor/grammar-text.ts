// The grammar text on the page before and after CodeMirror (issue 22): the studio draws its first
// plant with a plain <textarea> holding the grammar, and the editor (CodeMirror, its language,
// completion, hover docs and linting: about a third of the page's script) loads after that first
// frame, or as soon as the user reaches for the text. What the user typed or selected meanwhile
// goes over into the editor; nothing typed early is lost or ignored (it builds as it does later).
// Invariant: nothing here imports CodeMirror; `./grammar-editor` arrives by a dynamic import.
import type { Vocabulary } from '../core';
import type { Diagnose } from './diagnostics';
import type { TextChange } from './growth-directives';

/** What the grammar editor needs. */
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
  /**
   * Opens the editor of what a line declares (its gutter marker, Alt+B on it): the surface editor
   * on surface X of a `#surface X`/`#patch X` line, the curve editor on a `#curve`/`#table` function.
   */
  openEditor?: OpenEditor;
}

/** What the text asks to edit: a surface by its letter, or a curve function by its name. */
export interface EditorTarget {
  what: 'surface' | 'curve';
  name: string;
}

/** Opens the surface editor on a surface's letter, or the curve editor on a curve function's name. */
export type OpenEditor = (target: EditorTarget) => void;

/**
 * How a change enters the undo history: as one undo step of its own (true), not at all (false: a
 * change undo skips), or as a step of a drag: the steps of one drag (the same `drag`, a time in
 * ms) make one undo step, which the first step starts and the last (no change needed) closes.
 */
export type HistoryStep = boolean | { drag: number; step: 'first' | 'next' | 'last' };

/** The grammar text on the page: the placeholder's until the editor has loaded, then the editor's. */
export interface GrammarEditor {
  /** The current grammar text. */
  text(): string;
  /** The cursor's position (UTF-16 offset). */
  cursor(): number;
  /** Moves the keyboard focus to the text. */
  focus(): void;
  /** Measures the layout again (after the pane changed size). */
  requestMeasure(): void;
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
  /**
   * Replaces several ranges at once (offsets in the text before the change; none overlapping) in
   * one transaction, which enters the undo history as {@link HistoryStep} says (by default, one
   * undo step of its own, never joined to the typing or the edit before or after it).
   */
  replaceRanges(changes: readonly TextChange[], options?: { history?: HistoryStep }): void;
  /** Marks a range (a production picked elsewhere) and scrolls it into view; null clears the mark. */
  markProduction(range: { from: number; to: number } | null): void;
  /**
   * Opens the list of the text's errors and warnings under it (CodeMirror's lint panel: each in
   * full; choosing one moves the cursor to it) with the keyboard focus in it: what a touch screen,
   * which has no hover for the underlines' tooltips, reads them by. Loads the editor if need be.
   */
  showProblems(): void;
  /**
   * Settles when the full editor is on the page, or when it could not load (the text then stays a
   * plain textarea, still built on every change); reading it starts the loading.
   */
  readonly loaded: Promise<void>;
}

/** The module with the full editor (CodeMirror), loaded on demand. */
export interface EditorModule {
  createGrammarEditor(options: GrammarEditorOptions, selection?: { anchor: number; head: number }): GrammarEditor;
}

/**
 * The lazy editor's options: the vocabulary arrives with the editor (`core/vocabulary.ts`: after
 * the first plant); who hears of changes and of the cursor says so on the editor made
 * ({@link LazyGrammarEditor.onChange}), so that it can be made before them.
 */
export type LazyGrammarEditorOptions = Omit<GrammarEditorOptions, 'vocabulary' | 'onChange' | 'onCursor' | 'openEditor'> & { vocabulary: () => Promise<Vocabulary> };

/** The grammar text on the page, which tells its listeners of every change and cursor move. */
export interface LazyGrammarEditor extends GrammarEditor {
  /** Calls `listener` with the new text after every change of the document. */
  onChange(listener: (text: string) => void): void;
  /** Calls `listener` with the cursor's position (UTF-16) whenever it moves or the text changes. */
  onCursor(listener: (pos: number) => void): void;
  /** Calls `listener` with what the user asks to edit from the text (the gutter, Alt+B): a surface's letter or a curve's name. */
  onOpenEditor(listener: OpenEditor): void;
}

/**
 * A grammar text in a plain <textarea> in `options.parent` at once, replaced by the full editor
 * from `load()` when {@link GrammarEditor.loaded} is first read or the user focuses the textarea,
 * with the text and the selection the textarea held then (and the focus, if it had it). Until then
 * every change, typed or made through the methods, tells the change listeners as the editor's do;
 * marks and diagnostics wait for the editor.
 */
export function createLazyGrammarEditor(options: LazyGrammarEditorOptions, load: () => Promise<EditorModule>): LazyGrammarEditor {
  const changeListeners: ((text: string) => void)[] = [];
  const cursorListeners: ((pos: number) => void)[] = [];
  const onChange = (text: string) => changeListeners.forEach((listener) => listener(text));
  const onCursor = (pos: number) => cursorListeners.forEach((listener) => listener(pos));
  const editorListeners: OpenEditor[] = [];
  const openEditor: OpenEditor = (target) => editorListeners.forEach((listener) => listener(target));
  const area = document.createElement('textarea');
  area.className = 'grammar-placeholder';
  area.dataset.testid = 'grammar-placeholder';
  area.value = options.doc;
  area.spellcheck = false;
  area.setAttribute('aria-label', 'L-system grammar');
  area.setAttribute('autocapitalize', 'off');
  area.setAttribute('autocomplete', 'off');
  options.parent.append(area);
  const changed = () => {
    onChange(area.value);
    onCursor(area.selectionStart);
  };
  area.addEventListener('input', changed);

  let full: GrammarEditor | undefined;
  let loading: Promise<void> | undefined;
  const upgrade = (): Promise<void> =>
    (loading ??= Promise.all([load(), options.vocabulary()]).then(([module, vocabulary]) => {
      const hadFocus = document.activeElement === area;
      const [start, end] = [area.selectionStart, area.selectionEnd];
      const selection = area.selectionDirection === 'backward' ? { anchor: end, head: start } : { anchor: start, head: end };
      const clamp = (n: number) => Math.min(n, area.value.length);
      full = module.createGrammarEditor({ ...options, onChange, onCursor, openEditor, vocabulary, doc: area.value }, { anchor: clamp(selection.anchor), head: clamp(selection.head) });
      area.remove();
      if (hadFocus) full.focus();
    }, reportLoadError));
  area.addEventListener('focus', () => void upgrade(), { once: true });

  return {
    onChange: (listener) => void changeListeners.push(listener),
    onCursor: (listener) => void cursorListeners.push(listener),
    onOpenEditor: (listener) => void editorListeners.push(listener),
    text: () => full?.text() ?? area.value,
    cursor: () => full?.cursor() ?? area.selectionStart,
    focus: () => (full ? full.focus() : area.focus()),
    requestMeasure: () => full?.requestMeasure(),
    refreshDiagnostics: () => full?.refreshDiagnostics(),
    replaceText: (text) => {
      if (full) return full.replaceText(text);
      area.value = text;
      area.setSelectionRange(0, 0);
      area.scrollTop = 0;
      changed();
    },
    replaceRange: (from, to, insert, history) => {
      if (full) return full.replaceRange(from, to, insert, history);
      area.setRangeText(insert, from, to, 'preserve');
      changed();
    },
    replaceRanges: (changes, history) => {
      if (full) return full.replaceRanges(changes, history);
      // From the last to the first: each leaves the offsets before it as they were.
      for (const c of [...changes].sort((a, b) => b.from - a.from)) area.setRangeText(c.insert, c.from, c.to, 'preserve');
      changed();
    },
    markProduction: (range) => full?.markProduction(range),
    showProblems: () => void upgrade().then(() => full?.showProblems()),
    get loaded() {
      return upgrade();
    },
  };
}

function reportLoadError(error: unknown): void {
  console.error('The grammar editor could not load (the text stays editable as plain text):', error);
}
