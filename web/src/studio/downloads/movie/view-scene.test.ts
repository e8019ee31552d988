import { describe, expect, it } from 'vitest';
import type { FilmFrames, PictureLook, PlantView } from '../../../view';
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
});
