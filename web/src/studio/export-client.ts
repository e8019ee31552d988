// The page's side of the export worker (export-worker.ts): one worker per export, its progress
// forwarded, cancellation by terminating it. Exports never run on the page's thread, so a model of
// millions of vertices is written while the page stays responsive.
import type { ExportOptions, ExportProgress, ModelFile, ModelFormat } from '../core';

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
export interface ExportWorkerLike {
  postMessage(message: ExportRequest): void;
  terminate(): void;
  addEventListener(type: 'message', listener: (event: MessageEvent<ExportResponse>) => void): void;
  addEventListener(type: 'error', listener: (event: ErrorEvent) => void): void;
}

/** Starts a real export worker (vite bundles export-worker.ts as a module worker). */
export function createExportWorker(): Worker {
  return new Worker(new URL('./export-worker.ts', import.meta.url), { type: 'module', name: 'meristem-export' });
}

/** An export under way. */
export interface RunningExport {
  /** Settles once: with the file, the core's reason, or `cancelled`. */
  readonly done: Promise<ExportOutcome>;
  /** Stops the export (its worker is terminated); `done` settles as `cancelled`. */
  cancel(): void;
}

/**
 * Exports `source` in `format` with `options` in a fresh worker from `createWorker`, calling
 * `onProgress` with each stage the core starts. The worker is terminated when the export ends.
 */
export function runExport(
  createWorker: () => ExportWorkerLike,
  request: ExportRequest,
  onProgress: (progress: ExportProgress) => void,
): RunningExport {
  let finish: (outcome: ExportOutcome) => void = () => {};
  let settled = false;
  const done = new Promise<ExportOutcome>((resolve) => (finish = resolve));
  const worker = createWorker();
  const end = (outcome: ExportOutcome) => {
    if (settled) return;
    settled = true;
    worker.terminate();
    finish(outcome);
  };
  worker.addEventListener('message', (event) => {
    if (settled) return;
    const response = event.data;
    if (response.kind === 'progress') onProgress(response.progress);
    else if (response.kind === 'done') end({ kind: 'done', file: response.file });
    else end({ kind: 'failed', message: response.message, crashed: response.crashed });
  });
  worker.addEventListener('error', (event) => {
    event.preventDefault?.();
    end({ kind: 'failed', message: `the export worker failed: ${event.message || 'it could not start'}`, crashed: true });
  });
  worker.postMessage(request);
  return { done, cancel: () => end({ kind: 'cancelled' }) };
}

/** `Exporting glTF 2.0 binary: meshing (4 of 6)…` */
export function describeProgress(label: string, progress: ExportProgress): string {
  return `Exporting ${label}: ${progress.stage} (${progress.index + 1} of ${progress.count})…`;
}
