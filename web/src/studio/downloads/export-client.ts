// The page's side of the export worker (export-worker.ts): one worker per export, its progress
// forwarded, cancellation by terminating it. Exports never run on the page's thread, so a model of
// millions of vertices is written while the page stays responsive.
import type { ExportOptions, ExportProgress, ModelFile, ModelFormat } from '../../core';
import { runWorkerJob, type JobWorkerLike, type WorkerJob } from '../../build';

/** Page → export worker: the one request a worker gets. */
export interface ExportRequest {
  source: string;
  format: ModelFormat;
  options: ExportOptions;
}

/** Export worker → page. */
export type ExportResponse =
  | { kind: 'progress'; progress: ExportProgress }
  | { kind: 'done'; file: ModelFile }
  /** `crashed`: a panic of the core (a bug), not a refusal such as a grammar with errors. */
  | { kind: 'failed'; message: string; crashed: boolean };

/** How an export ended. */
export type ExportOutcome =
  | { kind: 'done'; file: ModelFile }
  | { kind: 'failed'; message: string; crashed: boolean }
  | { kind: 'cancelled' };

/** What the client needs of a Worker (a fake one in unit tests). */
export type ExportWorkerLike = JobWorkerLike<ExportRequest, ExportResponse>;

/** Starts a real export worker (vite bundles export-worker.ts as a module worker). */
export function createExportWorker(): Worker {
  return new Worker(new URL('./export-worker.ts', import.meta.url), { type: 'module', name: 'meristem-export' });
}

/** An export under way: `done` settles once, with the file, the core's reason, or `cancelled`. */
export type RunningExport = WorkerJob<ExportOutcome>;

/**
 * Exports `source` in `format` with `options` in a fresh worker from `createWorker`, calling
 * `onProgress` with each stage the core starts. The worker is terminated when the export ends.
 */
export function runExport(
  createWorker: () => ExportWorkerLike,
  request: ExportRequest,
  onProgress: (progress: ExportProgress) => void,
): RunningExport {
  return runWorkerJob<ExportRequest, ExportResponse, ExportOutcome>(createWorker, request, {
    answer: (response) => {
      if (response.kind === 'progress') return void onProgress(response.progress);
      return response.kind === 'done' ? { kind: 'done', file: response.file } : { kind: 'failed', message: response.message, crashed: response.crashed };
    },
    failed: (message) => ({ kind: 'failed', message: `the export worker failed: ${message}`, crashed: true }),
    cancelled: { kind: 'cancelled' },
  });
}

/** `Exporting glTF 2.0 binary: meshing (4 of 6)…` */
export function describeProgress(label: string, progress: ExportProgress): string {
  return `Exporting ${label}: ${progress.stage} (${progress.index + 1} of ${progress.count})…`;
}
