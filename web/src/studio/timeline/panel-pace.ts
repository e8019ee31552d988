// The pace at which the String and Derivation panels follow the growth while it plays (issue 45).
// A timed grammar's plant at t is a build at t, and each build delivered is the plant on screen;
// the panels show it too, but while Play runs they take the newest build at most every
// {@link PANELS_EVERY_MS} (each hand-over asks the worker for the rows in view and, on the
// Derivation tab, the traced derivation, and replaces their DOM: at 30 builds a second that would
// be most of the page's work, for text no one reads at that speed). When Play pauses, or when not
// playing (scrubbing, stepping: each build is a t the user chose), they take it at once.

/** While the growth plays, the panels show the newest build at most this often (ms). */
export const PANELS_EVERY_MS = 250;

/** A build for the panels: given to them, or passed over (its inspector freed). */
export interface HandOver {
  give(): void;
  drop(): void;
}

/** Clock and timers, replaceable for tests. */
export interface PaceClock {
  now(): number;
  after(ms: number, callback: () => void): unknown;
  cancel(handle: unknown): void;
}

const REAL_CLOCK: PaceClock = {
  now: () => performance.now(),
  after: (ms, callback) => setTimeout(callback, ms),
  cancel: (handle) => clearTimeout(handle as ReturnType<typeof setTimeout>),
};

/** Hands builds to the panels: at once, or while playing at most every {@link PANELS_EVERY_MS}. */
export class PanelPace {
  private held: HandOver | undefined;
  private timer: unknown;
  private lastGiven = -Infinity;

  constructor(
    private readonly playing: () => boolean,
    private readonly clock: PaceClock = REAL_CLOCK,
  ) {}

  /** A build delivered: given now, or held (replacing, and dropping, one held before) until its turn. */
  offer(build: HandOver): void {
    this.held?.drop();
    this.held = build;
    const wait = this.playing() ? PANELS_EVERY_MS - (this.clock.now() - this.lastGiven) : 0;
    if (wait <= 0) this.flush();
    else this.timer ??= this.clock.after(wait, () => this.flush());
  }

  /** Gives the build held, if any, now (Play paused). */
  flush(): void {
    if (this.timer !== undefined) this.clock.cancel(this.timer);
    this.timer = undefined;
    const held = this.held;
    this.held = undefined;
    if (!held) return;
    this.lastGiven = this.clock.now();
    held.give();
  }
}
