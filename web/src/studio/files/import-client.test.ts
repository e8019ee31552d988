import { describe, expect, it } from 'vitest';
import { FakeJobWorker } from '../../build/fake-job-worker';
import { runImport, type ImportRequest, type ImportResponse } from './import-client';

class FakeImportWorker extends FakeJobWorker<ImportRequest, ImportResponse> {}

const request: ImportRequest = { files: [{ name: 'tree.l', bytes: new TextEncoder().encode('Lsystem: 1\nAxiom: F\nendlsystem\n') }] };

describe('runImport', () => {
  it('imports in the worker, settles with its text and ends the worker', async () => {
    const worker = new FakeImportWorker();
    const job = runImport(() => worker, request);
    expect(worker.messages).toEqual([request]);
    const opened = { ok: true as const, text: 'axiom: F', dialect: 'cpfg' as const, notes: [] };
    worker.send({ kind: 'done', opened });
    expect(await job.done).toEqual({ kind: 'done', opened });
    expect(worker.terminated).toBe(true);
  });

  it('stops an import that is cancelled: the worker is terminated and a late answer changes nothing', async () => {
    const worker = new FakeImportWorker();
    const job = runImport(() => worker, request);
    job.cancel();
    expect(worker.terminated).toBe(true);
    worker.send({ kind: 'done', opened: { ok: true, text: 'late', dialect: null, notes: [] } });
    expect(await job.done).toEqual({ kind: 'cancelled' });
  });

  it('stops an import that runs past its time limit', async () => {
    const worker = new FakeImportWorker();
    const job = runImport(() => worker, request, 20);
    expect(await job.done).toEqual({ kind: 'timeout' });
    expect(worker.terminated).toBe(true);
  });

  it('reports a panic of the importer and a worker that cannot start', async () => {
    const panicking = new FakeImportWorker();
    const a = runImport(() => panicking, request);
    panicking.send({ kind: 'failed', message: 'unreachable' });
    expect(await a.done).toEqual({ kind: 'failed', message: 'the importer failed (a bug): unreachable' });
    const broken = new FakeImportWorker();
    const b = runImport(() => broken, request);
    broken.fail();
    expect(await b.done).toEqual({ kind: 'failed', message: 'the import worker failed: it could not start' });
    expect(broken.terminated).toBe(true);
  });
});
