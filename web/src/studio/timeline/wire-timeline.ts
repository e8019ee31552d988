// The timeline wired to the studio's parts: the view it shows at a growth time, the builds it asks
// growth arrays of, the steps of the plant on screen.
import type { StudioParts } from '../parts';

/** Connects the timeline to the view and the builds (its bar loads later: {@link LazyTimeline.load}). */
export function wireTimeline({ timeline, view, preview, derivation }: StudioParts): void {
  // A timed or stepwise grammar's plant at t is derived at t: its timeline spans its iterations,
  // whatever t the plant on screen was derived at.
  const timedSpan = () => {
    const build = preview.lastGood?.build;
    return build?.timed || build?.stepwise ? (derivation.iterations() ?? build.grammarIterations) : null;
  };
  const stepwise = () => preview.lastGood?.build.stepwise === true;
  timeline.connect({ view, rebuild: () => preview.rebuild(), steps: () => preview.lastGood?.build.stats.iterations, timedSpan, stepwise, busy: () => preview.busy });
  preview.onDelivered(() => timeline.delivered());
}
