import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { initCore, inspectPlant } from '../core';
import { answerTransferables, progressWanted, PROGRESS_INTERVAL, transferablesOf } from './worker-protocol';

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

describe('progressWanted', () => {
  it('lets the environment pass through after a step at once, and steps and passes in time', () => {
    const soon = PROGRESS_INTERVAL / 2;
    expect(progressWanted('', 'parsing', 0), 'a stage start').toBe(true);
    expect(progressWanted('deriving', 'deriving', soon), 'a step soon after a step').toBe(false);
    expect(progressWanted('deriving', 'environment', soon), 'the pass after a step, however soon').toBe(true);
    expect(progressWanted('environment', 'deriving', soon), 'a step soon after a pass').toBe(false);
    expect(progressWanted('environment', 'environment', soon), 'a pass soon after a pass').toBe(false);
    expect(progressWanted('environment', 'deriving', PROGRESS_INTERVAL), 'a step in time').toBe(true);
    expect(progressWanted('environment', 'interpreting', soon), 'the next stage').toBe(true);
  });
});
