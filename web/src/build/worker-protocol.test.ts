import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { initCore, inspectPlant } from '../core';
import { answerTransferables, postedBuild, progressWanted, PROGRESS_INTERVAL, receivedBuild, transferablesOf, type PostedBuild } from './worker-protocol';

await initCore(readFileSync(new URL('../../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));

describe('transferablesOf', () => {
  it('lists the buffer of every array of a build once, and moving them leaves nothing behind', () => {
    const { build, inspector, gpu } = inspectPlant('#iterations 2\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF', {}, { forGpu: true });
    inspector.free();
    const posted = postedBuild(build);
    const buffers = transferablesOf(posted, gpu);
    const arrays = [...Object.values(build.mesh), build.origins, gpu.normals, gpu.colors].filter((a) => a !== undefined && a.byteLength > 0); // (growth arrays absent: undefined)
    expect(arrays.length).toBeGreaterThanOrEqual(6);
    for (const array of arrays) expect(buffers).toContain(array.buffer);
    expect(new Set(buffers).size).toBe(buffers.length);
    // What postMessage does with a transfer list: the buffers move, the originals detach.
    const moved = structuredClone(posted, { transfer: buffers });
    expect(moved.mesh.positions.length).toBeGreaterThan(0);
    expect(build.mesh.positions.length).toBe(0);
  });

  it('moves 100,000 diagnostics as a few arrays, not 100,000 objects the page would deserialise (issue 50)', () => {
    const { build, inspector, gpu } = inspectPlant(`axiom: F\n${'?\n'.repeat(100_000)}`, {}, { forGpu: true });
    inspector.free();
    const posted: PostedBuild = postedBuild(build);
    const buffers: ArrayBufferLike[] = transferablesOf(posted, gpu);
    expect(arrayBuffersIn(posted).filter((b) => b.byteLength > 0 && !buffers.includes(b)), 'buffers copied, not moved').toEqual([]);
    const moved = structuredClone(posted, { transfer: buffers as ArrayBuffer[] });
    // Everything the page deserialises but the bytes of its typed arrays (moved, not copied).
    expect(objectsIn(moved), 'objects and strings in the posted build').toBeLessThan(200);
    const received = receivedBuild(moved);
    expect(received.diagnostics).toHaveLength(100_000);
    expect(received.diagnostics.at(99_999)).toMatchObject({ severity: 'error', code: 'E0105', line: 100_001, column: 1 });
  });
});

/** The objects and strings reachable from `value`, a typed array counted as one. */
function objectsIn(value: unknown, seen = new Set<unknown>()): number {
  if (typeof value === 'string') return 1;
  if (typeof value !== 'object' || value === null || seen.has(value)) return 0;
  seen.add(value);
  if (ArrayBuffer.isView(value)) return 1;
  return 1 + Object.values(value).reduce((sum: number, v) => sum + objectsIn(v, seen), 0);
}

/** The buffers of the typed arrays reachable from `value`. */
function arrayBuffersIn(value: unknown, seen = new Set<unknown>()): ArrayBufferLike[] {
  if (typeof value !== 'object' || value === null || seen.has(value)) return [];
  seen.add(value);
  if (ArrayBuffer.isView(value)) return [value.buffer];
  return Object.values(value).flatMap((v) => arrayBuffersIn(v, seen));
}

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
