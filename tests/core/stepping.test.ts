// Stepping that is incremental (issue 45), on the real WebAssembly core through the facade: a build
// continued from a kept build of fewer steps (`inspectPlant`'s `from`, what the build worker does for
// a step forward and Play) gives the same arrays as a build from the axiom, and derives only the new
// steps; what cannot be continued is built from the axiom, to the same plant.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { inspectPlant, type BuildOptions, type PlantBuild, type PlantInspector } from '../../web/src/core';

const DT = `#define dt 0.01
axiom: X(0)
X(k) : k < 7 -> /(137.5)[&(35)X(k+1)]X(k+1)
X(k) : k >= 7 -> A(0)
A(t) -> A(t + dt)
homomorphism:
A(t) -> F(0.05 + t)
`;

/** Every array and number of a plain build but its timings (which a clock measures). */
function comparable(build: PlantBuild): unknown {
  const { timings: _timings, continuedFrom: _from, ...rest } = build;
  return rest;
}

/** The build from the axiom, its inspector freed. */
function fresh(source: string, options: BuildOptions): PlantBuild {
  const { build, inspector } = inspectPlant(source, options);
  inspector.free();
  return build;
}

/** Builds `source` with `options` on `from`: the plain build, its inspector kept by the caller. */
function on(source: string, options: BuildOptions, from?: PlantInspector): { build: PlantBuild; inspector: PlantInspector } {
  return inspectPlant(source, options, { from });
}

describe('a build continued from a kept one', () => {
  it('is the build from the axiom, array for array, and derives only the new steps', () => {
    let kept = on(DT, { iterations: 12 }).inspector;
    let previous = 12;
    for (const n of [13, 14, 20]) {
      const continued = on(DT, { iterations: n }, kept);
      const whole = fresh(DT, { iterations: n });
      expect(continued.build.continuedFrom).toBe(previous);
      expect(whole.continuedFrom).toBeUndefined();
      expect(comparable(continued.build)).toEqual(comparable(whole));
      expect(continued.build.mesh.positions.length).toBeGreaterThan(0);
      kept.free();
      kept = continued.inspector;
      previous = n;
    }
    kept.free();
  });

  it('keeps its questions answered: module texts of the continued string', async () => {
    const kept = on(DT, { iterations: 8 }).inspector;
    const continued = on(DT, { iterations: 10 }, kept);
    const whole = on(DT, { iterations: 10 });
    expect(await continued.inspector.moduleTexts(0, 40)).toEqual(await whole.inspector.moduleTexts(0, 40));
    expect(await continued.inspector.lastStep()).toEqual(await whole.inspector.lastStep());
    for (const i of [kept, continued.inspector, whole.inspector]) i.free();
  });

  it('is built from the axiom for a step back, another seed, or a grammar that reads MaxIt', () => {
    const stochastic = 'axiom: A\nA -> (1) A[+F]\nA -> (1) A[-F]F\n';
    const kept = on(stochastic, { iterations: 6, seed: 3 }).inspector;
    for (const options of [{ iterations: 5, seed: 3 }, { iterations: 8, seed: 4 }]) {
      const built = on(stochastic, options, kept);
      expect(built.build.continuedFrom).toBeUndefined();
      expect(comparable(built.build)).toEqual(comparable(fresh(stochastic, options)));
      built.inspector.free();
    }
    const forward = on(stochastic, { iterations: 9, seed: 3 }, kept);
    expect(forward.build.continuedFrom).toBe(6);
    expect(comparable(forward.build)).toEqual(comparable(fresh(stochastic, { iterations: 9, seed: 3 })));
    const maxIt = 'axiom: A(0)\nA(x) -> F(1) [+(x)F] A(x + MaxIt)\n';
    const before = on(maxIt, { iterations: 3 }).inspector;
    const after = on(maxIt, { iterations: 5 }, before);
    expect(after.build.continuedFrom).toBeUndefined();
    expect(comparable(after.build)).toEqual(comparable(fresh(maxIt, { iterations: 5 })));
    for (const i of [kept, forward.inspector, before, after.inspector]) i.free();
  });

  it('continues a gallery tree step by step to the build from the axiom', () => {
    const source = readFileSync(new URL('../../public/examples/abop-1.24d.lsys', import.meta.url), 'utf8');
    let kept = on(source, { iterations: 2 }).inspector;
    for (const n of [3, 4, 5]) {
      const continued = on(source, { iterations: n }, kept);
      expect(continued.build.continuedFrom).toBe(n - 1);
      expect(comparable(continued.build)).toEqual(comparable(fresh(source, { iterations: n })));
      kept.free();
      kept = continued.inspector;
    }
    kept.free();
  });
});
