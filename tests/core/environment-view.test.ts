// What a build knows of its environment, for the views (issue 47), through the facade on the real
// wasm: the studio core's builds carry the light grid (its values as a typed array, within [0, 1]),
// the obstacles' solids, the attraction points left and the names of a `?E`'s reply values; the
// first plant's core and a grammar without an environment carry none.
import { readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { buildPlant, initCore, inspectPlant } from '../../web/src/core';
import { startStudioCore } from '../../web/src/core/studio-core';

beforeAll(async () => {
  await initCore(readFileSync(new URL('../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));
  await startStudioCore();
});

const LIT = [
  '#environment light',
  '#environment obstacle sphere center 2 1 0 radius 0.5',
  '#environment attractors box min -3 0 -3 max 3 6 3 count 500 kill 0.6',
  '#iterations 4',
  '#angle 30',
  'axiom: A',
  'A -> F [ + F ?E(0, 0, 0, 0, 0, 0, 0, 0, 0, 0) A ] [ & F ?E(0, 0, 0, 0, 0, 0, 0, 0, 0, 0) A ]',
].join('\n');

function built(source: string) {
  const { build, inspector } = inspectPlant(source);
  inspector.free();
  return build;
}

describe("a build's environment through the facade", () => {
  it('carries the light grid, the sphere, the points left and the reply words', () => {
    const build = built(LIT);
    expect([...build.diagnostics]).toEqual([]);
    const environment = build.environment!;
    expect(environment.replies).toEqual(['exposure', 'dx', 'dy', 'dz', 'free', 'distance', 'count', 'dx', 'dy', 'dz']);
    expect(environment.fields).toHaveLength(1);
    const [grid] = environment.fields;
    expect(grid.name).toBe('light');
    expect(grid.values).toBeInstanceOf(Float32Array);
    expect(grid.values.length).toBe(grid.dims[0] * grid.dims[1] * grid.dims[2]);
    expect(grid.values.every((v) => v >= 0 && v <= 1)).toBe(true);
    expect(Math.min(...grid.values)).toBeCloseTo(grid.min, 6);
    expect(Math.max(...grid.values)).toBeCloseTo(grid.max, 6);
    expect(grid.min).toBeLessThan(grid.max); // the plant shades some voxels
    expect(environment.solids).toEqual([{ shape: 'sphere', center: [2, 1, 0], radius: 0.5 }]);
    // Points the plant passed near were killed; the rest are left, inside the box.
    const points = environment.points;
    expect(points.length % 3).toBe(0);
    expect(points.length / 3).toBeGreaterThan(0);
    expect(points.length / 3).toBeLessThan(500);
    for (let i = 0; i < points.length; i += 3) {
      expect(Math.abs(points[i])).toBeLessThanOrEqual(3);
      expect(points[i + 1]).toBeGreaterThanOrEqual(0);
    }
  });

  it('is absent without an environment, and from the first plant\'s core', () => {
    expect(built('axiom: F').environment).toBeUndefined();
    expect(buildPlant(LIT).environment).toBeUndefined();
  });

  it("the derivation view's sequence shows each step's ?E as the environment answered it", async () => {
    // The shoot of docs/LANGUAGE.md's example: its apex rises 1 a step towards a box whose floor is
    // at y = 2.5; after step k it stands at y = k, so the box is 2.5 - k away, and inside after 3.
    const source = ['#environment obstacle box min -1 2.5 -1 max 1 10 1', '#iterations 4', 'axiom: A ?E(1, 0)', 'A > ?E(f, d) : f == 1 -> F A', 'A > ?E(f, d) : f == 0 -> B'].join('\n');
    const { inspector } = inspectPlant(source);
    try {
      const steps = await inspector.sequence(1000);
      expect(steps!.map((step) => step.texts.at(-1))).toEqual(['?E(1,2.5)', '?E(1,1.5)', '?E(1,0.5)', '?E(0,-0.5)', '?E(0,-0.5)']);
    } finally {
      inspector.free();
    }
  });
});
