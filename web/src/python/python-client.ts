// The page's side of the Python worker (python-worker.ts): one model at a time, in one worker kept
// between models (Pyodide loads once per page), stopped by terminating it (a Python loop cannot be
// interrupted otherwise without cross-origin isolation, which a static host does not give), and
// replaced by a fresh worker for the next model. A guard terminates a worker that outlives the
// runtime's own time limit (a body that never returns to the runtime's clock checks).
import type { PythonWorkerRequest, PythonWorkerResponse } from './python-protocol';
import type { PythonRunRequest } from './python-runner';

/** What the client needs of a Worker (a fake one in unit tests). */
export interface PythonWorkerLike {
  postMessage(message: PythonWorkerRequest): void;
  addEventListener(type: 'message', listener: (event: { data: PythonWorkerResponse }) => void): void;
  addEventListener(type: 'error', listener: (event: { message?: string; preventDefault?: () => void }) => void): void;
  terminate(): void;
}

/** Starts a real Python worker (vite bundles python-worker.ts, and the package's sources, as a module worker). */
export function createPythonWorker(): Worker {
  return new Worker(new URL('./python-worker.ts', import.meta.url), { type: 'module', name: 'meristem-python' });
}

/** Where Pyodide's files are served: `pyodide/` beside the page (scripts/pyodide-plugin.ts). */
export function pyodideIndexURL(base: string = document.baseURI): string {
  return new URL('pyodide/', base).href;
}

/** `run`'s result (python/README.md): the contract's fields the page reads; the core reads the rest. */
export interface PythonResult {
  ok: boolean;
  dialect: string | null;
  steps: number;
  error: { line: number; column: number; message: string } | null;
}

/** How a run ended: its result (JSON text, and parsed), or why there is none. */
export type PythonOutcome =
  | { kind: 'done'; json: string; result: PythonResult; millis: number }
  | { kind: 'failed'; message: string }
  | { kind: 'stopped' }
  | { kind: 'timeout'; seconds: number };

/** What a run is doing: fetching and starting Python (the first model only), or running the model. */
export type PythonState = 'loading' | 'running';

/** A run under way. */
export interface PythonJob {
  done: Promise<PythonOutcome>;
  /** Stops the run at once (the worker is terminated; the next run starts a new one). */
  stop(): void;
}

/** Longest Pyodide may take to download and start (s): 13.5 MB (6.3 MB gzipped) on a slow connection. */
export const LOADING_LIMIT_S = 300;

/** Time granted beyond the runtime's own `time_limit` before the worker is terminated (s). */
export const RUN_MARGIN_S = 15;

/** The runtime's default time limit (s), when the request gives none (common contract). */
const DEFAULT_TIME_LIMIT_S = 50;

/** The run under way: what its worker's messages and errors go to. */
interface CurrentRun {
  message(response: PythonWorkerResponse): void;
  end(outcome: PythonOutcome): void;
}

/** Runs models in a Python worker; one at a time (a new run stops the one under way). */
export class PythonClient {
  private worker: PythonWorkerLike | undefined;
  private current: CurrentRun | undefined;

  constructor(
    private readonly createWorker: () => PythonWorkerLike = createPythonWorker,
    private readonly indexURL: () => string = () => pyodideIndexURL(),
  ) {}

  /** Runs `request`; `onState` hears when Python is loading and when the model runs. */
  run(request: PythonRunRequest, onState: (state: PythonState) => void = () => {}): PythonJob {
    this.current?.end({ kind: 'stopped' });
    const worker = this.ensureWorker();
    let finish: (outcome: PythonOutcome) => void = () => {};
    const done = new Promise<PythonOutcome>((resolve) => (finish = resolve));
    let timer: ReturnType<typeof setTimeout> | undefined;
    const guard = (seconds: number) => {
      clearTimeout(timer);
      timer = setTimeout(() => run.end({ kind: 'timeout', seconds }), seconds * 1000);
    };
    const runLimit = (request.options.time_limit ?? DEFAULT_TIME_LIMIT_S) + RUN_MARGIN_S;
    const run: CurrentRun = {
      message: (response) => {
        if (response.kind === 'loading') {
          guard(LOADING_LIMIT_S);
          onState('loading');
        } else if (response.kind === 'running') {
          guard(runLimit);
          onState('running');
        } else if (response.kind === 'failed') run.end({ kind: 'failed', message: response.message });
        else run.end(parsed(response.result, response.millis));
      },
      end: (outcome) => {
        if (this.current !== run) return;
        this.current = undefined;
        clearTimeout(timer);
        // A worker whose run did not finish by itself is spent: it may still be running the model.
        if (outcome.kind !== 'done') this.dropWorker(worker);
        finish(outcome);
      },
    };
    this.current = run;
    guard(LOADING_LIMIT_S);
    worker.postMessage({ indexURL: this.indexURL(), run: request });
    return { done, stop: () => run.end({ kind: 'stopped' }) };
  }

  /** The kept worker, or a new one whose messages go to the run under way. */
  private ensureWorker(): PythonWorkerLike {
    if (this.worker) return this.worker;
    const worker = this.createWorker();
    worker.addEventListener('message', (event) => {
      if (this.worker === worker) this.current?.message(event.data);
    });
    worker.addEventListener('error', (event) => {
      event.preventDefault?.();
      if (this.worker === worker) this.current?.end({ kind: 'failed', message: `the Python worker failed: ${event.message || 'it could not start'}` });
    });
    this.worker = worker;
    return worker;
  }

  private dropWorker(worker: PythonWorkerLike): void {
    worker.terminate();
    if (this.worker === worker) this.worker = undefined;
  }
}

/** The result read, or a failure when it is not the contract's shape. */
function parsed(json: string, millis: number): PythonOutcome {
  try {
    const result = JSON.parse(json) as PythonResult;
    if (typeof result === 'object' && result !== null && typeof result.ok === 'boolean') return { kind: 'done', json, result, millis };
  } catch {
    // below
  }
  return { kind: 'failed', message: 'the Python runtime answered something that is not a result' };
}
