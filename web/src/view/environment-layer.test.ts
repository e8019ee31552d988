import { describe, expect, it } from 'vitest';
import { heatColour, heatRange, HEAT_STOPS, layersOf, liveliestLayer } from './environment-layer';
import type { EnvironmentField } from '../core';

function field(dims: [number, number, number], value: (i: number, j: number, k: number) => number): EnvironmentField {
  const values = new Float32Array(dims[0] * dims[1] * dims[2]);
  for (let k = 0; k < dims[2]; k++) for (let j = 0; j < dims[1]; j++) for (let i = 0; i < dims[0]; i++) values[i + dims[0] * (j + dims[1] * k)] = value(i, j, k);
  return { program: 0, name: 'light', origin: [0, 0, 0], cell: 1, dims, min: 0, max: 1, values };
}

describe('the heat map', () => {
  it('runs from its first stop to its last, clamped, and between stops linearly', () => {
    expect(heatColour(0)).toEqual([...HEAT_STOPS[0]]);
    expect(heatColour(1)).toEqual([...HEAT_STOPS[HEAT_STOPS.length - 1]]);
    expect(heatColour(-3)).toEqual(heatColour(0));
    expect(heatColour(Number.NaN)).toEqual(heatColour(0));
    const [a, b] = [HEAT_STOPS[0], HEAT_STOPS[1]];
    expect(heatColour(0.125)).toEqual([0, 1, 2].map((c) => Math.round((a[c] + b[c]) / 2)));
    // Lightness rises: the light end is the brightest.
    const sum = (c: readonly number[]) => c[0] + c[1] + c[2];
    for (let s = 1; s < HEAT_STOPS.length; s++) expect(sum(HEAT_STOPS[s])).toBeGreaterThan(sum(HEAT_STOPS[s - 1]));
  });

  it("spans the grid's own range, 1 wide when its values are all one", () => {
    expect(heatRange({ min: 0.8, max: 1 })).toEqual([0.8, 1]);
    expect(heatRange({ min: 1, max: 1 })).toEqual([1, 2]);
  });

  it('finds the layer of most spread: the shade under a crown, not the open sky', () => {
    // 4 × 5 × 3: full light everywhere but layer y = 2, half of it shaded.
    const f = field([4, 5, 3], (i, j) => (j === 2 && i < 2 ? 0.2 : 1));
    expect(layersOf(f, 'y')).toBe(5);
    expect(layersOf(f, 'z')).toBe(3);
    expect(layersOf(f, 'none')).toBe(0);
    expect(liveliestLayer(f, 'y')).toBe(2);
    // Upright, every layer z holds the same shade: the first.
    expect(liveliestLayer(f, 'z')).toBe(0);
  });
});
