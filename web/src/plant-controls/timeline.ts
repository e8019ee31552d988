// The timeline of a plant's growth (issue 45): the growth time t (in derivation steps, 0 … N, see
// the view's ./growth.ts), played at a speed in steps per second, looped or not, over a range
// [from, to], one `show(t)` per animation frame. Showing a t costs the host one uniform (no
// build): the timeline never waits for anything but the next frame. The studio's timeline bar and
// `<meristem-plant animate>` drive it.

/** What the timeline drives: a plant that can be shown at any growth time of [0, span()]. */
export interface TimelineHost {
  /** N, the growth time of the whole plant; null while the plant shown cannot grow (no growth arrays yet). */
  span(): number | null;
  /** Shows the plant at growth time `t`. */
  show(t: number): void;
}

/** The speeds offered, in steps per second. */
export const TIMELINE_SPEEDS = [0.25, 0.5, 1, 2, 4] as const;
/** The slowest and fastest speed accepted (from a link or an attribute), in steps per second. */
export const SPEED_MIN = 0.05;
export const SPEED_MAX = 20;
/** The largest growth time accepted (a step count far past any derivation's limit). */
export const TIME_MAX = 1_000_000;
/** A frame longer than this (a tab in the background, a stall) advances t by this much time only. */
const LONGEST_FRAME_S = 0.25;

/** Options of {@link Timeline}; the clock and frame functions are replaceable for tests. */
export interface TimelineOptions {
  speed?: number;
  loop?: boolean;
  now?: () => number;
  requestFrame?: (callback: () => void) => unknown;
  cancelFrame?: (handle: unknown) => void;
}

/** What the timeline's listeners are told. */
export interface TimelineState {
  t: number;
  playing: boolean;
  speed: number;
  loop: boolean;
  /** The range played, within [0, span]. */
  from: number;
  to: number;
  /** N, or null while the plant cannot grow. */
  span: number | null;
}

/** A finite number clamped to [low, high], or `fallback`. */
export function clampedNumber(value: unknown, low: number, high: number, fallback: number): number {
  const n = typeof value === 'number' ? value : typeof value === 'string' && value.trim() !== '' ? Number(value) : NaN;
  return Number.isFinite(n) ? Math.min(high, Math.max(low, n)) : fallback;
}

/** The state machine of growth playback: play, pause, scrub, speed, loop and range. */
export class Timeline {
  private time = 0;
  private playingNow = false;
  private speedNow: number;
  private loopNow: boolean;
  /** The range asked for; `to` null: up to the end (N, whatever it is). */
  private rangeFrom = 0;
  private rangeTo: number | null = null;
  private frame: unknown;
  private lastFrameAt = 0;
  private readonly listeners = new Set<(state: TimelineState) => void>();
  private readonly now: () => number;
  private readonly requestFrame: (callback: () => void) => unknown;
  private readonly cancelFrame: (handle: unknown) => void;

  constructor(
    private readonly host: TimelineHost,
    options: TimelineOptions = {},
  ) {
    this.speedNow = clampedNumber(options.speed, SPEED_MIN, SPEED_MAX, 1);
    this.loopNow = options.loop ?? false;
    this.now = options.now ?? (() => performance.now());
    this.requestFrame = options.requestFrame ?? ((callback) => requestAnimationFrame(callback));
    this.cancelFrame = options.cancelFrame ?? ((handle) => cancelAnimationFrame(handle as number));
  }

  /** The state now (t, playing, speed, loop, range and span). */
  get state(): TimelineState {
    const span = this.host.span();
    const [from, to] = this.range(span);
    return { t: this.time, playing: this.playingNow, speed: this.speedNow, loop: this.loopNow, from, to, span };
  }

  get t(): number {
    return this.time;
  }

  get playing(): boolean {
    return this.playingNow;
  }

  /** Calls `listener` whenever the state changes (every frame while playing); returns the function that stops it. */
  onChange(listener: (state: TimelineState) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** [from, to] clamped to [0, span] (to ≥ from); [from, to] as asked while there is no span. */
  private range(span: number | null): [number, number] {
    const end = span ?? Math.max(this.rangeFrom, this.rangeTo ?? this.rangeFrom);
    const to = Math.min(end, this.rangeTo ?? end);
    const from = Math.min(Math.max(0, this.rangeFrom), to);
    return [from, Math.max(from, to)];
  }

  /**
   * Plays from t (from the range's start when t is at or past its end, or before its start) at the
   * speed chosen. While the plant cannot grow yet (no span), it waits, playing, for one that can.
   */
  play(): void {
    if (this.playingNow) return;
    this.playingNow = true;
    const span = this.host.span();
    if (span !== null) {
      const [from, to] = this.range(span);
      if (this.time >= to || this.time < from) this.time = from;
      this.host.show(this.time);
    }
    this.lastFrameAt = this.now();
    this.frame = this.requestFrame(this.tick);
    this.changed();
  }

  /** Stops playing; t stays. */
  pause(): void {
    if (this.frame !== undefined) this.cancelFrame(this.frame);
    this.frame = undefined;
    if (!this.playingNow) return;
    this.playingNow = false;
    this.changed();
  }

  toggle(): void {
    if (this.playingNow) this.pause();
    else this.play();
  }

  /** Shows growth time `t`, clamped to [0, span] (scrubbing; playing goes on from there). */
  seek(t: number): void {
    const span = this.host.span();
    this.time = clampedNumber(t, 0, span ?? TIME_MAX, this.time);
    if (span !== null) this.host.show(this.time);
    this.changed();
  }

  /** Pauses and moves t by `delta` steps (e.g. ±1, or ±0.1 for a fine step). */
  stepBy(delta: number): void {
    this.pause();
    this.seek(this.time + delta);
  }

  /** The speed in steps per second, clamped to [{@link SPEED_MIN}, {@link SPEED_MAX}]. */
  setSpeed(speed: number): void {
    this.speedNow = clampedNumber(speed, SPEED_MIN, SPEED_MAX, this.speedNow);
    this.changed();
  }

  /** Whether playing starts again at the range's start when it reaches its end. */
  setLoop(loop: boolean): void {
    this.loopNow = loop;
    this.changed();
  }

  /**
   * The range played: [from, to] (`to` null or not a finite number: up to the end), clamped to
   * [0, span] when played.
   */
  setRange(from: number, to: number | null): void {
    this.rangeFrom = clampedNumber(from, 0, TIME_MAX, 0);
    this.rangeTo = to === null || !Number.isFinite(to) ? null : clampedNumber(to, this.rangeFrom, TIME_MAX, this.rangeFrom);
    this.changed();
  }

  /**
   * The plant shown changed (a new build, perhaps with another span): t is clamped to it and shown
   * again, if the plant can grow.
   */
  refresh(): void {
    const span = this.host.span();
    if (span === null) return;
    this.time = Math.min(span, Math.max(0, this.time));
    this.host.show(this.time);
    this.changed();
  }

  /** Stops playing and forgets the listeners (the host goes away). */
  dispose(): void {
    this.pause();
    this.listeners.clear();
  }

  private readonly tick = (): void => {
    this.frame = undefined;
    if (!this.playingNow) return;
    const now = this.now();
    const seconds = Math.min(LONGEST_FRAME_S, Math.max(0, (now - this.lastFrameAt) / 1000));
    this.lastFrameAt = now;
    const span = this.host.span();
    if (span !== null) this.advance(seconds, span);
    if (this.playingNow) this.frame = this.requestFrame(this.tick);
  };

  /** Moves t on by `seconds` of playing within the range; at its end loops or stops. */
  private advance(seconds: number, span: number): void {
    const [from, to] = this.range(span);
    if (this.time < from || this.time > to) this.time = from;
    let t = this.time + seconds * this.speedNow;
    if (t >= to) {
      if (this.loopNow && to > from) t = from + ((t - to) % (to - from));
      else {
        t = to;
        this.playingNow = false;
      }
    }
    this.time = t;
    this.host.show(t);
    this.changed();
  }

  private changed(): void {
    const state = this.state;
    for (const listener of this.listeners) listener(state);
  }
}

// The growth shown at t (a timed grammar derived at t), for the same hosts as the timeline.
export { GrowthShow, type GrowthView, type TimedBuilds } from './timed-growth';
