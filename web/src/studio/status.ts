// The status line's text, as pure functions of a build (tested without a page).
import type { Diagnostic, PlantStats, StageTimings } from '../core';

/** What the status line shows after a build. */
export interface StatusReport {
  /** `ok`: a fresh plant; `stale`: errors, the last good plant stays; `error`: errors, no plant yet. */
  state: 'ok' | 'stale' | 'error';
  text: string;
}

const count = new Intl.NumberFormat('en-US');

/** `1 error`, `3 errors`, `1,024 vertices` (irregular plurals passed as `nouns`). */
export function plural(n: number, noun: string, nouns = `${noun}s`): string {
  return `${count.format(n)} ${n === 1 ? noun : nouns}`;
}

/** A duration in ms: one decimal under 10 ms, whole above. */
export function millis(ms: number): string {
  return ms < 10 ? ms.toFixed(1) : String(Math.round(ms));
}

/**
 * The status after a successful build: sizes, the time of each stage of the core, the round trip
 * (`totalMillis`: from the request to the build's arrival on the page, waiting for the worker and
 * transferring the arrays included) and any warnings.
 */
export function reportPlant(
  stats: PlantStats,
  diagnostics: readonly Diagnostic[],
  timings: StageTimings,
  totalMillis: number,
): StatusReport {
  const parts = [
    plural(stats.modules, 'module'),
    plural(stats.segments, 'segment'),
    plural(stats.vertices, 'vertex', 'vertices'),
    plural(stats.triangles, 'triangle'),
    `parse+resolve ${millis(timings.parseResolve)} · derive ${millis(timings.derive)} · interpret ${millis(timings.interpret)} · mesh ${millis(timings.mesh)} ms`,
    `${millis(totalMillis)} ms round trip`,
  ];
  const warnings = diagnostics.filter((d) => d.severity === 'warning').length;
  if (warnings > 0) parts.push(plural(warnings, 'warning'));
  if (stats.lines > 0) parts.push(`too large to mesh: ${plural(stats.lines, 'segment')} drawn as lines`);
  return { state: 'ok', text: parts.join(' · ') };
}

/** The status after a build with errors; `hasPlant` tells whether an older plant is still shown. */
export function reportErrors(diagnostics: readonly Diagnostic[], hasPlant: boolean): StatusReport {
  const errors = plural(diagnostics.filter((d) => d.severity === 'error').length, 'error');
  return hasPlant
    ? { state: 'stale', text: `${errors} — showing last good plant` }
    : { state: 'error', text: `${errors} — no plant yet` };
}
