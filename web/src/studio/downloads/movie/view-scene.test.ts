import { describe, expect, it } from 'vitest';
import type { FilmFrames, PictureLook, PlantView } from '../../../view';
import type { DerivedGrowth } from './derived-growth';
import { growthSpanOf, viewScene } from './view-scene';

/** A view that films into a fake canvas and records what is asked of it; its plant has growth times over `span` steps (null: none). */
function fakeView(span: number | null) {
  const calls: string[] = [];
  const film: FilmFrames = {
    turn: (angle) => void calls.push(`turn ${angle}`),
    draw: (width, height) => (calls.push(`draw ${width}×${height}`), { width, height } as HTMLCanvasElement),
    close: () => void calls.push('close'),
  };
  const view = {
    film: async (look: PictureLook) => (calls.push(`film ${look.background}`), film),
    growthSpan: () => span,
    setGrowthTime: (t: number | null) => void calls.push(`time ${t}`),
    growthReady: Promise.resolve(),
    holdFrame: (holder: string, on: boolean) => void calls.push(`hold ${holder} ${on}`),
  };
  return { view: view as unknown as PlantView, calls };
}

describe('the view as a FrameScene', () => {
  it('sets the growth time and the turn of each frame (as on screen: lines grow too), draws at the size, and shows the plant whole after', async () => {
    const { view, calls } = fakeView(7);
    expect(growthSpanOf(view)).toBe(7);
    const scene = await viewScene(view, { background: 'white' });
    await scene.at(2.5, 0.5);
    expect(scene.draw(320, 240)).toEqual({ width: 320, height: 240 });
    scene.close();
    expect(calls).toEqual(['film white', 'time 2.5', 'turn 0.5', 'draw 320×240', 'time null', 'close']);
  });

  it('turns the whole plant where the plant has no growth times', async () => {
    const { view, calls } = fakeView(null);
    expect(growthSpanOf(view)).toBeNull();
    const scene = await viewScene(view, { background: 'view' });
    await scene.at(3, 1);
    scene.draw(16, 16);
    scene.close();
    expect(calls).toEqual(['film view', 'turn 1', 'draw 16×16', 'close']);
  });

  it('derives a timed or stepwise plant at each frame’s time (whole first, its frame held), and puts the studio back after', async () => {
    const { view, calls } = fakeView(null);
    const derived: DerivedGrowth = {
      span: 6,
      show: async (t) => void calls.push(`derive ${t}`),
      restore: () => void calls.push('restore'),
    };
    expect(growthSpanOf(view, derived)).toBe(6);
    const scene = await viewScene(view, { background: 'white' }, derived);
    await scene.at(2.5, 0.25);
    scene.draw(32, 24);
    scene.close();
    scene.close();
    expect(() => scene.draw(32, 24), 'no frame after the movie').toThrow(/closed/);
    expect(calls).toEqual(['derive 6', 'hold movie true', 'film white', 'derive 2.5', 'turn 0.25', 'draw 32×24', 'close', 'hold movie false', 'restore']);
  });

  it('puts the studio back when the whole plant cannot be built', async () => {
    const { view, calls } = fakeView(null);
    const derived: DerivedGrowth = {
      span: 6,
      show: () => Promise.reject(new Error('the grammar has errors at t = 6')),
      restore: () => void calls.push('restore'),
    };
    await expect(viewScene(view, { background: 'white' }, derived)).rejects.toThrow('errors at t = 6');
    expect(calls).toEqual(['restore']);
  });
});
