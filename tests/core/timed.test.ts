// A timed grammar (ABOP 6.1) through the facade on the real wasm: the build option `time` derives
// it at that growth time, as `meristem derive --at` does.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { inspectPlant } from '../../web/src/core';

const ANABAENA = readFileSync(new URL('../../public/examples/abop-6.1-timed-anabaena.lsys', import.meta.url), 'utf8');

describe('a timed grammar through the facade', () => {
  it.each([
    [undefined, 21],
    [2.5, 3],
    [4, 8],
    [0, 1],
  ])('at time %s has the cells of the filament then (%i)', (time, modules) => {
    const { build, inspector } = inspectPlant(ANABAENA, time === undefined ? {} : { time });
    try {
      expect(build.timed).toBe(true);
      expect(build.stats.modules).toBe(modules);
    } finally {
      inspector.free();
    }
  });

  it('says a grammar without timed modules is not timed', () => {
    const { build, inspector } = inspectPlant('axiom: F\nF -> FF');
    inspector.free();
    expect(build.timed).toBe(false);
  });
});
