// The timeline wired to the studio's parts: the view it shows at a growth time, the builds it asks
// growth arrays of, the steps of the plant on screen.
import type { StudioParts } from '../parts';

/** Connects the timeline to the view and the builds (its bar loads later: {@link LazyTimeline.load}). */
export function wireTimeline({ timeline, view, preview }: StudioParts): void {
  timeline.connect({ view, rebuild: () => preview.rebuild(), steps: () => preview.lastGood?.build.stats.iterations });
  preview.onDelivered(() => timeline.delivered());
}
