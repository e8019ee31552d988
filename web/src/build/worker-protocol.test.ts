import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { initCore, inspectPlant } from '../core';
import { answerTransferables, transferablesOf } from './worker-protocol';

await initCore(readFileSync(new URL('../../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));

describe('transferablesOf', () => {
  it('lists the buffer of every array of a build once, and moving them leaves nothing behind', () => {
    const { build, inspector, gpu } = inspectPlant('#iterations 2\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF', {}, { forGpu: true });
    inspector.free();
    const buffers = transferablesOf(build, gpu);
    const arrays = [...Object.values(build.mesh), build.origins, gpu.normals, gpu.colors].filter((a) => a !== undefined && a.byteLength > 0); // (growth arrays absent: undefined)
    expect(arrays.length).toBeGreaterThanOrEqual(6);
    for (const array of arrays) expect(buffers).toContain(array.buffer);
    expect(new Set(buffers).size).toBe(buffers.length);
    // What postMessage does with a transfer list: the buffers move, the originals detach.
    const moved = structuredClone(build, { transfer: buffers });
    expect(moved.mesh.positions.length).toBeGreaterThan(0);
    expect(build.mesh.positions.length).toBe(0);
  });
});

describe('answerTransferables', () => {
  it('moves an explanation’s module lists, and nothing for other answers', () => {
    const lists = [new Uint32Array([1, 2]), new Uint32Array([3]), new Uint32Array(0)];
    const explanation = { production: 0, fired: 1, contextMatched: 1, conditionFailed: 0, produced: lists[0], leftContext: lists[1], rightContext: lists[2] };
    expect(answerTransferables(explanation)).toEqual([lists[0].buffer, lists[1].buffer]);
    expect(answerTransferables(['F'])).toEqual([]);
    expect(answerTransferables(null)).toEqual([]);
    expect(answerTransferables('abc')).toEqual([]);
  });
});
