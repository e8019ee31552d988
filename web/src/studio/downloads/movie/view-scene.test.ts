import { describe, expect, it } from 'vitest';
import type { FilmFrames, PictureLook, PlantView } from '../../../view';
import { growthSpanOf, viewScene } from './view-scene';

/** A view that films into a fake canvas and records what is asked of it; with `growth`, it has issue 45's growth API. */
function fakeView(growth: { span: number | null } | null) {
  const calls: string[] = [];
  const film: FilmFrames = {
    turn: (angle) => void calls.push(`turn ${angle}`),
    draw: (width, height) => (calls.push(`draw ${width}×${height}`), { width, height } as HTMLCanvasElement),
    close: () => void calls.push('close'),
  };
  const view: Record<string, unknown> = { film: async (look: PictureLook) => (calls.push(`film ${look.background}`), film) };
  if (growth) {
    view.growthSpan = () => growth.span;
    view.setGrowthTime = (t: number | null) => void calls.push(`time ${t}`);
  }
  return { view: view as unknown as PlantView, calls };
}

describe('the view as a FrameScene', () => {
  it('sets the growth time and the turn of each frame, draws at the size, and shows the plant whole after', async () => {
    const { view, calls } = fakeView({ span: 7 });
    expect(growthSpanOf(view)).toBe(7);
    const scene = await viewScene(view, { background: 'white' });
    await scene.at(2.5, 0.5);
    expect(scene.draw(320, 240)).toEqual({ width: 320, height: 240 });
    scene.close();
    expect(calls).toEqual(['film white', 'time 2.5', 'turn 0.5', 'draw 320×240', 'time null', 'close']);
  });

  it('turns the whole plant where the view has no growth API yet, or its plant no growth times', async () => {
    for (const growth of [null, { span: null }]) {
      const { view, calls } = fakeView(growth);
      expect(growthSpanOf(view)).toBeNull();
      const scene = await viewScene(view, { background: 'view' });
      await scene.at(3, 1);
      scene.draw(16, 16);
      scene.close();
      expect(calls).toEqual(['film view', 'turn 1', 'draw 16×16', 'close']);
    }
  });
});
