// L-Py's commands that place the turtle by coordinates (`@LineTo`, `@LineRel`, `@OLineTo`,
// `@OLineRel`, `@R`) and draw its frame (`@Frame`) through the facade on the real wasm: the first
// plant's core (crate/pkg-core, no room for them in its first load) says the grammar uses them and
// draws nothing for them, as the build worker needs to know to build it again with the studio
// core, which draws them (docs/LANGUAGE.md, "Turtle").
import { readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { buildPlant, initCore, inspectPlant } from '../../web/src/core';
import { startStudioCore } from '../../web/src/core/studio-core';

beforeAll(async () => {
  await initCore(readFileSync(new URL('../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));
  await startStudioCore();
});

// L-Py's LineTo.lpy in Meristem's axes, then the frame at its end and one step up.
const LINES = 'axiom: @LineTo(0,3,0)[@LineTo(1,4,0)]@LineTo(0,5,0)@Frame(1)F(1)';

describe('placing the turtle by coordinates through the facade', () => {
  it('the first plant’s core says the grammar uses them and leaves them to the studio core', () => {
    const first = buildPlant(LINES);
    expect(first.placesByCoordinates).toBe(true);
    expect(first.stats.segments).toBe(1);
    expect(buildPlant('axiom: F@M(1,2,3)F').placesByCoordinates).toBe(false);
  });

  it('the studio core draws the three lines, the frame’s three axes and the step', () => {
    const { build, inspector } = inspectPlant(LINES);
    try {
      expect(build.placesByCoordinates).toBe(true);
      expect([...build.diagnostics]).toEqual([]);
      expect(build.stats.segments).toBe(3 + 3 + 1);
      // The step after the frame goes on up from (0, 5, 0): the plant is 6 tall.
      const [low, high] = build.stats.bounds;
      expect(high[1] - low[1]).toBeCloseTo(6, 5);
    } finally {
      inspector.free();
    }
  });
});
