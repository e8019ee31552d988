// Step / play / pause over the derivation: step −/+ shows one iteration fewer or more; play shows
// 0, 1, 2, … up to the grammar's iterations at a few steps per second, each step waiting until the
// previous one is on screen (a slow grammar plays slower, it never queues builds).

/** What playback drives: the iterations shown, through the iterations box. */
export interface PlaybackHost {
  /** The iteration on screen: the override, or the grammar's own. */
  shown(): number;
  /** The grammar's `#iterations`. */
  grammarIterations(): number;
  /** Asks for iteration `n`, or the grammar's own (`undefined`); a build follows. */
  show(n: number | undefined): void;
}

/** Options of {@link Playback}; the timer functions are replaceable for tests. */
export interface PlaybackOptions {
  stepsPerSecond?: number;
  /** Largest iteration step + goes to. */
  maxIterations?: number;
  now?: () => number;
  setTimer?: (action: () => void, ms: number) => unknown;
  clearTimer?: (timer: unknown) => void;
}

/** The state machine behind the step and play buttons. */
export class Playback {
  private playingNow = false;
  private waitingForBuild = false;
  private lastStepAt = 0;
  private timer: unknown;
  private readonly listeners = new Set<(playing: boolean) => void>();
  private readonly intervalMs: number;
  private readonly maxIterations: number;
  private readonly now: () => number;
  private readonly setTimer: (action: () => void, ms: number) => unknown;
  private readonly clearTimer: (timer: unknown) => void;

  constructor(
    private readonly host: PlaybackHost,
    options: PlaybackOptions = {},
  ) {
    this.intervalMs = 1000 / (options.stepsPerSecond ?? 3);
    this.maxIterations = options.maxIterations ?? 30;
    this.now = options.now ?? (() => performance.now());
    this.setTimer = options.setTimer ?? ((action, ms) => setTimeout(action, ms));
    this.clearTimer = options.clearTimer ?? ((timer) => clearTimeout(timer as ReturnType<typeof setTimeout>));
  }

  get playing(): boolean {
    return this.playingNow;
  }

  /** Calls `listener` when playing starts or stops. */
  onPlayingChange(listener: (playing: boolean) => void): void {
    this.listeners.add(listener);
  }

  /** Pauses and shows `delta` iterations more (or fewer), within 0 … maxIterations. */
  stepBy(delta: number): void {
    this.pause();
    const next = Math.min(this.maxIterations, Math.max(0, this.host.shown() + delta));
    if (next !== this.host.shown()) this.host.show(next);
  }

  /** Plays from 0 (or from the iteration shown, if below the grammar's) up to the grammar's iterations. */
  play(): void {
    if (this.playingNow) return;
    this.setPlaying(true);
    const start = this.host.shown() < this.host.grammarIterations() ? this.host.shown() : 0;
    this.stepTo(start);
  }

  /** Stops playing; the iteration shown stays. */
  pause(): void {
    if (this.timer !== undefined) this.clearTimer(this.timer);
    this.timer = undefined;
    this.waitingForBuild = false;
    if (this.playingNow) this.setPlaying(false);
  }

  toggle(): void {
    if (this.playingNow) this.pause();
    else this.play();
  }

  /** The host calls this when a build is on screen: playing goes on after the step interval. */
  shownBuild(): void {
    if (!this.playingNow || !this.waitingForBuild) return;
    this.waitingForBuild = false;
    const wait = Math.max(0, this.lastStepAt + this.intervalMs - this.now());
    this.timer = this.setTimer(() => {
      this.timer = undefined;
      this.stepTo(this.host.shown() + 1);
    }, wait);
  }

  private stepTo(n: number): void {
    if (!this.playingNow) return;
    this.lastStepAt = this.now();
    if (n >= this.host.grammarIterations()) {
      this.host.show(undefined);
      this.pause();
      return;
    }
    this.waitingForBuild = true;
    this.host.show(n);
  }

  private setPlaying(playing: boolean): void {
    this.playingNow = playing;
    for (const listener of this.listeners) listener(playing);
  }
}
