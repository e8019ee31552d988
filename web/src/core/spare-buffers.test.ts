import { describe, expect, it } from 'vitest';
import { MAX_SPARE_BYTES, MIN_SPARE_BYTES, SpareBuffers } from './spare-buffers';

const MB = 1 << 20;

/** Spares whose page-touching tasks run when `run` is called, counted. */
function manual(): { spares: SpareBuffers; run: () => number } {
  let tasks: (() => void)[] = [];
  const spares = new SpareBuffers((task) => {
    tasks.push(task);
    return undefined as unknown as ReturnType<typeof setTimeout>;
  });
  const run = () => {
    let count = 0;
    while (tasks.length > 0) {
      const now = tasks;
      tasks = [];
      for (const task of now) task();
      count += now.length;
    }
    return count;
  };
  return { spares, run };
}

describe('spare buffers for a build worker', () => {
  it('holds one buffer per size asked for, at least a megabyte each, and gives each out once', () => {
    const { spares } = manual();
    spares.prepare([12 * MB, 100, 3 * MB, MIN_SPARE_BYTES - 1]);
    expect(spares.bytes).toBe(15 * MB);
    const taken = spares.take(12 * MB);
    expect(taken?.byteLength).toBe(12 * MB);
    expect(spares.take(12 * MB)).toBeUndefined();
    expect(spares.take(100)).toBeUndefined();
    expect(spares.bytes).toBe(3 * MB);
  });

  it('gives a spare up to half as big again as asked, not bigger', () => {
    const { spares } = manual();
    spares.prepare([3 * MB]);
    expect(spares.take(1.9 * MB)).toBeUndefined();
    expect(spares.take(2.1 * MB)?.byteLength).toBe(3 * MB);
    spares.prepare([3 * MB]);
    expect(spares.take(3 * MB + 1)).toBeUndefined();
  });

  it('keeps the spares of sizes asked again and drops the others', () => {
    const { spares } = manual();
    spares.prepare([2 * MB, 4 * MB]);
    spares.prepare([4 * MB, 8 * MB]);
    expect(spares.bytes).toBe(12 * MB);
    expect(spares.take(2 * MB)).toBeUndefined();
  });

  it('holds no more than its cap', () => {
    const { spares } = manual();
    spares.prepare([MAX_SPARE_BYTES / 2, MAX_SPARE_BYTES / 2, 4 * MB]);
    expect(spares.bytes).toBe(MAX_SPARE_BYTES);
  });

  it('touches the spares a few megabytes per task, and stops when all are touched', () => {
    const { spares, run } = manual();
    spares.prepare([20 * MB, 4 * MB]);
    expect(run()).toBe(3); // 24 MB at 8 MB a task
    expect(run()).toBe(0);
    spares.prepare([20 * MB, 4 * MB]); // the same sizes: kept, already touched
    expect(run()).toBe(0);
    spares.take(4 * MB);
    spares.prepare([20 * MB, 4 * MB]); // a new 4 MB one
    expect(run()).toBe(1);
  });

  it('does not touch a spare once it is taken (it may have left with a build)', () => {
    const { spares, run } = manual();
    spares.prepare([16 * MB, 2 * MB]);
    const taken = spares.take(16 * MB)!;
    structuredClone(taken, { transfer: [taken] }); // as posting it to the page does: detached here
    expect(taken.byteLength).toBe(0);
    expect(run()).toBe(1); // touching a detached buffer would throw
  });
});
