// The build of a plant shown at growth time t by deriving it (issue 45), for the studio's timeline
// and an embed alike: a timed grammar (ABOP 6.1) is derived at t itself, a stepwise one (a `#dt`
// without timed modules: L-Py's continuous growth) to its whole steps at t, ⌊t⌋ (so that a build
// goes on from the one a step before, as Play's steps do). In the first load (tiny): the studio's
// lazy timeline asks it for every build's options.

/** The time a derived grammar is built at for growth time `t` (null: its own iterations). */
export function derivedTime(t: number | null, stepwise: boolean): number | null {
  return t !== null && stepwise ? Math.floor(t) : t;
}

/**
 * The build options of the timeline: growth arrays when wanted (which the GPU grows); a timed
 * grammar's `time` at {@link derivedTime} `at`; a stepwise grammar's steps at t as its
 * `iterations`, without growth arrays (derivations that count each step's elements are not
 * continued from the step before).
 */
export function derivedBuildOptions(at: number | null, stepwise: boolean, growth: boolean): { growth?: true; time?: number; iterations?: number } {
  if (at !== null && stepwise) return { iterations: at };
  return { ...(growth ? { growth: true } : {}), ...(at === null ? {} : { time: at }) };
}
