// Growth in time across the boundary (docs/LANGUAGE.md, "Growth in time"): the REAL wasm core's
// growth arrays, through the facade and the build worker's transfer list. The studio core
// (crate/pkg, feature `growth`) makes them; the first plant's (crate/pkg-core) has no room for
// them and ignores the option.
import { readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { buildPlant, initCore, initIo, inspectPlant, type BuildOptions, type PlantBuild } from '../../web/src/core';
import { startStudioCore } from '../../web/src/core/studio-core';
import { postedBuild, transferablesOf } from '../../web/src/build/worker-protocol';

beforeAll(async () => {
  await initCore(readFileSync(new URL('../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));
  await initIo(readFileSync(new URL('../../crate/pkg/meristem_bg.wasm', import.meta.url)));
  await startStudioCore();
});

/** A build by the studio core (what the build worker makes once it is loaded). */
function studioBuild(source: string, options: BuildOptions): PlantBuild {
  const { build, inspector } = inspectPlant(source, options);
  inspector.free();
  return build;
}

const TREE = '#angle 20\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF';

/** Where vertex `v` is at growth time `t`: the formula of interfaces.md (smoothstep). */
function grownAt(positions: Float32Array, origins: Float32Array, times: Float32Array, v: number, t: number): number[] {
  const [t0, t1] = [times[2 * v], times[2 * v + 1]];
  const x = Math.min(1, Math.max(0, (t - t0) / (t1 - t0)));
  const g = x * x * (3 - 2 * x);
  return [0, 1, 2].map((k) => origins[3 * v + k] + (positions[3 * v + k] - origins[3 * v + k]) * g);
}

describe('the growth arrays', () => {
  it('are absent unless asked for, and from the first plant’s core', () => {
    const plant = studioBuild(TREE, { iterations: 3 });
    expect(plant.mesh.growthOrigins).toBeUndefined();
    expect(plant.mesh.growthTimes).toBeUndefined();
    const first = buildPlant(TREE, { iterations: 3, growth: true });
    expect(first.mesh.growthTimes).toBeUndefined();
    expect(first.mesh.positions.length).toBe(plant.mesh.positions.length);
  });

  it('hold an origin and (t0, t1) per vertex within [−1, N], the plant growing from its base', () => {
    const n = 4;
    // A trunk segment first, so that step 0's plant has something to draw.
    const plant = studioBuild(TREE.replace('axiom: X', 'axiom: FX'), { iterations: n, growth: true });
    const { positions, growthOrigins, growthTimes } = plant.mesh;
    if (!growthOrigins || !growthTimes) throw new Error('no growth arrays');
    const vertices = positions.length / 3;
    expect(vertices).toBeGreaterThan(0);
    expect(growthOrigins.length).toBe(3 * vertices);
    expect(growthTimes.length).toBe(2 * vertices);
    let whole = 0;
    for (let v = 0; v < vertices; v++) {
      const [t0, t1] = [growthTimes[2 * v], growthTimes[2 * v + 1]];
      expect(t0).toBeGreaterThanOrEqual(-1);
      expect(t1).toBeGreaterThan(t0);
      expect(t1).toBeLessThanOrEqual(n);
      if (t1 <= 0) whole++;
    }
    // The axiom's plant (one segment's tube) is whole at 0, the rest grows after.
    expect(whole).toBeGreaterThan(0);
    expect(whole).toBeLessThan(vertices);
    // The plant grows all the time (its vertices' distances from their origins, summed), never
    // shrinks in height, and is the whole plant at N.
    const grown = (t: number): [number, number] => {
      let [size, top] = [0, -Infinity];
      for (let v = 0; v < vertices; v++) {
        const p = grownAt(positions, growthOrigins, growthTimes, v, t);
        size += Math.hypot(p[0] - growthOrigins[3 * v], p[1] - growthOrigins[3 * v + 1], p[2] - growthOrigins[3 * v + 2]);
        top = Math.max(top, p[1]);
      }
      return [size, top];
    };
    const times = [0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4];
    const sizes = times.map(grown);
    for (let k = 1; k < sizes.length; k++) {
      expect(sizes[k][0], `at ${times[k]}`).toBeGreaterThan(sizes[k - 1][0]);
      expect(sizes[k][1], `at ${times[k]}`).toBeGreaterThanOrEqual(sizes[k - 1][1]);
    }
    expect(sizes[sizes.length - 1][1]).toBeCloseTo(plant.stats.bounds[1][1], 4);
  });

  it('move to the page with the build worker’s transfer list', () => {
    const { build, inspector, gpu } = inspectPlant(TREE, { iterations: 3, growth: true }, { forGpu: true });
    inspector.free();
    const { growthOrigins, growthTimes } = build.mesh;
    if (!growthOrigins || !growthTimes) throw new Error('no growth arrays');
    const buffers = transferablesOf(postedBuild(build), gpu);
    expect(buffers).toContain(growthOrigins.buffer);
    expect(buffers).toContain(growthTimes.buffer);
  });
});
