// The status line's text, as pure functions of a build (tested without a page).
import type { BuildProgress, DiagnosticList, PlantStats, StageTimings } from '../../core';

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
  diagnostics: DiagnosticList,
  timings: StageTimings,
  totalMillis: number,
): StatusReport {
  const parts = [
    plural(stats.modules, 'module'),
    plural(stats.segments, 'segment'),
    // A plant the Lines mode draws without tubes (and without leaves or polygons) has no mesh: say
    // how it is drawn rather than "0 vertices", which reads as nothing drawn.
    ...(stats.vertices === 0 && stats.segments > 0 && stats.lines === 0
      ? ['drawn as lines']
      : [plural(stats.vertices, 'vertex', 'vertices'), plural(stats.triangles, 'triangle')]),
    `parse+resolve ${millis(timings.parseResolve)} · derive ${millis(timings.derive)} · interpret ${millis(timings.interpret)} · mesh ${millis(timings.mesh)} ms`,
    `${millis(totalMillis)} ms round trip`,
  ];
  const warnings = diagnostics.count('warning');
  if (warnings > 0) parts.push(plural(warnings, 'warning'));
  if (stats.lines > 0) parts.push(`too large to mesh: ${plural(stats.lines, 'segment')} drawn as lines`);
  return { state: 'ok', text: parts.join(' · ') };
}

/**
 * The status after a build with errors; `hasPlant` tells whether an older plant is still shown.
 * The first error follows in words (with its line): when a limit was hit (steps, modules, memory)
 * the core's message says what to change, and it is said where the user is looking.
 */
export function reportErrors(diagnostics: DiagnosticList, hasPlant: boolean): StatusReport {
  const errors = plural(diagnostics.count('error'), 'error');
  const error = diagnostics.first('error');
  const first = error ? ` · line ${error.line}: ${error.message}` : '';
  return hasPlant
    ? { state: 'stale', text: `${errors} — showing last good plant${first}` }
    : { state: 'error', text: `${errors} — no plant yet${first}` };
}

/** What each stage of a build is doing, for the status line. */
const BUILDING: Record<BuildProgress['stage'], string> = {
  parsing: 'reading the grammar',
  deriving: 'deriving',
  environment: 'environment',
  interpreting: 'drawing the turtle’s path',
  meshing: 'meshing',
};

/**
 * The status while a build runs: `Building… step 12 of 40 · 3 s` (the stage, or the derivation
 * step it has reached, and after a second the time so far); `Building… environment, step 12 of 40`
 * while the environment answers the plant of step 12. Never a plant's figures: the plant on
 * screen may be of an older text.
 */
export function reportBuilding(progress: BuildProgress | undefined, elapsedMs: number): { state: 'building'; text: string } {
  let doing = '';
  if (progress?.steps) doing = `${progress.stage === 'environment' ? ' environment,' : ''} step ${count.format(progress.step)} of ${count.format(progress.steps)}`;
  else if (progress) doing = ` ${BUILDING[progress.stage]}`;
  const time = elapsedMs >= 1000 ? ` · ${Math.floor(elapsedMs / 1000)} s` : '';
  return { state: 'building', text: `Building…${doing}${time}` };
}
