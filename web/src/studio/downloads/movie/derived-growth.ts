// A movie of a plant derived at each frame's growth time (issue 45): a timed grammar (ABOP 6.1) at
// t, a stepwise one (a `#dt` without timed modules) at ⌊t⌋, whole at its own iterations from t = N:
// what the studio's timeline shows, through its builds (`LazyTimeline.deriveAt`, whose options are
// plant-controls/derived-at.ts's), each frame waiting for the plant of its time to be on screen.
// The build worker goes on from the build before (its incremental continue-from), so successive
// frames cost the steps between them. A build that fails (an error at some t, a crash, a stop)
// fails the movie with its reason, never waits forever.
import type { LivePreview } from '../../preview';
import type { LazyTimeline } from '../../timeline';

/** What filming a derived plant needs of the studio. */
export interface DerivedStudio {
  timeline: Pick<LazyTimeline, 'deriveAt' | 'timedAt' | 'timedSpan' | 'pose'>;
  preview: Pick<LivePreview, 'answered' | 'settled' | 'lastResult'>;
  /** The view has a plant on its way to the GPU (`PlantView.uploading`). */
  uploading(): boolean;
  /** Settles once the next plant is on screen (`PlantView.onPlantShown`). */
  nextPlantShown(): Promise<void>;
}

/** A plant shown at a growth time by deriving it (see the file's comment). */
export interface DerivedGrowth {
  /** N: the plant at t ≥ N is the grammar's own iterations. */
  readonly span: number;
  /** Shows the plant derived at growth time t: settles once it is on screen, rejects with the build's problem. */
  show(t: number): Promise<void>;
  /** Puts the studio back at the time it showed before (the movie is done); {@link show} asks nothing more. */
  restore(): void;
}

/** A build asked for once more when another time was asked meanwhile (the timeline's last), at most this often. */
const RETRIES = 4;

/** The problem of the plant on screen after a build was answered, or null when it is the one asked for. */
function problem(preview: DerivedStudio['preview'], t: number): string | null {
  if (!preview.settled) return `the build at t = ${t} was stopped, or the core crashed on it`;
  const build = preview.lastResult?.build;
  if (build?.ok) return null;
  const error = build?.diagnostics.first('error');
  return `the grammar has errors at t = ${t}${error ? `: ${error.message}` : ''}`;
}

/**
 * The derived growth of the plant on screen, or null when it grows on the GPU (not timed nor
 * stepwise). (The timeline is to be posed first, `LazyTimeline.pose`: the movie poses the plant.)
 */
export function derivedGrowth(studio: DerivedStudio): DerivedGrowth | null {
  const span = studio.timeline.timedSpan();
  if (span === null) return null;
  const { timeline, preview } = studio;
  const before = timeline.timedAt;
  let closed = false;
  return {
    span,
    show: async (t) => {
      const at = t >= span ? null : t;
      for (let tries = 0; !closed; tries++) {
        timeline.deriveAt(at);
        const asked = timeline.timedAt;
        await preview.answered();
        if (closed) return;
        const wrong = problem(preview, t);
        if (wrong !== null) throw new Error(wrong);
        if (timeline.timedAt === asked) break;
        if (tries >= RETRIES) throw new Error(`the plant at t = ${t} was asked for ${RETRIES} times, each time replaced by another`);
      }
      if (studio.uploading()) await studio.nextPlantShown();
    },
    restore: () => {
      if (closed) return;
      closed = true;
      timeline.deriveAt(before);
    },
  };
}
