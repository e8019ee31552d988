// The page's side of the import worker (import-worker.ts): a grammar file of another dialect, or
// files opened together (a vlab object, an L-Py model, a .zip), is imported in a worker of its own,
// with a Cancel button in the notice and a time limit, so the page stays responsive however long
// an importer takes. `.lsys` files need no import: the page reads them itself. A model the core
// says Python should run goes to python-opening.ts between two imports: what to run, then what
// Python derived.
import type { ObjectFile } from '../../core';
import type { PythonClient, PythonRunRequest } from '../../python';
import { checkGrammarBytes, type OpenedFile } from './grammar-files';
import type { Notice } from '../page';
import { runWorkerJob, type JobWorkerLike, type WorkerJob } from '../../build';
import { openInPython, pagePython } from './python-opening';

/**
 * Page → import worker: the files a worker imports (one grammar file, or an object's files); with
 * `derived`, what Python derived (`result`: the runtime's JSON) for `main` among them, to be made
 * Meristem text.
 */
export interface ImportRequest {
  files: ObjectFile[];
  derived?: { result: string; main: string };
}

/**
 * Import worker → page: the text; or `python`, the model to run in Python, with the hand
 * translation (`translated`, used when Python cannot be loaded).
 */
export type ImportResponse = { kind: 'done'; opened: OpenedFile } | { kind: 'python'; run: PythonRunRequest; translated: OpenedFile } | { kind: 'failed'; message: string };

/** How an import ended. */
export type ImportOutcome =
  | { kind: 'done'; opened: OpenedFile }
  | { kind: 'python'; run: PythonRunRequest; translated: OpenedFile }
  | { kind: 'failed'; message: string }
  | { kind: 'cancelled' }
  | { kind: 'timeout' };

/** What the client needs of a Worker (a fake one in unit tests). */
export type ImportWorkerLike = JobWorkerLike<ImportRequest, ImportResponse>;

/** Longest an import may run (ms) before it is stopped and said to be too slow. */
export const IMPORT_TIME_LIMIT = 10_000;

/** An import taking longer than this (ms) shows its notice with Cancel. */
export const IMPORT_NOTICE_AFTER = 300;

/** Starts a real import worker (vite bundles import-worker.ts as a module worker). */
export function createImportWorker(): Worker {
  return new Worker(new URL('./import-worker.ts', import.meta.url), { type: 'module', name: 'meristem-import' });
}

/** Imports the request's files in a fresh worker from `createWorker`, stopped after `limitMs`. */
export function runImport(createWorker: () => ImportWorkerLike, request: ImportRequest, limitMs = IMPORT_TIME_LIMIT): WorkerJob<ImportOutcome> {
  return runWorkerJob<ImportRequest, ImportResponse, ImportOutcome>(createWorker, request, {
    answer: (response) => (response.kind === 'failed' ? { kind: 'failed', message: `the importer failed (a bug): ${response.message}` } : response),
    failed: (message) => ({ kind: 'failed', message: `the import worker failed: ${message}` }),
    cancelled: { kind: 'cancelled' },
    limit: { ms: limitMs, outcome: { kind: 'timeout' } },
  });
}

/**
 * What reading a file uses: the worker to import in, the notice that shows the import, its time
 * limit, and the Python worker's client for models that Python runs (default: the page's one,
 * so that Python loads once).
 */
export interface FileReadingParts {
  createWorker: () => ImportWorkerLike;
  notice: Notice;
  limitMs?: number;
  python?: () => PythonClient;
}

/** What the notice shows about an import (its topic, so that only its own notice is taken back). */
const IMPORTING = 'importing';

/**
 * Reads a file the user opened: `.lsys` at once; another dialect imported in a worker, the notice
 * saying so (with Cancel) once it takes longer than {@link IMPORT_NOTICE_AFTER}. Settles with the
 * text, or why there is none: a cancelled or too slow import is an `ok: false` with its reason.
 */
export async function readGrammarFile(file: File, parts: FileReadingParts): Promise<OpenedFile> {
  const bytes = new Uint8Array(await file.arrayBuffer());
  const checked = checkGrammarBytes(file.name, bytes);
  if (!checked.ok) return checked;
  if (checked.lsys) return { ok: true, text: checked.text, dialect: null, notes: checked.notes };
  return importInWorker([{ name: file.name, bytes }], file.name, parts);
}

/**
 * Reads files opened together (a dropped folder, several picked files, a `.zip`), called `name`
 * in the notice: a vlab object or an L-Py model imported whole in a worker, as
 * {@link readGrammarFile} imports one file.
 */
export function readObjectFiles(files: ObjectFile[], name: string, parts: FileReadingParts): Promise<OpenedFile> {
  return importInWorker(files, name, parts);
}

/**
 * Imports `files` in a worker, the notice saying so (with Cancel) once it takes a while; a model
 * that Python runs goes on in {@link openInPython}. With `derived`, makes text of what Python derived.
 */
export async function importInWorker(files: ObjectFile[], name: string, parts: FileReadingParts, derived?: ImportRequest['derived']): Promise<OpenedFile> {
  const limitMs = parts.limitMs ?? IMPORT_TIME_LIMIT;
  const job = runImport(parts.createWorker, { files, ...(derived ? { derived } : {}) }, limitMs);
  const shown = setTimeout(() => {
    parts.notice.show('info', `Importing ${name}…`, [], IMPORTING, [{ label: 'Cancel', testid: 'import-cancel', run: () => job.cancel() }]);
  }, IMPORT_NOTICE_AFTER);
  const outcome = await job.done;
  clearTimeout(shown);
  parts.notice.hide(IMPORTING);
  switch (outcome.kind) {
    case 'done':
      return outcome.opened;
    case 'python':
      return openInPython(outcome.run, outcome.translated, name, {
        notice: parts.notice,
        python: parts.python ?? pagePython,
        derive: (result, main) => importInWorker(files, name, parts, { result, main }),
      });
    case 'failed':
      return { ok: false, error: outcome.message };
    case 'cancelled':
      return { ok: false, error: 'the import was cancelled; your text is as it was' };
    case 'timeout':
      return {
        ok: false,
        error: `importing it took longer than ${limitMs / 1000} s, so it was stopped (the file may have more than the importer can translate in time, such as macros that expand into themselves on many lines); your text is as it was`,
      };
  }
}
