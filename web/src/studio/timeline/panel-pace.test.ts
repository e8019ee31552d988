import { describe, expect, it } from 'vitest';
import { PANELS_EVERY_MS, PanelPace } from './panel-pace';

/** A pace whose clock and timers the test turns; `log` says what was given and dropped. */
function setup() {
  const state = { playing: false, now: 0, timers: [] as { at: number; callback: () => void }[], log: [] as string[] };
  const pace = new PanelPace(() => state.playing, {
    now: () => state.now,
    after: (ms, callback) => {
      const timer = { at: state.now + ms, callback };
      state.timers.push(timer);
      return timer;
    },
    cancel: (handle) => (state.timers = state.timers.filter((t) => t !== handle)),
  });
  const build = (name: string) => ({ give: () => state.log.push(`give ${name}`), drop: () => state.log.push(`drop ${name}`) });
  const wait = (ms: number) => {
    state.now += ms;
    const due = state.timers.filter((t) => t.at <= state.now);
    state.timers = state.timers.filter((t) => t.at > state.now);
    for (const t of due) t.callback();
  };
  return { state, pace, build, wait };
}

describe('PanelPace', () => {
  it('gives every build at once when the growth is not playing (scrubbing, stepping)', () => {
    const { state, pace, build } = setup();
    pace.offer(build('a'));
    pace.offer(build('b'));
    expect(state.log).toEqual(['give a', 'give b']);
  });

  it('while playing, gives the newest build at most every PANELS_EVERY_MS, dropping those passed over', () => {
    const { state, pace, build, wait } = setup();
    state.playing = true;
    pace.offer(build('1'));
    expect(state.log, 'the first at once').toEqual(['give 1']);
    wait(30);
    pace.offer(build('2'));
    wait(30);
    pace.offer(build('3'));
    expect(state.log, 'held').toEqual(['give 1', 'drop 2']);
    wait(PANELS_EVERY_MS - 60);
    expect(state.log, 'the newest, a pace after the first').toEqual(['give 1', 'drop 2', 'give 3']);
    wait(PANELS_EVERY_MS);
    expect(state.log, 'nothing new, nothing given').toEqual(['give 1', 'drop 2', 'give 3']);
    expect(state.timers).toEqual([]);
  });

  it('gives the build held at once when Play pauses', () => {
    const { state, pace, build, wait } = setup();
    state.playing = true;
    pace.offer(build('1'));
    wait(10);
    pace.offer(build('2'));
    state.playing = false;
    pace.flush();
    expect(state.log).toEqual(['give 1', 'give 2']);
    expect(state.timers, 'its timer cancelled').toEqual([]);
    pace.flush();
    expect(state.log, 'nothing held: nothing given').toEqual(['give 1', 'give 2']);
  });
});
