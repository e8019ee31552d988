// The studio's growth timeline as the first plant's script holds it: whether builds carry growth
// arrays (once the timeline is used), and the timeline bar under the view (./timeline-bar.ts, its
// own chunk), loaded after the first plant or by the first Play. Play, the keyboard and share
// links reach the timeline through here.
import { derivedBuildOptions, derivedTime } from '../../plant-controls';
import type { SharedGrowth } from '../../share';
import type { PlantView } from '../../view';
import type * as Bar from './timeline-bar';
import type { HandOver } from './panel-pace';

/** The bar's place in the page (index.html) and the toolbar's Play. */
export interface TimelineElements {
  /** The bar under the view, filled when its code arrives. */
  bar: HTMLElement;
  /** The toolbar's Play / Pause (the timeline's, as the bar's own). */
  play: HTMLButtonElement;
}

/** What the timeline needs of the studio. */
export interface TimelineStudio {
  view: PlantView;
  /** Asks for a build (with the options of now: growth arrays once {@link LazyTimeline.growthWanted}). */
  rebuild: () => void;
  /**
   * The steps the timeline spans when the plant at t is derived at t (a timed or a stepwise
   * grammar: its iterations, the plant at t = N), or null when it grows on the GPU from the whole
   * plant's mesh (its growth arrays span its steps).
   */
  timedSpan: () => number | null;
  /** The grammar on screen is stepwise (`PlantBuild.stepwise`): derived to each whole step of t. */
  stepwise: () => boolean;
  /** The derivation steps of the plant on screen (N before its growth arrays are there). */
  steps: () => number | undefined;
  /** A build is under way (a timed grammar's next time waits for it). */
  busy: () => boolean;
}

/** The timeline, its bar loaded on first use. */
export class LazyTimeline {
  /** Builds carry growth arrays: the timeline was used (asking for them costs a little meshing and memory). */
  growthWanted = false;
  /**
   * The growth time a timed or stepwise grammar's builds are derived at, or null for the grammar's
   * own iterations: a timed plant is shown at t by deriving it at t (ABOP 6.1), a stepwise one
   * at ⌊t⌋ (whole steps: then a step forward goes on from the step before), not grown from the
   * whole plant's mesh. See {@link buildOptions}.
   */
  timedAt: number | null = null;
  private loading: Promise<Bar.TimelineBar> | undefined;
  private loaded: Bar.TimelineBar | undefined;
  private studio: TimelineStudio | undefined;

  constructor(private readonly els: TimelineElements) {}

  /** Connects the studio (after the parts are made: the preview reads {@link growthWanted}). */
  connect(studio: TimelineStudio): void {
    this.studio = studio;
    this.els.play.addEventListener('click', () => this.toggle());
  }

  /** From now on builds carry growth arrays; a build follows if they did not. */
  want(): void {
    if (this.growthWanted) return;
    this.growthWanted = true;
    this.studio?.rebuild();
  }

  /** Loads the bar in the background (after the first plant); a failure is logged, and Play tries again. */
  preload(): Promise<unknown> {
    return this.load().catch((error: unknown) => console.error('The timeline could not load:', error));
  }

  /**
   * Builds from now on derive a timed grammar at `t`, a stepwise one at ⌊t⌋ (null: at its own
   * iterations); a build follows a change.
   */
  deriveAt(t: number | null): void {
    const at = derivedTime(t, this.studio?.stepwise() ?? false);
    if (at === this.timedAt) return;
    this.timedAt = at;
    this.studio?.rebuild();
  }

  /**
   * What the timeline asks of the builds: once it was used, growth arrays (which the GPU grows),
   * but not for a plant derived at t (a timed or stepwise grammar never plays them, and a build
   * that counts each step's elements derives from the axiom again); the time {@link deriveAt}
   * asked for, a timed grammar's `time`; a stepwise grammar's steps at t as its `iterations` (so
   * that a build goes on from the one a step before it, as Play's steps do).
   */
  buildOptions(): { growth?: true; time?: number; iterations?: number } {
    const studio = this.studio;
    return derivedBuildOptions(this.timedAt, studio?.stepwise() ?? false, this.growthWanted && studio?.timedSpan() === null);
  }

  /** The bar, loaded (and shown) on first call. */
  load(): Promise<Bar.TimelineBar> {
    const studio = this.studio;
    if (!studio) return Promise.reject(new Error('the timeline is not connected'));
    this.loading ??= import('./timeline-bar').then(
      (code) => (this.loaded = new code.TimelineBar(this.els, studio, { want: () => this.want(), deriveAt: (t) => this.deriveAt(t) })),
      (error: unknown) => {
        this.loading = undefined; // the next Play tries again
        throw error;
      },
    );
    return this.loading;
  }

  /** N when the plant on screen is derived at t (a timed or stepwise grammar), else null. */
  timedSpan(): number | null {
    return this.studio?.timedSpan() ?? null;
  }

  /**
   * A movie poses the plant (`on`) or is done: meanwhile the timeline pauses and asks for no time
   * of its own (each plant shown or build delivered would have it ask for its t again).
   */
  pose(on: boolean): void {
    this.loaded?.pose(on);
  }

  /** Play / pause the growth. */
  toggle(): void {
    void this.load().then((bar) => bar.toggle());
  }

  /**
   * A build was delivered: the bar shows its steps (the plant may still be on its way to the GPU).
   * Whether builds carry growth arrays follows the plant on screen: if this build's grammar turned
   * timed or stepwise (or stopped being), it is built again as the options now say.
   */
  delivered(): void {
    this.loaded?.stepsChanged();
    if (this.growthWanted) this.studio?.rebuild(); // (nothing when the options are the same)
  }

  /**
   * A delivered build for the String and Derivation panels: given to them at once, or while the
   * growth plays at the bar's pace (./panel-pace.ts: at most 4 a second, the newest at Pause).
   */
  handOver(build: HandOver): void {
    if (this.loaded) this.loaded.handOver(build);
    else build.give();
  }

  /** Another text is opened: playing stops, the plant shows whole. */
  clear(): void {
    this.timedAt = null;
    this.loaded?.clear();
  }

  /** What a share link keeps of the timeline (nothing until it was used). */
  toShared(): SharedGrowth | undefined {
    return this.loaded?.toShared();
  }

  /** A link's timeline: the bar loads and takes it (growth arrays are asked for if it has a time). */
  applyShared(growth: SharedGrowth | undefined): void {
    if (growth) void this.load().then((bar) => bar.applyShared(growth));
  }
}
