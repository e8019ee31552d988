import { describe, expect, it } from 'vitest';
import { GrowthShow } from './timed-growth';

/** A view with growth arrays of span `growthSpan`, and builds that stay under way until `arrive()`. */
function setup({ timedSpan = null as number | null, growthSpan = 4 as number | null } = {}) {
  const state = { timedSpan, growthSpan, viewT: undefined as number | null | undefined, asked: [] as (number | null)[], underWay: 0, at: null as number | null };
  const show = new GrowthShow(
    { growthSpan: () => state.growthSpan, setGrowthTime: (t) => (state.viewT = t) },
    {
      timedSpan: () => state.timedSpan,
      // As the studio and the embed do: a change of time asks for a build, the same time none.
      deriveAt: (t) => {
        if (t === state.at) return;
        state.at = t;
        state.asked.push(t);
        state.underWay++;
      },
      busy: () => state.underWay > 0,
    },
  );
  const arrive = () => {
    state.underWay = Math.max(0, state.underWay - 1);
    show.delivered();
  };
  return { state, show, arrive };
}

describe('GrowthShow', () => {
  it('grows a grammar that is not timed on the GPU: no build, the view at t, whole at the span’s end', () => {
    const { state, show } = setup();
    expect(show.span()).toBe(4);
    expect(show.show(2.5)).toBe(false);
    expect(state.viewT).toBe(2.5);
    expect(show.show(4)).toBe(true);
    expect(state.viewT).toBeNull();
    expect(state.asked, 'no build for a grammar grown on the GPU').toEqual([]);
  });

  it('derives a timed grammar at t: its span is its iterations, its plant drawn whole, whole at t ≥ N', () => {
    const { state, show, arrive } = setup({ timedSpan: 6, growthSpan: null });
    expect(show.span()).toBe(6);
    expect(show.show(2.5)).toBe(true);
    expect(state.viewT, 'the plant derived at t is drawn whole').toBeNull();
    expect(state.asked).toEqual([2.5]);
    arrive();
    show.show(6);
    expect(state.asked, 'at N: the grammar’s own iterations').toEqual([2.5, null]);
  });

  it('paces builds while playing: a time shown while a build is under way waits, and only the newest is asked for', () => {
    const { state, show, arrive } = setup({ timedSpan: 6 });
    show.show(1);
    show.show(1.1);
    show.show(1.2);
    expect(state.asked, 'one build under way at a time').toEqual([1]);
    arrive();
    expect(state.asked, 'the newest time wanted meanwhile, once the build arrived').toEqual([1, 1.2]);
    arrive();
    expect(state.asked, 'nothing more is wanted').toEqual([1, 1.2]);
    show.show(1.2);
    expect(state.asked, 'the time on screen is not built again').toEqual([1, 1.2]);
  });

  it('asks for the newest time after a build of something else (an edit) arrives', () => {
    const { state, show, arrive } = setup({ timedSpan: 6 });
    state.underWay = 1; // an edit's build
    show.show(3);
    expect(state.asked).toEqual([]);
    arrive();
    expect(state.asked).toEqual([3]);
  });
});
