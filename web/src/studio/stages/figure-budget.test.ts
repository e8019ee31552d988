import { describe, expect, it } from 'vitest';
import type { StagePlant } from '../../view/stages-view';
import { FigureBudget, MAX_FIGURE_BYTES, plantBytes } from './stages';

/** A plant of `positions` floats of position, as many of normal, and `lines` floats of lines. */
function plant(caption: string, positions: number, lines = 0): StagePlant {
  const mesh = { positions: new Float32Array(positions), normals: new Float32Array(positions), indices: new Uint32Array(0) };
  const sketch = { lines: new Float32Array(lines), lineColors: new Float32Array(lines) };
  return { mesh: mesh as unknown as StagePlant['mesh'], lines: sketch, flat: false, bounds: [[0, 0, 0], [1, 1, 1]], caption };
}

describe("a figure's memory budget (Stages, Variants)", () => {
  it('counts every array a plant holds in the page', () => {
    expect(plantBytes(plant('n = 1', 30, 12))).toBe(4 * (30 + 30 + 12 + 12));
    expect(MAX_FIGURE_BYTES).toBe(512 * 2 ** 20);
  });

  it('keeps the plants that fit, leaves out the one that would pass it and says so, and keeps smaller ones after it', () => {
    const budget = new FigureBudget(1000);
    const kept = [plant('n = 1', 50), plant('n = 2', 60), plant('n = 3', 100), plant('seed 2, n = 1', 10)].map((p) => budget.keep(p));
    expect(kept.map((p) => p.mesh !== null)).toEqual([true, true, false, true]);
    expect(kept[2].caption).toMatch(/^n = 3: left out \(over [\d.]+ MB\)$/);
    expect(budget.leftOut).toBe(1);
    expect(budget.words()).toContain('1 left out: the figure would hold more than');
    expect(new FigureBudget().words()).toBe('');
  });
});
