// Core diagnostics shown in the editor: exact ranges, a gutter marker, hover text.
import { linter, lintGutter, openLintPanel, type Diagnostic as EditorDiagnostic } from '@codemirror/lint';
import { StateEffect, type Extension } from '@codemirror/state';
import { keymap } from '@codemirror/view';
import { utf16Offsets, type Diagnostic } from '../core';

/**
 * Converts the core's diagnostics for `text` (UTF-8 byte spans) into CodeMirror diagnostics
 * (UTF-16 positions, clamped to the text). The code (`E0101`) becomes the diagnostic's source,
 * shown before the message.
 */
export function toEditorDiagnostics(text: string, diagnostics: readonly Diagnostic[]): EditorDiagnostic[] {
  const toUtf16 = utf16Offsets(text);
  return diagnostics.map((d) => {
    const from = toUtf16(d.fromByte);
    const to = Math.max(from, toUtf16(d.toByte));
    return { from, to, severity: d.severity, message: d.message, source: d.code };
  });
}

/**
 * Returns the core's diagnostics for a grammar text, now or later (the studio answers when the
 * build worker delivers that text's build). An answer about a text that is no longer the
 * document's is dropped by the linter.
 */
export type Diagnose = (text: string) => readonly Diagnostic[] | Promise<readonly Diagnostic[]>;

/** How long the editor waits after the last edit before showing diagnostics, in ms. */
export const LINT_DELAY_MS = 400;

/**
 * Asks the linter to run again on the same text, e.g. when a build option (the iterations box)
 * changed its diagnostics; CodeMirror's `forceLinting` alone only hurries a run a change scheduled.
 */
export const relint = StateEffect.define<null>();

/**
 * The lint extensions: underline + tooltip at each span, markers in a gutter, and Ctrl+Shift+M for
 * the list of them on every platform (basicSetup's Mod-Shift-m is Cmd+Shift+M on a Mac, which
 * Chrome keeps for its profile menu).
 */
export function grammarLinting(diagnose: Diagnose): Extension {
  return [
    linter(
      async (view) => {
        const text = view.state.doc.toString();
        return toEditorDiagnostics(text, await diagnose(text));
      },
      { delay: LINT_DELAY_MS, needsRefresh: (update) => update.transactions.some((t) => t.effects.some((e) => e.is(relint))) },
    ),
    lintGutter(),
    keymap.of([{ key: 'Ctrl-Shift-m', run: openLintPanel, preventDefault: true }]),
  ];
}
