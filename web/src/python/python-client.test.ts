import { describe, expect, it, vi } from 'vitest';
import { FakeJobWorker } from '../build/fake-job-worker';
import { PythonClient, RUN_MARGIN_S, type PythonState } from './python-client';
import type { PythonWorkerRequest, PythonWorkerResponse } from './python-protocol';
import type { PythonRunRequest } from './python-runner';

class FakePythonWorker extends FakeJobWorker<PythonWorkerRequest, PythonWorkerResponse> {}

const request: PythonRunRequest = { files: { 'a.lpy': 'Axiom: F' }, main: 'a.lpy', options: { steps: null, seed: 0, time_limit: 0.02 } };
const result = { ok: true, dialect: 'lpy', steps: 1, lstring: 'F', materials: [], notes: [], error: null };

/** A client over fake workers; `made` lists every worker it started. */
function client(): { python: PythonClient; made: FakePythonWorker[] } {
  const made: FakePythonWorker[] = [];
  const python = new PythonClient(
    () => {
      const worker = new FakePythonWorker();
      made.push(worker);
      return worker;
    },
    () => 'http://site/pyodide/',
  );
  return { python, made };
}

describe('PythonClient', () => {
  it('runs a model, says when Python loads and when it runs, and keeps the worker for the next model', async () => {
    const { python, made } = client();
    const states: PythonState[] = [];
    const job = python.run(request, (state) => states.push(state));
    expect(made[0].messages).toEqual([{ indexURL: 'http://site/pyodide/', run: request }]);
    made[0].send({ kind: 'loading' });
    made[0].send({ kind: 'running' });
    made[0].send({ kind: 'done', result: JSON.stringify(result), millis: 5 });
    const outcome = await job.done;
    expect(outcome).toMatchObject({ kind: 'done', result: { ok: true, steps: 1 }, millis: 5 });
    expect(states).toEqual(['loading', 'running']);
    expect(made[0].terminated).toBe(false);
    const second = python.run(request);
    expect(made).toHaveLength(1);
    made[0].send({ kind: 'running' });
    made[0].send({ kind: 'done', result: JSON.stringify({ ...result, ok: false }), millis: 1 });
    expect(await second.done).toMatchObject({ kind: 'done', result: { ok: false } });
  });

  it('stops a run by terminating its worker; a late answer changes nothing, and the next run starts a new worker', async () => {
    const { python, made } = client();
    const job = python.run(request);
    made[0].send({ kind: 'running' });
    job.stop();
    expect(made[0].terminated).toBe(true);
    made[0].send({ kind: 'done', result: JSON.stringify(result), millis: 1 });
    expect(await job.done).toEqual({ kind: 'stopped' });
    python.run(request);
    expect(made).toHaveLength(2);
  });

  it('stops a model that outlives the runtime time limit (plus a margin), and a new run stops the one under way', async () => {
    vi.useFakeTimers();
    try {
      const { python, made } = client();
      const first = python.run(request);
      const second = python.run(request);
      expect(await first.done).toEqual({ kind: 'stopped' });
      expect(made[0].terminated).toBe(true);
      made[1].send({ kind: 'running' });
      vi.advanceTimersByTime((0.02 + RUN_MARGIN_S) * 1000 - 10);
      expect(made[1].terminated).toBe(false);
      vi.advanceTimersByTime(20);
      expect(await second.done).toEqual({ kind: 'timeout', seconds: 0.02 + RUN_MARGIN_S });
      expect(made[1].terminated).toBe(true);
    } finally {
      vi.useRealTimers();
    }
  });

  it('reports a worker that cannot start, Python that does not start, and an answer that is not a result', async () => {
    const { python, made } = client();
    const a = python.run(request);
    made[0].fail();
    expect(await a.done).toEqual({ kind: 'failed', message: 'the Python worker failed: it could not start' });
    const b = python.run(request);
    made[1].send({ kind: 'failed', message: 'Python could not start: 404' });
    expect(await b.done).toEqual({ kind: 'failed', message: 'Python could not start: 404' });
    const c = python.run(request);
    made[2].send({ kind: 'done', result: '[1, 2]', millis: 1 });
    expect(await c.done).toEqual({ kind: 'failed', message: 'the Python runtime answered something that is not a result' });
  });
});
