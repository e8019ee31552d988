// Core diagnostics shown in the editor: exact ranges, a gutter marker, hover text.
import { linter, lintGutter } from '@codemirror/lint';
import { StateEffect, type Extension } from '@codemirror/state';
import type { DiagnosticList } from '../core';
import { ProblemList } from './problem-list';
import { problems } from './problems';
import { markedDiagnostics, problemsUpdate } from './problems-state';

/**
 * Returns the core's diagnostics for a grammar text, now or later (the studio answers when the
 * build worker delivers that text's build). An answer about a text that is no longer the
 * document's is dropped by the linter.
 */
export type Diagnose = (text: string) => DiagnosticList | Promise<DiagnosticList>;

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
        const all = ProblemList.of(text, await diagnose(text));
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
