// The environment (`#environment`, `#stand`, `?E`; issue 47) through the facade on the real wasm:
// the first plant's core (crate/pkg-core, no room for the environment in its first load) says the
// grammar declares one and leaves `?E` as written, as the build worker needs to know to build it
// again with the studio core, which answers `?E` between steps and plants a stand.
import { readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { buildPlant, initCore, inspectPlant } from '../../web/src/core';
import { startStudioCore } from '../../web/src/core/studio-core';

beforeAll(async () => {
  await initCore(readFileSync(new URL('../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));
  await startStudioCore();
});

// A shoot that stops growing when it reaches a box: after step 3 its apex stands inside the box,
// half a unit above the floor (docs/LANGUAGE.md, "Environment").
const SHOOT = [
  '#environment obstacle box min -1 2.5 -1 max 1 10 1',
  '#iterations 4',
  'axiom: A ?E(1, 0)',
  'A > ?E(f, d) : f == 1 -> F A',
  'A > ?E(f, d) : f == 0 -> B',
].join('\n');

describe('the environment through the facade', () => {
  it('the first plant’s core says it is declared and leaves ?E as written', () => {
    const first = buildPlant(SHOOT);
    expect(first.declaresEnvironment).toBe(true);
    expect(first.derived).toBe('FFFFA?E(1,0)');
    expect(buildPlant('axiom: F').declaresEnvironment).toBe(false);
  });

  it('the studio core answers ?E between steps: the shoot stops in the box', () => {
    const { build, inspector } = inspectPlant(SHOOT);
    try {
      expect(build.declaresEnvironment).toBe(true);
      expect([...build.diagnostics]).toEqual([]);
      expect(build.derived).toBe('FFFB?E(0,-0.5)');
    } finally {
      inspector.free();
    }
  });

  it('the studio core plants a stand of 9, each plant at its place', () => {
    const { build, inspector } = inspectPlant('#stand grid 3 3 spacing 2\n#iterations 2\naxiom: F');
    try {
      expect([...build.diagnostics]).toEqual([]);
      expect(build.derived).toBe(
        '[@M(-2,0,-2)F][@M(0,0,-2)F][@M(2,0,-2)F][@M(-2,0,0)F][@M(0,0,0)F][@M(2,0,0)F][@M(-2,0,2)F][@M(0,0,2)F][@M(2,0,2)F]',
      );
      expect(build.stats.segments).toBe(9);
    } finally {
      inspector.free();
    }
  });
});
