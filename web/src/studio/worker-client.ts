// The page's side of the build worker: one request at a time, the newest waiting request only,
// stale answers never delivered, and a worker stuck on an outdated build replaced.
import type { BuildOptions, PlantBuild } from '../core';
import type { BuildRequest, BuildResponse } from './worker-protocol';

/** What the client needs of a Worker (a fake one in unit tests). */
export interface WorkerLike {
  postMessage(message: BuildRequest): void;
  terminate(): void;
  addEventListener(type: 'message', listener: (event: MessageEvent<BuildResponse>) => void): void;
  addEventListener(type: 'error', listener: (event: ErrorEvent) => void): void;
}

/** A finished build and what it cost. */
export interface BuildResult {
  source: string;
  options: BuildOptions;
  build: PlantBuild;
  /** Time of the core call in the worker (its stages are in `build.timings`). */
  workerMillis: number;
  /** From the request to the answer on the page: waiting, building and transferring. */
  roundTripMillis: number;
}

/** How a request ended. */
export type BuildOutcome =
  | { kind: 'built'; result: BuildResult }
  /** A newer request replaced this one: its build, if it ran, is not delivered. */
  | { kind: 'superseded' }
  /** The core crashed (or the worker failed to start) on this request. */
  | { kind: 'crashed'; message: string };

/** Options of {@link BuildClient}. */
export interface BuildClientOptions {
  /**
   * An outdated build that has run this long (ms) is abandoned: the worker is terminated and a
   * fresh one takes the newest request. Default 2000.
   */
  abandonAfterMs?: number;
  /** The clock, in ms (tests pass a fake one). Default `performance.now()`. */
  now?: () => number;
}

interface Entry {
  id: number;
  source: string;
  options: BuildOptions;
  requestedAt: number;
  resolve: (outcome: BuildOutcome) => void;
  /** Settled already (superseded): the answer, when it comes, is dropped. */
  settled: boolean;
  /** When it was posted to the worker. */
  sentAt?: number;
}

/** Starts the real build worker (vite bundles worker.ts as a module worker next to the page). */
export function createBuildWorker(): Worker {
  return new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'meristem-build' });
}

/**
 * Sends builds to a worker. Only one build runs at a time; a request made meanwhile waits, and a
 * newer request replaces a waiting one (which settles as `superseded`), so a burst of edits costs
 * at most two builds. When a newer request arrives, the running build settles as `superseded` at
 * once and its answer is dropped; if it keeps running past `abandonAfterMs` the worker is
 * terminated and recreated. A crash settles its request as `crashed` and replaces the worker.
 */
export class BuildClient {
  private worker: WorkerLike | undefined;
  private running: Entry | undefined;
  private waiting: Entry | undefined;
  private nextId = 1;
  private abandonTimer: ReturnType<typeof setTimeout> | undefined;
  private readonly abandonAfterMs: number;
  private readonly now: () => number;
  /** Workers started so far (the first one included): more than one means a restart. */
  workersStarted = 0;

  constructor(
    private readonly createWorker: () => WorkerLike,
    options: BuildClientOptions = {},
  ) {
    this.abandonAfterMs = options.abandonAfterMs ?? 2000;
    this.now = options.now ?? (() => performance.now());
  }

  /** Builds `source` with `options`; settles with the build, or says why there is none. */
  request(source: string, options: BuildOptions): Promise<BuildOutcome> {
    return new Promise((resolve) => {
      const entry: Entry = { id: this.nextId++, source, options, requestedAt: this.now(), resolve, settled: false };
      if (this.waiting) this.settle(this.waiting, { kind: 'superseded' });
      this.waiting = entry;
      if (this.running) {
        this.settle(this.running, { kind: 'superseded' });
        this.armAbandonTimer();
      } else {
        this.sendWaiting();
      }
    });
  }

  /** Stops the worker; requests still open settle as superseded. */
  dispose(): void {
    if (this.waiting) this.settle(this.waiting, { kind: 'superseded' });
    if (this.running) this.settle(this.running, { kind: 'superseded' });
    this.waiting = undefined;
    this.running = undefined;
    this.stopWorker();
  }

  private settle(entry: Entry, outcome: BuildOutcome): void {
    if (entry.settled) return;
    entry.settled = true;
    entry.resolve(outcome);
  }

  private ensureWorker(): WorkerLike {
    if (this.worker) return this.worker;
    const worker = this.createWorker();
    this.workersStarted++;
    worker.addEventListener('message', (event) => {
      if (worker === this.worker) this.answer(event.data);
    });
    worker.addEventListener('error', (event) => {
      if (worker !== this.worker) return;
      event.preventDefault?.();
      this.fail(`the build worker failed: ${event.message || 'it could not start'}`);
    });
    this.worker = worker;
    return worker;
  }

  private stopWorker(): void {
    if (this.abandonTimer !== undefined) clearTimeout(this.abandonTimer);
    this.abandonTimer = undefined;
    this.worker?.terminate();
    this.worker = undefined;
  }

  private sendWaiting(): void {
    const entry = this.waiting;
    if (!entry) return;
    this.waiting = undefined;
    entry.sentAt = this.now();
    this.running = entry;
    this.ensureWorker().postMessage({ id: entry.id, source: entry.source, options: entry.options });
  }

  private answer(response: BuildResponse): void {
    const running = this.running;
    if (!running || response.id !== running.id) return;
    this.running = undefined;
    if (this.abandonTimer !== undefined) clearTimeout(this.abandonTimer);
    this.abandonTimer = undefined;
    if (response.kind === 'built') {
      const result: BuildResult = {
        source: running.source,
        options: running.options,
        build: response.build,
        workerMillis: response.workerMillis,
        roundTripMillis: this.now() - running.requestedAt,
      };
      this.settle(running, { kind: 'built', result });
    } else {
      this.settle(running, { kind: 'crashed', message: response.message });
      this.stopWorker(); // its wasm instance may be broken: the next request gets a fresh one
    }
    this.sendWaiting();
  }

  private fail(message: string): void {
    if (this.running) this.settle(this.running, { kind: 'crashed', message });
    this.running = undefined;
    this.stopWorker();
    this.sendWaiting();
  }

  /** Abandons the running (outdated) build once it has run `abandonAfterMs`. */
  private armAbandonTimer(): void {
    if (!this.running || this.abandonTimer !== undefined) return;
    const left = Math.max(0, (this.running.sentAt ?? this.now()) + this.abandonAfterMs - this.now());
    this.abandonTimer = setTimeout(() => {
      this.abandonTimer = undefined;
      if (!this.running || !this.waiting) return;
      this.running = undefined;
      this.stopWorker();
      this.sendWaiting();
    }, left);
  }
}
