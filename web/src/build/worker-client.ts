// The page's side of the build worker: one request at a time, the newest waiting request only,
// stale answers never delivered, and a worker stuck on an outdated build replaced.
import { type BuildOptions, type BuildProgress, type DerivationStep, type Explanation, type GpuArrays, type LastStepLinks, type BreakpointAnswer, type Lineage, type MatchReport, type PlantBuild, type PlantInspector, type PlantSketch } from '../core';
import { receivedBuild, type BuildResponse, type InspectAnswer, type InspectQuestion, type WorkerRequest, type WorkerResponse } from './worker-protocol';
import { startBuildWorker, takeEarlyBuildWorker } from './build-worker-start';

/** What the client needs of a Worker (a fake one in unit tests). */
export interface WorkerLike {
  postMessage(message: WorkerRequest): void;
  terminate(): void;
  addEventListener(type: 'message', listener: (event: MessageEvent<WorkerResponse>) => void): void;
  addEventListener(type: 'error', listener: (event: ErrorEvent) => void): void;
}

/** A finished build and what it cost. */
export interface BuildResult {
  source: string;
  options: BuildOptions;
  build: PlantBuild;
  /** The mesh's normals and colours packed for the GPU (for `PlantView.showPlant`). */
  gpu?: GpuArrays;
  /**
   * Questions about this build, answered by the worker, which keeps the core's derivation until
   * `inspector.free()`: whoever takes the result must free it (or hand it on) when done.
   */
  inspector: PlantInspector;
  /** Time of the core call in the worker (its stages are in `build.timings`). */
  workerMillis: number;
  /** Whether the studio core built it (after {@link BuildClient.useStudioCore}), rather than the first plant's. */
  studioCore: boolean;
  /** From the request to the answer on the page: waiting, building and transferring. */
  roundTripMillis: number;
}

/** How a request ended. */
export type BuildOutcome =
  | { kind: 'built'; result: BuildResult }
  /** A newer request replaced this one: its build, if it ran, is not delivered. */
  | { kind: 'superseded' }
  /** The core crashed (or the worker failed to start) on this request. */
  | { kind: 'crashed'; message: string }
  /** {@link BuildClient.stop} ended it: its worker was terminated. */
  | { kind: 'stopped' };

/** What a request's caller follows while it is built. */
export interface RequestWatch {
  /** Takes the sketch of a big plant, before its build. */
  onSketch?: (sketch: PlantSketch) => void;
  /** Plants of this many segments or more are sketched (the worker's default when absent). */
  sketchFrom?: number;
  /** Told the stage and derivation step the build is at, while the request is the one wanted. */
  onProgress?: (progress: BuildProgress) => void;
}

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
  watch: RequestWatch;
}

/**
 * Starts the real build worker (./build-worker-start.ts), or adopts the one the page's boot script
 * started before the studio's script had arrived (the first call on the studio page: issue 22).
 */
export function createBuildWorker(): Worker {
  return takeEarlyBuildWorker() ?? startBuildWorker();
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
  /** Open questions to the current worker, by id: each settles with its answer, or its fallback if the worker goes. */
  private readonly questions = new Map<number, { settle: (answer: InspectAnswer) => void; fallback: InspectAnswer }>();
  private nextQuestion = 1;
  private readonly abandonAfterMs: number;
  private readonly now: () => number;
  /** Whether each worker is to load the studio core ({@link useStudioCore}). */
  private studioCoreWanted = false;
  /** Workers started so far (the first one included): more than one means a restart. */
  workersStarted = 0;
  /** Kept builds built again by a new worker so far (see {@link ask}). */
  rekept = 0;

  constructor(
    private readonly createWorker: () => WorkerLike,
    options: BuildClientOptions = {},
  ) {
    this.abandonAfterMs = options.abandonAfterMs ?? 2000;
    this.now = options.now ?? (() => performance.now());
  }

  /**
   * Builds `source` with `options`; settles with the build, or says why there is none. A big
   * plant's sketch (of `watch.sketchFrom` segments or more, when given) goes to `watch.onSketch`
   * first, and the build's progress to `watch.onProgress`, unless the request is superseded by then.
   */
  request(source: string, options: BuildOptions, watch: RequestWatch = {}): Promise<BuildOutcome> {
    return new Promise((resolve) => {
      const entry: Entry = { id: this.nextId++, source, options, requestedAt: this.now(), resolve, settled: false, watch };
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

  /**
   * Stops the build under way and any waiting one at once: the worker is terminated and a fresh
   * one started for the next request, and those still wanted settle as `stopped`. True when one was.
   */
  stop(): boolean {
    const open = [this.running, this.waiting].filter((e): e is Entry => e !== undefined);
    const wanted = open.some((e) => !e.settled);
    this.running = undefined;
    this.waiting = undefined;
    for (const entry of open) this.settle(entry, { kind: 'stopped' });
    if (open.length > 0) {
      this.stopWorker();
      this.ensureWorker(); // started now, so the next build does not wait for it to load
    }
    return wanted;
  }

  /** True while a build runs or waits. */
  get busy(): boolean {
    return this.running !== undefined || this.waiting !== undefined;
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

  /** Starts the worker now (its script and core load meanwhile), before the first request. */
  warmUp(): void {
    this.ensureWorker();
  }

  /**
   * Has the worker load the studio core (crate/pkg) in the background, and every worker that
   * replaces it: the builds after it are faster (the core built for speed, not size) and their
   * inspectors answer every question. For after the first load: the first plant never waits for it.
   */
  useStudioCore(): void {
    if (this.studioCoreWanted) return;
    this.studioCoreWanted = true;
    this.worker?.postMessage({ kind: 'studio-core' });
  }

  private ensureWorker(): WorkerLike {
    if (this.worker) return this.worker;
    const worker = this.createWorker();
    this.workersStarted++;
    if (this.studioCoreWanted) worker.postMessage({ kind: 'studio-core' });
    worker.addEventListener('message', (event) => {
      if (worker !== this.worker) return;
      const response = event.data;
      if (response.kind === 'inspected') {
        this.questions.get(response.id)?.settle(response.answer);
        this.questions.delete(response.id);
      } else if (response.kind === 'sketch' || response.kind === 'progress') {
        // Only the running request's, and only while it is still wanted.
        const running = this.running;
        if (!running || running.id !== response.id || running.settled) return;
        if (response.kind === 'sketch') running.watch.onSketch?.(response.sketch);
        else running.watch.onProgress?.(response.progress);
      } else {
        this.answer(response);
      }
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
    // The kept builds died with it: open questions get their empty answers.
    for (const question of this.questions.values()) question.settle(question.fallback);
    this.questions.clear();
  }

  /**
   * Asks kept build `kept` a question. When the worker that kept it was replaced (Stop, a crash, an
   * abandoned build) the current one builds it again first, once, from its text and options, so a
   * plant still on the page goes on answering; the fallback only if the worker goes while asked.
   */
  ask<T extends InspectAnswer>(kept: KeptBuild, question: InspectQuestion, args: (number | string)[], fallback: T): Promise<T> {
    const worker = this.ensureWorker();
    if (kept.worker !== worker) {
      kept.worker = worker;
      kept.build = this.nextId++; // never a build request's id: the worker keeps both by id
      this.rekept++;
      worker.postMessage({ kind: 'keep', build: kept.build, source: kept.source, options: kept.options });
    }
    const id = this.nextQuestion++;
    return new Promise<T>((resolve) => {
      this.questions.set(id, { settle: (answer) => resolve(answer as T), fallback });
      worker.postMessage({ kind: 'inspect', id, build: kept.build, question, args });
    });
  }

  /** Lets the worker free kept build `kept` (nothing to do if its worker is gone). */
  release(kept: KeptBuild): void {
    if (kept.worker === this.worker) kept.worker.postMessage({ kind: 'free', build: kept.build });
  }

  private sendWaiting(): void {
    const entry = this.waiting;
    if (!entry) return;
    this.waiting = undefined;
    entry.sentAt = this.now();
    this.running = entry;
    this.ensureWorker().postMessage({ kind: 'build', id: entry.id, source: entry.source, options: entry.options, sketchFrom: entry.watch.sketchFrom });
  }

  private answer(response: BuildResponse): void {
    const running = this.running;
    if (!running || response.id !== running.id) return;
    this.running = undefined;
    if (this.abandonTimer !== undefined) clearTimeout(this.abandonTimer);
    this.abandonTimer = undefined;
    if (response.kind === 'built') {
      const worker = this.worker!;
      if (running.settled) {
        this.release({ worker, build: response.id, source: running.source, options: running.options }); // superseded: nobody will ask it anything
      } else {
        const result: BuildResult = {
          source: running.source,
          options: running.options,
          build: receivedBuild(response.build),
          gpu: response.gpu,
          inspector: new RemoteInspector(this, { worker, build: response.id, source: running.source, options: running.options }),
          workerMillis: response.workerMillis,
          studioCore: response.studioCore,
          roundTripMillis: this.now() - running.requestedAt,
        };
        this.settle(running, { kind: 'built', result });
      }
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

/** Where a build is kept: its worker and its id there, and what builds it again in another worker. */
export interface KeptBuild {
  worker: WorkerLike;
  build: number;
  readonly source: string;
  readonly options: BuildOptions;
}

/**
 * A {@link PlantInspector} whose build is kept by the worker: each question is a message. It
 * outlives its worker: after a Stop, a crash or an abandoned build the next worker builds the same
 * plant again when first asked (see {@link BuildClient.ask}).
 */
class RemoteInspector implements PlantInspector {
  private freed = false;

  constructor(
    private readonly client: BuildClient,
    private readonly kept: KeptBuild,
  ) {}

  private ask<T extends InspectAnswer>(question: InspectQuestion, args: (number | string)[], fallback: T): Promise<T> {
    return this.freed ? Promise.resolve(fallback) : this.client.ask<T>(this.kept, question, args, fallback);
  }

  explain(production: number): Promise<Explanation | null> {
    return this.ask<Explanation | null>('explain', [production], null);
  }

  explainModule(module: number): Promise<Explanation | null> {
    return this.ask<Explanation | null>('explainModule', [module], null);
  }

  moduleTexts(start: number, count: number): Promise<string[]> {
    return this.ask<string[]>('moduleTexts', [start, count], []);
  }

  derivedHash(): Promise<string> {
    return this.ask<string>('derivedHash', [], '');
  }

  matchReport(production: number, module: number): Promise<MatchReport | null> {
    return this.ask<MatchReport | null>('matchReport', [production, module], null);
  }

  sequence(maxModules: number): Promise<DerivationStep[] | null> {
    return this.ask<DerivationStep[] | null>('sequence', [maxModules], null);
  }

  lineage(module: number): Promise<Lineage> {
    return this.ask<Lineage>('lineage', [module], { error: '' });
  }

  breakpoint(source: string, production: number, watch: string): Promise<BreakpointAnswer> {
    return this.ask<BreakpointAnswer>('breakpoint', [source, production, watch], { error: '' });
  }

  previousTexts(start: number, count: number): Promise<string[]> {
    return this.ask<string[]>('previousTexts', [start, count], []);
  }

  lastStep(): Promise<LastStepLinks> {
    return this.ask<LastStepLinks>('lastStep', [], { parents: new Uint32Array(0), previousCount: 0 });
  }

  free(): void {
    if (this.freed) return;
    this.freed = true;
    this.client.release(this.kept);
  }
}
