// The messages between the page and the Python worker (python-worker.ts, python-client.ts).
import type { PythonRunRequest } from './python-runner';

/** Page → worker: run one model; `indexURL` is where Pyodide's files are (the site's `pyodide/`). */
export interface PythonWorkerRequest {
  indexURL: string;
  run: PythonRunRequest;
}

/**
 * Worker → page: `loading` when Pyodide is being fetched and started (the first model only),
 * `running` once it runs the model, then `done` with `run`'s result as JSON text, or `failed` when
 * Pyodide could not start or broke (not the model's error: that is in the result).
 */
export type PythonWorkerResponse =
  | { kind: 'loading' }
  | { kind: 'running' }
  | { kind: 'done'; result: string; millis: number }
  | { kind: 'failed'; message: string };
