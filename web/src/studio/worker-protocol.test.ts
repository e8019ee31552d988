import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { buildPlant, initCore } from '../core';
import { transferablesOf } from './worker-protocol';

await initCore(readFileSync(new URL('../../../crate/pkg/meristem_bg.wasm', import.meta.url)));

describe('transferablesOf', () => {
  it('lists the buffer of every array of a build once, and moving them leaves nothing behind', () => {
    const build = buildPlant('#iterations 2\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF');
    const buffers = transferablesOf(build);
    const arrays = [...Object.values(build.mesh), build.origins].filter((a) => a.byteLength > 0);
    expect(arrays.length).toBeGreaterThanOrEqual(6);
    for (const array of arrays) expect(buffers).toContain(array.buffer);
    expect(new Set(buffers).size).toBe(buffers.length);
    // What postMessage does with a transfer list: the buffers move, the originals detach.
    const moved = structuredClone(build, { transfer: buffers });
    expect(moved.mesh.positions.length).toBeGreaterThan(0);
    expect(build.mesh.positions.length).toBe(0);
  });
});
