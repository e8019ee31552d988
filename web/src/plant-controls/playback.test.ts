import { describe, expect, it } from 'vitest';
import { Playback, type PlaybackHost } from './playback';

/** A host whose builds land when the test says, and a clock and timers the test turns. */
function setup(grammarIterations = 4) {
  let override: number | undefined;
  const shownLog: (number | undefined)[] = [];
  const host: PlaybackHost = {
    shown: () => override ?? grammarIterations,
    grammarIterations: () => grammarIterations,
    show: (n) => {
      override = n;
      shownLog.push(n);
    },
  };
  let clock = 0;
  let timers: { at: number; action: () => void }[] = [];
  const playback = new Playback(host, {
    stepsPerSecond: 4,
    now: () => clock,
    setTimer: (action, ms) => {
      const timer = { at: clock + ms, action };
      timers.push(timer);
      return timer;
    },
    clearTimer: (timer) => (timers = timers.filter((t) => t !== timer)),
  });
  const advance = (ms: number) => {
    clock += ms;
    const due = timers.filter((t) => t.at <= clock);
    timers = timers.filter((t) => t.at > clock);
    for (const t of due) t.action();
  };
  return { playback, shownLog, advance, timers: () => timers, setOverride: (n: number | undefined) => (override = n) };
}

describe('Playback', () => {
  it('steps one iteration back and forth, never below 0', () => {
    const { playback, shownLog, setOverride } = setup(2);
    playback.stepBy(-1);
    playback.stepBy(-1);
    playback.stepBy(-1);
    expect(shownLog).toEqual([1, 0]);
    setOverride(undefined);
    playback.stepBy(+1);
    expect(shownLog.at(-1)).toBe(3);
  });

  it('plays 0 → the grammar’s iterations at the set pace, one step per build shown', () => {
    const { playback, shownLog, advance } = setup(3);
    const states: boolean[] = [];
    playback.onPlayingChange((p) => states.push(p));
    playback.play();
    expect(shownLog).toEqual([0]);
    advance(100);
    playback.shownBuild(); // built in 100 ms: the next step waits for the 250 ms interval
    advance(100);
    expect(shownLog).toEqual([0]);
    advance(50);
    expect(shownLog).toEqual([0, 1]);
    advance(1000); // a slow build: nothing happens until it is shown
    expect(shownLog).toEqual([0, 1]);
    playback.shownBuild();
    advance(0);
    expect(shownLog).toEqual([0, 1, 2]);
    playback.shownBuild();
    advance(250);
    expect(shownLog).toEqual([0, 1, 2, undefined]); // the last step shows the grammar's own
    expect(playback.playing).toBe(false);
    expect(states).toEqual([true, false]);
  });

  it('pauses where it is, and stepping pauses too', () => {
    const { playback, shownLog, advance, timers } = setup(5);
    playback.play();
    playback.shownBuild();
    advance(250);
    playback.pause();
    expect(timers()).toEqual([]);
    playback.shownBuild();
    advance(1000);
    expect(shownLog).toEqual([0, 1]);
    playback.play(); // resumes from the iteration shown
    expect(shownLog).toEqual([0, 1, 1]);
    playback.stepBy(1);
    expect(playback.playing).toBe(false);
    expect(shownLog.at(-1)).toBe(2);
  });
});
