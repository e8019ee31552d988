// Which kept build a new build goes on from (issue 45, stepping that is incremental): the build
// worker keeps its last builds (worker.ts), and a request for the same text and options with more
// iterations derives only the new steps from one of them (`inspectPlant`'s `from`).
import type { BuildOptions } from '../core';

/** What the worker knows of a kept build, to continue it. */
export interface KeptBuild {
  source: string;
  options: BuildOptions;
  /** The grammar's own `#iterations` (what a build without `options.iterations` derives). */
  grammarIterations: number;
}

/** The steps a build of a kept build's text with `options` derives. */
function stepsOf(options: BuildOptions, grammarIterations: number): number {
  return options.iterations ?? grammarIterations;
}

/** `options` but the iterations, as a key (absent and undefined alike, in a fixed order). */
function otherOptions(options: BuildOptions): string {
  const entries = Object.entries(options).filter(([key, value]) => key !== 'iterations' && value !== undefined);
  return JSON.stringify(entries.sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0)));
}

/**
 * The kept build (of `kept`, oldest first) a build of `source` with `options` goes on from: one of
 * the same text and the same options but `iterations`, with fewer steps than asked; the one with
 * the most steps (the newest of those), so that the fewest are derived. `undefined` when there is
 * none: the build derives from the axiom (a step back, another text, another seed or view option).
 * The core checks the rest (the grammar allows it, the same seed) and else derives from the axiom.
 */
export function continuable<K extends KeptBuild>(kept: Iterable<K>, source: string, options: BuildOptions): K | undefined {
  const key = otherOptions(options);
  let best: { entry: K; steps: number } | undefined;
  for (const entry of kept) {
    if (entry.source !== source || otherOptions(entry.options) !== key) continue;
    const steps = stepsOf(entry.options, entry.grammarIterations);
    if (steps >= stepsOf(options, entry.grammarIterations)) continue;
    if (!best || steps >= best.steps) best = { entry, steps };
  }
  return best?.entry;
}
