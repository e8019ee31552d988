// Declared surfaces (`#surface`, `#patch`) through the facade on the real wasm: the first plant's
// core (crate/pkg-core, no room for them in its first load) says the grammar declares surfaces and
// draws none, as the build worker needs to know to build it again with the studio core, which
// draws them; the studio core's inspector lists each `#patch` point with the text of its numbers.
import { readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { buildPlant, initCore, inspectPlant } from '../../web/src/core';
import { startStudioCore } from '../../web/src/core/studio-core';

beforeAll(async () => {
  await initCore(readFileSync(new URL('../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));
  await startStudioCore();
});

const POINTS = Array.from({ length: 16 }, (_, k) => `${k % 4} ${Math.floor(k / 4)} 0`).join(', ');
const FLOWER = `#surface p petal\n#patch b ${POINTS}\naxiom: F~p(2)~b`;

describe('declared surfaces through the facade', () => {
  it('the first plant’s core says they are declared and leaves them to the studio core', () => {
    const first = buildPlant(FLOWER);
    expect(first.declaresSurfaces).toBe(true);
    const plain = buildPlant('axiom: F');
    expect(plain.declaresSurfaces).toBe(false);
    // No patch is meshed by the first plant's core: ~p stands in as Meristem's own flat petal (22
    // outline points, two sides) and ~b draws nothing, until the studio core builds it again.
    expect(first.stats.vertices).toBe(plain.stats.vertices + 2 * 22);
  });

  it('the studio core meshes them: 2 patches of the petal and 1 of the bract, both sides', () => {
    const { build, inspector } = inspectPlant(FLOWER);
    try {
      expect(build.declaresSurfaces).toBe(true);
      expect([...build.diagnostics]).toEqual([]);
      const tube = buildPlant('axiom: F').stats.vertices;
      // The petal at precision 8 (9 × 9 points a patch), the bract at 5 (6 × 6), two sides each.
      expect(build.stats.vertices).toBe(tube + 2 * (2 * 81 + 36));
    } finally {
      inspector.free();
    }
  });
});
