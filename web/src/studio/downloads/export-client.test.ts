import { describe, expect, it } from 'vitest';
import { FakeJobWorker } from '../../build/fake-job-worker';
import type { ExportProgress, ModelFile } from '../../core';
import { describeProgress, runExport, type ExportRequest, type ExportResponse } from './export-client';

class FakeExportWorker extends FakeJobWorker<ExportRequest, ExportResponse> {}

const request: ExportRequest = { source: 'axiom: F', format: 'glb', options: { iterations: 2 } };
const file: ModelFile = { fileName: 'plant.glb', mimeType: 'model/gltf-binary', bytes: new Uint8Array([1, 2, 3]) };
const stage = (index: number, name: ExportProgress['stage']): ExportProgress => ({ stage: name, index, count: 6 });

describe('runExport', () => {
  it('sends the request, forwards each stage, settles with the file and ends the worker', async () => {
    const worker = new FakeExportWorker();
    const seen: string[] = [];
    const running = runExport(() => worker, request, (p) => seen.push(p.stage));
    expect(worker.messages).toEqual([request]);
    worker.send({ kind: 'progress', progress: stage(0, 'parsing') });
    worker.send({ kind: 'progress', progress: stage(3, 'meshing') });
    expect(worker.terminated).toBe(false);
    worker.send({ kind: 'done', file });
    expect(await running.done).toEqual({ kind: 'done', file });
    expect(seen).toEqual(['parsing', 'meshing']);
    expect(worker.terminated).toBe(true);
  });

  it("passes on the core's refusal and tells a crash from it", async () => {
    const refused = new FakeExportWorker();
    const a = runExport(() => refused, request, () => {});
    refused.send({ kind: 'failed', message: 'the grammar has errors: nothing to export', crashed: false });
    expect(await a.done).toEqual({ kind: 'failed', message: 'the grammar has errors: nothing to export', crashed: false });
    const broken = new FakeExportWorker();
    const b = runExport(() => broken, request, () => {});
    broken.fail();
    expect(await b.done).toEqual({ kind: 'failed', message: 'the export worker failed: it could not start', crashed: true });
    expect(broken.terminated).toBe(true);
  });

  it('cancels: the worker is terminated at once and later answers are ignored', async () => {
    const worker = new FakeExportWorker();
    const seen: string[] = [];
    const running = runExport(() => worker, request, (p) => seen.push(p.stage));
    running.cancel();
    expect(worker.terminated).toBe(true);
    worker.send({ kind: 'progress', progress: stage(1, 'deriving') });
    worker.send({ kind: 'done', file });
    expect(await running.done).toEqual({ kind: 'cancelled' });
    expect(seen).toEqual([]);
  });

  it('words the progress for the status line', () => {
    expect(describeProgress('glTF 2.0 binary', stage(3, 'meshing'))).toBe('Exporting glTF 2.0 binary: meshing (4 of 6)…');
  });
});
