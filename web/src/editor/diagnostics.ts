// Core diagnostics shown in the editor: exact ranges, a gutter marker, hover text.
import { linter, lintGutter, type Diagnostic as EditorDiagnostic } from '@codemirror/lint';
import { StateEffect, type Extension } from '@codemirror/state';
import { utf16Offsets, type Diagnostic } from '../core';
import { problems } from './problems';
import { inTextOrder, markedDiagnostics, problemsUpdate } from './problems-state';

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
 * The lint extensions: underline + tooltip at each span and markers in a gutter, for the first
 * thousand problems (problems-state.ts's `markedDiagnostics`: 100,000 markers blocked the page),
 * and every problem in the Problems panel and under F8 (problems.ts).
 */
export function grammarLinting(diagnose: Diagnose): Extension {
  return [
    linter(
      async (view) => {
        const { doc } = view.state;
        const text = doc.toString();
        const all = inTextOrder(toEditorDiagnostics(text, await diagnose(text)));
        // CodeMirror drops an answer about an older text; so do the problems.
        if (view.state.doc === doc) view.dispatch(problemsUpdate(all));
        return markedDiagnostics(all);
      },
      { delay: LINT_DELAY_MS, needsRefresh: (update) => update.transactions.some((t) => t.effects.some((e) => e.is(relint))) },
    ),
    lintGutter(),
    problems(),
  ];
}
