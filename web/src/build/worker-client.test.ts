import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { BuildStage } from '../core';
import { FakeJobWorker } from './fake-job-worker';
import { BuildClient, type BuildOutcome, type WorkerLike } from './worker-client';
import type { InspectAnswer, PostedBuild, WorkerRequest, WorkerResponse } from './worker-protocol';

/** A build worker that records requests and answers when the test says so. */
class FakeWorker extends FakeJobWorker<WorkerRequest, WorkerResponse> implements WorkerLike {
  /** The build requests received. */
  get requests() {
    return this.messages.filter((m) => m.kind === 'build');
  }
  /** Answers request `id` (default: the last one) with a build whose `derived` is its source. */
  answer(id = this.requests.at(-1)!.id): void {
    const request = this.requests.find((r) => r.id === id)!;
    const build = { ok: true, derived: request.source } as unknown as PostedBuild;
    this.send({ kind: 'built', id, build, workerMillis: 1, studioCore: false } as WorkerResponse);
  }
  crash(id = this.requests.at(-1)!.id): void {
    this.send({ kind: 'crashed', id, message: 'RuntimeError: unreachable' });
  }
  /** Answers the last question asked. */
  reply(answer: InspectAnswer): void {
    const question = this.messages.filter((m) => m.kind === 'inspect').at(-1)!;
    this.send({ kind: 'inspected', id: question.id, answer });
  }
  /** Sends the sketch of request `id` (default: the last one). */
  sketch(id = this.requests.at(-1)!.id): void {
    const sketch = { lines: new Float32Array(6), lineColors: new Float32Array(6), flat: false, segments: 1 };
    this.send({ kind: 'sketch', id, sketch });
  }
  /** Tells request `id`'s progress (default: the last one's). */
  progress(step: number, steps: number, id = this.requests.at(-1)!.id, stage: BuildStage = 'deriving'): void {
    this.send({ kind: 'progress', id, progress: { stage, step, steps } });
  }
  override fail(message = 'no module'): void {
    super.fail(message);
  }
}

let workers: FakeWorker[];
let clock: number;
let client: BuildClient;
const latest = () => workers.at(-1)!;
const source = (outcome: BuildOutcome) => (outcome.kind === 'built' ? outcome.result.build.derived : outcome.kind);

beforeEach(() => {
  vi.useFakeTimers();
  workers = [];
  clock = 0;
  client = new BuildClient(
    () => {
      workers.push(new FakeWorker());
      return latest();
    },
    { now: () => clock, abandonAfterMs: 2000 },
  );
});

afterEach(() => {
  vi.useRealTimers();
});

describe('BuildClient: delivering builds', () => {
  it('delivers a build and its round trip time', async () => {
    const outcome = client.request('A', { iterations: 3 });
    expect(latest().requests).toEqual([{ kind: 'build', id: 1, source: 'A', options: { iterations: 3 } }]);
    clock = 40;
    latest().answer();
    const result = await outcome;
    expect(result.kind).toBe('built');
    if (result.kind === 'built') {
      expect(result.result.source).toBe('A');
      expect(result.result.roundTripMillis).toBe(40);
    }
  });

  it("hands a big plant's sketch to the running request before its build, and drops a superseded one's", async () => {
    const sketched: string[] = [];
    const a = client.request('A', {}, { onSketch: () => sketched.push('A') });
    latest().sketch(1);
    expect(sketched).toEqual(['A']);
    const b = client.request('B', {}, { onSketch: () => sketched.push('B') });
    latest().sketch(1); // A is superseded: its sketch is not shown
    expect(sketched).toEqual(['A']);
    expect(source(await a)).toBe('superseded');
    latest().answer(1);
    latest().sketch(2);
    latest().answer(2);
    expect(source(await b)).toBe('B');
    expect(sketched).toEqual(['A', 'B']);
  });

  it('runs one build at a time and keeps only the newest waiting request', async () => {
    const a = client.request('A', {});
    const b = client.request('B', {});
    const c = client.request('C', {});
    expect(latest().requests.map((r) => r.source)).toEqual(['A']);
    expect(source(await a)).toBe('superseded');
    expect(source(await b)).toBe('superseded');
    latest().answer(1); // A's answer arrives late: dropped, and C goes out
    expect(latest().requests.map((r) => r.source)).toEqual(['A', 'C']);
    latest().answer();
    expect(source(await c)).toBe('C');
    expect(workers).toHaveLength(1);
  });

  it('never delivers a stale build, even when its answer comes after the newer request', async () => {
    const outcomes: string[] = [];
    void client.request('old', {}).then((o) => outcomes.push(source(o)));
    void client.request('new', {}).then((o) => outcomes.push(source(o)));
    latest().answer(1);
    latest().answer(2);
    await vi.runAllTimersAsync();
    expect(outcomes).toEqual(['superseded', 'new']);
  });

  it('terminates a worker stuck on an outdated build for 2 s and sends the newest request to a new one', async () => {
    void client.request('slow', {});
    clock = 500;
    const fresh = client.request('fresh', {});
    await vi.advanceTimersByTimeAsync(1400);
    expect(workers).toHaveLength(1);
    clock = 2000;
    await vi.advanceTimersByTimeAsync(100);
    expect(workers).toHaveLength(2);
    expect(workers[0].terminated).toBe(true);
    expect(latest().requests.map((r) => r.source)).toEqual(['fresh']);
    workers[0].answer(1); // the old worker's answer (if any) is ignored
    latest().answer();
    expect(source(await fresh)).toBe('fresh');
    expect(client.workersStarted).toBe(2);
  });

  it('lets a long build finish when nothing newer is asked', async () => {
    const slow = client.request('slow', {});
    clock = 10_000;
    await vi.advanceTimersByTimeAsync(10_000);
    latest().answer();
    expect(source(await slow)).toBe('slow');
    expect(workers).toHaveLength(1);
  });

  it('reports a crash and builds the next request on a fresh worker', async () => {
    const broken = client.request('panic', {});
    latest().crash();
    expect(await broken).toEqual({ kind: 'crashed', message: 'RuntimeError: unreachable' });
    expect(workers[0].terminated).toBe(true);
    const next = client.request('fine', {});
    expect(workers).toHaveLength(2);
    latest().answer();
    expect(source(await next)).toBe('fine');
  });
});

describe('BuildClient: the studio core and kept builds', () => {
  it('has the worker load the studio core once asked, and every worker that replaces it', async () => {
    const first = client.request('A', {});
    expect(latest().messages.filter((m) => m.kind === 'studio-core')).toHaveLength(0);
    client.useStudioCore();
    client.useStudioCore(); // once is enough
    expect(latest().messages.filter((m) => m.kind === 'studio-core')).toHaveLength(1);
    latest().crash();
    await first;
    const second = client.request('B', {});
    expect(workers).toHaveLength(2);
    expect(latest().messages.map((m) => m.kind)).toEqual(['studio-core', 'build']);
    latest().answer();
    expect(source(await second)).toBe('B');
  });

  it('asks the worker about a kept build, and frees it once', async () => {
    const outcome = client.request('A', {});
    latest().answer();
    const result = await outcome;
    if (result.kind !== 'built') throw new Error('not built');
    const hash = result.result.inspector.derivedHash();
    expect(latest().messages.at(-1)).toEqual({ kind: 'inspect', id: 1, build: 1, question: 'derivedHash', args: [] });
    latest().reply('00ff00ff00ff00ff');
    expect(await hash).toBe('00ff00ff00ff00ff');
    const texts = result.result.inspector.moduleTexts(0, 2);
    expect(latest().messages.at(-1)).toMatchObject({ question: 'moduleTexts', args: [0, 2] });
    latest().reply(['F', '+']);
    expect(await texts).toEqual(['F', '+']);
    result.result.inspector.free();
    result.result.inspector.free();
    expect(latest().messages.filter((m) => m.kind === 'free')).toEqual([{ kind: 'free', build: 1 }]);
    expect(await result.result.inspector.explain(0)).toBeNull();
  });

  it('frees the kept build of a superseded request as soon as it arrives', async () => {
    void client.request('old', {});
    void client.request('new', {});
    latest().answer(1);
    expect(latest().messages).toContainEqual({ kind: 'free', build: 1 });
  });

  // Was: "answers questions with empty answers once the worker that kept the build is gone". The
  // plant stays on the page after its worker goes, so its panels must go on answering (issue 19):
  // only a question the worker took with it gets the empty answer.
  it('answers a question the worker took with it empty; later ones from a fresh worker that keeps the build again', async () => {
    const outcome = client.request('A', { iterations: 3 });
    latest().answer();
    const result = await outcome;
    if (result.kind !== 'built') throw new Error('not built');
    const open = result.result.inspector.explain(3); // asked, never answered
    void client.request('B', {});
    latest().crash();
    expect(await open).toBeNull();
    expect(workers).toHaveLength(1);
    const texts = result.result.inspector.moduleTexts(0, 5);
    expect(workers, 'a fresh worker').toHaveLength(2);
    expect(latest().messages).toEqual([
      { kind: 'keep', build: 3, source: 'A', options: { iterations: 3 } },
      { kind: 'inspect', id: 2, build: 3, question: 'moduleTexts', args: [0, 5] },
    ]);
    latest().reply(['F', '[']);
    expect(await texts).toEqual(['F', '[']);
    expect(client.rekept).toBe(1);
  });

  it('keeps the plant on screen answering after Stop: built again once by the new worker, freed there', async () => {
    const shown = client.request('shown', { seed: 7 });
    latest().answer();
    const result = await shown;
    if (result.kind !== 'built') throw new Error('not built');
    const slow = client.request('slow', {});
    expect(client.stop()).toBe(true);
    expect(await slow).toEqual({ kind: 'stopped' });
    const fresh = latest();
    expect(fresh).not.toBe(workers[0]);
    const sequence = result.result.inspector.sequence(100);
    const hash = result.result.inspector.derivedHash();
    expect(fresh.messages.filter((m) => m.kind === 'keep'), 'built again once').toEqual([{ kind: 'keep', build: 3, source: 'shown', options: { seed: 7 } }]);
    expect(fresh.messages.filter((m) => m.kind === 'inspect').map((m) => m.kind === 'inspect' && m.build)).toEqual([3, 3]);
    fresh.reply('0123456789abcdef');
    expect(await hash).toBe('0123456789abcdef');
    const answered = fresh.messages.filter((m) => m.kind === 'inspect')[0];
    // The first question is answered too (the fake replies to the last one asked only).
    (fresh as unknown as { onMessage: (e: { data: WorkerResponse }) => void }).onMessage({ data: { kind: 'inspected', id: answered.kind === 'inspect' ? answered.id : 0, answer: [] } });
    expect(await sequence).toEqual([]);
    // A build after it is asked of the same worker, after the kept one.
    void client.request('next', {});
    expect(fresh.messages.at(-1)).toMatchObject({ kind: 'build', source: 'next' });
    result.result.inspector.free();
    expect(fresh.messages.at(-1)).toEqual({ kind: 'free', build: 3 });
    expect(workers[0].messages.filter((m) => m.kind === 'free'), 'nothing sent to the dead worker').toEqual([]);
  });

});

describe('BuildClient: progress, Stop and failures', () => {
  it("forwards the running request's progress while it is wanted", async () => {
    const told: string[] = [];
    const watch = (name: string) => ({ onProgress: (p: { step: number; steps: number }) => told.push(`${name} ${p.step}/${p.steps}`) });
    const a = client.request('A', {}, watch('A'));
    latest().progress(1, 4);
    void client.request('B', {}, watch('B'));
    latest().progress(2, 4, 1); // A is superseded: its progress is not shown
    expect(source(await a)).toBe('superseded');
    latest().answer(1);
    latest().progress(3, 9);
    expect(told).toEqual(['A 1/4', 'B 3/9']);
  });

  it('stops a running build and a waiting one: the worker is terminated, the next request gets a fresh one', async () => {
    expect(client.stop(), 'nothing to stop').toBe(false);
    const a = client.request('slow', {});
    const b = client.request('newer', {});
    expect(client.busy).toBe(true);
    expect(client.stop()).toBe(true);
    expect(source(await a)).toBe('superseded');
    expect(await b).toEqual({ kind: 'stopped' });
    expect(workers[0].terminated).toBe(true);
    expect(client.busy).toBe(false);
    expect(workers, 'a fresh worker is started at once').toHaveLength(2);
    workers[0].answer(1); // a late answer of the terminated worker changes nothing
    const next = client.request('next', {});
    expect(workers).toHaveLength(2);
    expect(workers[1].requests.map((r) => r.source)).toEqual(['next']);
    latest().answer();
    expect(source(await next)).toBe('next');
  });

  it('stops a build while the environment answers: the pass is ended with its worker', async () => {
    const told: string[] = [];
    const slow = client.request('light', {}, { onProgress: (p) => told.push(`${p.stage} ${p.step}/${p.steps}`) });
    latest().progress(3, 40);
    latest().progress(3, 40, undefined, 'environment');
    expect(told).toEqual(['deriving 3/40', 'environment 3/40']);
    expect(client.stop()).toBe(true);
    expect(await slow).toEqual({ kind: 'stopped' });
    expect(workers[0].terminated, 'the pass runs in the worker: terminated, it ends at once').toBe(true);
    workers[0].progress(4, 40, undefined, 'environment'); // the dead worker's late word is not shown
    expect(told).toHaveLength(2);
  });

  it('reports a worker that fails to start', async () => {
    const outcome = client.request('A', {});
    latest().fail();
    expect(await outcome).toEqual({ kind: 'crashed', message: 'the build worker failed: no module' });
  });
});
