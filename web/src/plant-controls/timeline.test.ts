import { describe, expect, it } from 'vitest';
import { clampedNumber, SPEED_MAX, SPEED_MIN, Timeline, type TimelineOptions, type TimelineState } from './timeline';

/** A host of span `span` (changeable), a clock and animation frames the test turns. */
function setup(span: number | null = 4, options: TimelineOptions = {}) {
  const host = { spanNow: span as number | null, shown: [] as number[] };
  let clock = 0;
  let frames: (() => void)[] = [];
  const timeline = new Timeline(
    { span: () => host.spanNow, show: (t) => host.shown.push(t) },
    {
      now: () => clock,
      requestFrame: (callback) => {
        frames.push(callback);
        return callback;
      },
      cancelFrame: (handle) => (frames = frames.filter((f) => f !== handle)),
      ...options,
    },
  );
  const states: TimelineState[] = [];
  timeline.onChange((state) => states.push(state));
  /** Runs animation frames `ms` apart, `count` times. */
  const frame = (ms: number, count = 1) => {
    for (let k = 0; k < count; k++) {
      clock += ms;
      const due = frames;
      frames = [];
      for (const f of due) f();
    }
  };
  return { host, timeline, states, frame, pending: () => frames.length };
}

describe('Timeline', () => {
  it('plays at its speed in steps per second, one show a frame, and stops at the end', () => {
    const { host, timeline, frame, pending } = setup(4, { speed: 2 });
    timeline.play();
    expect(host.shown).toEqual([0]);
    frame(250); // 0.25 s at 2 steps/s
    expect(timeline.t).toBeCloseTo(0.5, 9);
    frame(250, 7);
    expect(timeline.t).toBe(4);
    expect(timeline.playing).toBe(false);
    expect(pending()).toBe(0);
    expect(host.shown.at(-1)).toBe(4);
    // Every t shown went forward, none past N.
    for (let k = 1; k < host.shown.length; k++) expect(host.shown[k]).toBeGreaterThan(host.shown[k - 1]);
  });

  it('plays from the start again once at the end', () => {
    const { host, timeline, frame } = setup(3);
    timeline.seek(3);
    timeline.play();
    expect(host.shown.at(-1)).toBe(0);
    frame(200);
    expect(timeline.t).toBeCloseTo(0.2, 9);
  });

  it('loops within its range', () => {
    const { timeline, frame } = setup(10, { loop: true, speed: 4 });
    timeline.setRange(2, 3);
    timeline.play();
    expect(timeline.t).toBe(2);
    frame(200); // +0.8
    expect(timeline.t).toBeCloseTo(2.8, 9);
    frame(100); // +0.4 → 3.2 → wraps to 2.2
    expect(timeline.t).toBeCloseTo(2.2, 9);
    expect(timeline.playing).toBe(true);
    timeline.setLoop(false);
    frame(250, 2);
    expect(timeline.t).toBe(3);
    expect(timeline.playing).toBe(false);
  });

  it('clamps the range to the span, and a range past it to its end', () => {
    const { timeline } = setup(4);
    timeline.setRange(1, 99);
    expect([timeline.state.from, timeline.state.to]).toEqual([1, 4]);
    timeline.setRange(7, null);
    expect([timeline.state.from, timeline.state.to]).toEqual([4, 4]);
    timeline.setRange(3, 2);
    expect([timeline.state.from, timeline.state.to]).toEqual([3, 3]);
    timeline.setRange(Number.NaN, Number.POSITIVE_INFINITY);
    expect([timeline.state.from, timeline.state.to]).toEqual([0, 4]);
  });

  it('scrubs to any t within [0, N], and steps pause', () => {
    const { host, timeline, states } = setup(4);
    timeline.seek(2.5);
    expect(host.shown).toEqual([2.5]);
    timeline.seek(-3);
    timeline.seek(12);
    timeline.seek(Number.NaN); // kept
    expect(host.shown).toEqual([2.5, 0, 4, 4]);
    timeline.play();
    timeline.stepBy(-0.1);
    expect(timeline.playing).toBe(false);
    expect(timeline.t).toBe(0); // play restarted at 0 (t was at the end), then −0.1 clamps to 0
    expect(states.at(-1)).toMatchObject({ playing: false, t: 0, span: 4 });
  });

  it('never jumps more than a quarter second of growth after a long frame', () => {
    const { timeline, frame } = setup(100);
    timeline.play();
    frame(5000);
    expect(timeline.t).toBeCloseTo(0.25, 9);
  });

  it('waits, playing, while the plant cannot grow, and starts when it can', () => {
    const { host, timeline, frame } = setup(null);
    timeline.play();
    frame(100, 3);
    expect(host.shown).toEqual([]);
    expect(timeline.playing).toBe(true);
    host.spanNow = 2;
    frame(100);
    expect(host.shown.length).toBe(1);
    expect(timeline.t).toBeCloseTo(0.1, 9);
  });

  it('clamps t to a new plant\'s span on refresh, and shows it again', () => {
    const { host, timeline } = setup(6);
    timeline.seek(5.5);
    host.spanNow = 3;
    timeline.refresh();
    expect(timeline.t).toBe(3);
    expect(host.shown.at(-1)).toBe(3);
    host.spanNow = null;
    timeline.refresh(); // nothing to show
    expect(host.shown.length).toBe(2);
  });

  it('keeps its speed within bounds', () => {
    const { timeline } = setup(4);
    timeline.setSpeed(1000);
    expect(timeline.state.speed).toBe(SPEED_MAX);
    timeline.setSpeed(0);
    expect(timeline.state.speed).toBe(SPEED_MIN);
    timeline.setSpeed(Number.NaN);
    expect(timeline.state.speed).toBe(SPEED_MIN);
  });

  it('pauses and stops asking for frames', () => {
    const { timeline, frame, pending } = setup(4);
    timeline.play();
    expect(pending()).toBe(1);
    timeline.toggle();
    expect(pending()).toBe(0);
    frame(100);
    expect(timeline.t).toBe(0);
  });
});

describe('clampedNumber', () => {
  it('reads numbers and numeric text, clamps, and falls back on anything else', () => {
    expect(clampedNumber('2.5', 0, 4, 1)).toBe(2.5);
    expect(clampedNumber(' 9 ', 0, 4, 1)).toBe(4);
    expect(clampedNumber('', 0, 4, 1)).toBe(1);
    expect(clampedNumber('1e400', 0, 4, 1)).toBe(1);
    expect(clampedNumber({}, 0, 4, 1)).toBe(1);
    expect(clampedNumber(-1, 0, 4, 1)).toBe(0);
  });
});
