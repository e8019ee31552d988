import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { FakeJobWorker } from '../build/fake-job-worker';
import type { BuildOutcome, WorkerLike } from '../build';
import type { PostedBuild, WorkerRequest, WorkerResponse } from '../build/worker-protocol';
import { SharedBuilds } from './shared-builds';

/** A build worker that answers when the test says so. */
class FakeWorker extends FakeJobWorker<WorkerRequest, WorkerResponse> implements WorkerLike {
  get requests() {
    return this.messages.filter((m) => m.kind === 'build');
  }
  answer(): void {
    const request = this.requests.at(-1)!;
    const build = { ok: true, derived: request.source } as unknown as PostedBuild;
    this.send({ kind: 'built', id: request.id, build, workerMillis: 1, studioCore: false } as WorkerResponse);
  }
}

let workers: FakeWorker[];
let builds: SharedBuilds;
const latest = () => workers.at(-1)!;
const what = (outcome: BuildOutcome) => (outcome.kind === 'built' ? outcome.result.build.derived : outcome.kind);
const settled = () => new Promise((resolve) => setTimeout(resolve, 0));

beforeEach(() => {
  workers = [];
  builds = new SharedBuilds(() => {
    workers.push(new FakeWorker());
    return latest();
  });
});

afterEach(() => vi.useRealTimers());

describe('SharedBuilds', () => {
  it('stops the running build of a plant that left the page, and goes on with the others (issue 50, 9a)', async () => {
    const stuck = {};
    const other = {};
    const first = builds.build(stuck, 'never ends', {});
    const second = builds.build(other, 'F', {});
    await settled();
    expect(latest().requests.map((r) => r.source)).toEqual(['never ends']);
    builds.forget(stuck);
    expect(what(await first)).toBe('stopped');
    await settled();
    expect(workers[0].terminated).toBe(true);
    expect(latest().requests.map((r) => r.source)).toEqual(['F']);
    latest().answer();
    expect(what(await second)).toBe('F');
  });

  it('leaves the running build of another plant alone when a plant leaves', async () => {
    const running = builds.build({}, 'A', {});
    builds.forget({});
    await settled();
    expect(workers[0].terminated).toBe(false);
    latest().answer();
    expect(what(await running)).toBe('A');
  });

  it("stops a plant's build that runs on long after the same plant asked again", async () => {
    vi.useFakeTimers();
    const plant = {};
    const slow = builds.build(plant, 'slow', {});
    await vi.advanceTimersByTimeAsync(0);
    const newer = builds.build(plant, 'newer', {});
    await vi.advanceTimersByTimeAsync(1999);
    expect(workers).toHaveLength(1);
    await vi.advanceTimersByTimeAsync(1);
    expect(what(await slow)).toBe('stopped');
    await vi.advanceTimersByTimeAsync(0);
    expect(latest().requests.map((r) => r.source)).toEqual(['newer']);
    latest().answer();
    expect(what(await newer)).toBe('newer');
  });

  it('tells a build its progress', async () => {
    const steps: number[] = [];
    const done = builds.build({}, 'A', {}, (p) => steps.push(p.step));
    await settled();
    const id = latest().requests[0].id;
    latest().send({ kind: 'progress', id, progress: { stage: 'deriving', step: 3, steps: 9 } });
    latest().answer();
    await done;
    expect(steps).toEqual([3]);
  });
});
