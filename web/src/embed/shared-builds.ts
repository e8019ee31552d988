// One build worker for every plant of a page: the plants embedded in a course page share one core.
// Builds run one at a time, in the order they were asked for; a plant's newer request replaces its
// own waiting one (a slider dragged fast costs at most two builds), never another plant's. A build
// whose plant is gone (its element removed) or whose plant asked again long ago is stopped (the
// worker is replaced), so one plant that never finishes does not hold up the others (issue 50,
// finding 9a).
import type { BuildOptions, BuildProgress } from '../core';
import { BuildClient, createBuildWorker, type BuildOutcome, type WorkerLike } from '../build';

interface Waiting {
  owner: object;
  source: string;
  options: BuildOptions;
  onProgress?: (progress: BuildProgress) => void;
  resolve: (outcome: BuildOutcome) => void;
}

/** Options of {@link SharedBuilds}. */
export interface SharedBuildsOptions {
  /**
   * How long (ms) a plant's running build may go on once the same plant has asked for another:
   * then it is stopped (the worker replaced) and the newer one runs. Default 2000.
   */
  abandonAfterMs?: number;
}

export class SharedBuilds {
  private readonly client: BuildClient;
  private readonly queue: Waiting[] = [];
  /** The request being built. */
  private running: Waiting | undefined;
  private abandonTimer: ReturnType<typeof setTimeout> | undefined;
  private readonly abandonAfterMs: number;

  constructor(createWorker: () => WorkerLike = createBuildWorker, options: SharedBuildsOptions = {}) {
    this.client = new BuildClient(createWorker);
    this.abandonAfterMs = options.abandonAfterMs ?? 2000;
  }

  /**
   * Builds `source` for `owner` (a plant); settles `superseded` if the owner asks again before it
   * ran, `stopped` if it ran too long after the owner asked again. `onProgress` is told the stage
   * and derivation step while it is built.
   */
  build(owner: object, source: string, options: BuildOptions, onProgress?: (progress: BuildProgress) => void): Promise<BuildOutcome> {
    const earlier = this.queue.findIndex((w) => w.owner === owner);
    if (earlier >= 0) this.queue.splice(earlier, 1)[0].resolve({ kind: 'superseded' });
    if (this.running?.owner === owner && this.abandonTimer === undefined) {
      const running = this.running;
      this.abandonTimer = setTimeout(() => {
        this.abandonTimer = undefined;
        if (this.running === running) this.client.stop();
      }, this.abandonAfterMs);
    }
    return new Promise((resolve) => {
      this.queue.push({ owner, source, options, onProgress, resolve });
      void this.next();
    });
  }

  /** Forgets `owner`'s requests (its plant left the page): the waiting one, and the running one is stopped. */
  forget(owner: object): void {
    const earlier = this.queue.findIndex((w) => w.owner === owner);
    if (earlier >= 0) this.queue.splice(earlier, 1)[0].resolve({ kind: 'superseded' });
    if (this.running?.owner === owner) this.client.stop(); // the worker is replaced; the next request goes on
  }

  private async next(): Promise<void> {
    if (this.running) return;
    const waiting = this.queue.shift();
    if (!waiting) return;
    this.running = waiting;
    const outcome = await this.client.request(waiting.source, waiting.options, { onProgress: waiting.onProgress });
    this.running = undefined;
    if (this.abandonTimer !== undefined) clearTimeout(this.abandonTimer);
    this.abandonTimer = undefined;
    waiting.resolve(outcome);
    void this.next();
  }
}

let pageBuilds: SharedBuilds | undefined;

/** The page's one worker, started by the first plant that asks. */
export function sharedBuilds(): SharedBuilds {
  pageBuilds ??= new SharedBuilds();
  return pageBuilds;
}
