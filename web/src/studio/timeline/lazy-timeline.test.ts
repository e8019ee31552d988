import { describe, expect, it } from 'vitest';
import type { PlantView } from '../../view';
import { LazyTimeline, type TimelineElements, type TimelineStudio } from './lazy-timeline';

/** A timeline connected to a studio whose plant on screen is derived at t (`timed`) or grows on the GPU. */
function connected(plant: { timed: boolean; stepwise?: boolean }) {
  let rebuilds = 0;
  const els = { bar: {}, play: { addEventListener: () => {} } } as unknown as TimelineElements;
  const studio: TimelineStudio = {
    view: {} as PlantView,
    rebuild: () => void rebuilds++,
    timedSpan: () => (plant.timed ? 6 : null),
    stepwise: () => plant.stepwise === true,
    steps: () => 6,
    busy: () => false,
  };
  const timeline = new LazyTimeline(els);
  timeline.connect(studio);
  return { timeline, rebuilds: () => rebuilds };
}

describe('the growth arrays the timeline asks the builds for', () => {
  it('are asked for a plant that grows on the GPU, once the timeline is used', () => {
    const { timeline, rebuilds } = connected({ timed: false });
    expect(timeline.buildOptions()).toEqual({});
    timeline.want();
    expect(rebuilds()).toBe(1);
    expect(timeline.buildOptions()).toEqual({ growth: true });
  });

  it('are never asked for a timed or stepwise plant: it is derived at t, its builds go on from the one before', () => {
    const timed = connected({ timed: true });
    timed.timeline.want();
    expect(timed.timeline.buildOptions()).toEqual({});
    timed.timeline.deriveAt(2.5);
    expect(timed.timeline.buildOptions()).toEqual({ time: 2.5 });
    const stepwise = connected({ timed: true, stepwise: true });
    stepwise.timeline.want();
    stepwise.timeline.deriveAt(20.5);
    expect(stepwise.timeline.buildOptions()).toEqual({ iterations: 20 });
  });

  it('follow the plant on screen: a delivered build asks the builds again (the preview builds only if the options changed)', () => {
    const plant = { timed: false };
    const { timeline, rebuilds } = connected(plant);
    timeline.delivered();
    expect(rebuilds(), 'not before the timeline is used').toBe(0);
    timeline.want();
    plant.timed = true; // the text turned timed: its first build carried growth arrays
    timeline.delivered();
    expect(rebuilds()).toBe(2);
    expect(timeline.buildOptions()).toEqual({});
  });
});
