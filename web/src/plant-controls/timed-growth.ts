// How a plant is shown at a growth time t, by the studio's timeline and by an embed alike (issue
// 45): a timed grammar (ABOP 6.1, `#terminal_age`) is derived at t (a build of the grammar at time
// t: its modules and their ages at t), any other grows on the GPU from its whole plant's mesh (a
// uniform, no build). Builds at t are paced: a new t is asked for once the build under way has
// arrived, so Play shows each build as it comes, as fast as the worker builds (asked for every
// frame, each request would supersede the build under way, and a slow grammar would show nothing
// until Pause).

/** What growth needs of the view (`PlantView`). */
export interface GrowthView {
  /** N when the plant shown carries growth arrays, else null. */
  growthSpan(): number | null;
  /** Shows the plant at growth time t (null: whole). */
  setGrowthTime(t: number | null): void;
}

/** What showing a timed grammar at t needs of the plant's builds. */
export interface TimedBuilds {
  /**
   * N, the steps a timed grammar's timeline spans (its iterations: the plant at t = N), or null
   * when the plant on screen is not timed.
   */
  timedSpan(): number | null;
  /** Builds from now on derive a timed grammar at `t` (null: at its iterations); a build follows a change. */
  deriveAt(t: number | null): void;
  /** A build is under way: a new time waits for it. */
  busy(): boolean;
}

/** Shows a plant at a growth time: derived at t when timed, grown on the GPU otherwise. */
export class GrowthShow {
  /** The time builds should derive at next (null: the grammar's iterations). */
  private wanted: number | null = null;
  /** {@link wanted} waits for the build under way. */
  private pending = false;

  constructor(
    private readonly view: GrowthView,
    private readonly builds: TimedBuilds,
  ) {}

  /** N, the growth time of the whole plant: a timed grammar's iterations, else its growth arrays' span (null without them). */
  span(): number | null {
    return this.builds.timedSpan() ?? this.view.growthSpan();
  }

  /**
   * Shows growth time `t`. A timed grammar is derived at t (whole at t ≥ N: its own iterations),
   * its plant drawn whole; any other is drawn at t by the view. Returns whether the plant is drawn
   * whole.
   */
  show(t: number): boolean {
    const timedSpan = this.builds.timedSpan();
    this.derive(timedSpan === null || t >= timedSpan ? null : t);
    const span = timedSpan === null ? this.view.growthSpan() : 0;
    const whole = span === null || t >= span;
    this.view.setGrowthTime(whole ? null : t);
    return whole;
  }

  /** A build arrived (or ended): the time wanted meanwhile is asked for now. */
  delivered(): void {
    if (this.pending && !this.builds.busy()) this.flush();
  }

  private derive(t: number | null): void {
    this.wanted = t;
    this.pending = true;
    if (!this.builds.busy()) this.flush();
  }

  private flush(): void {
    this.pending = false;
    this.builds.deriveAt(this.wanted);
  }
}
