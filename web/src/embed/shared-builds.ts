// One build worker for every plant of a page: the plants embedded in a course page share one core.
// Builds run one at a time, in the order they were asked for; a plant's newer request replaces its
// own waiting one (a slider dragged fast costs at most two builds), never another plant's.
import type { BuildOptions } from '../core';
import { BuildClient, createBuildWorker, type BuildOutcome, type WorkerLike } from '../build';

interface Waiting {
  owner: object;
  source: string;
  options: BuildOptions;
  resolve: (outcome: BuildOutcome) => void;
}

export class SharedBuilds {
  private readonly client: BuildClient;
  private readonly queue: Waiting[] = [];
  private running = false;

  constructor(createWorker: () => WorkerLike = createBuildWorker) {
    this.client = new BuildClient(createWorker);
  }

  /** Builds `source` for `owner` (a plant); settles `superseded` if the owner asks again before it ran. */
  build(owner: object, source: string, options: BuildOptions): Promise<BuildOutcome> {
    const earlier = this.queue.findIndex((w) => w.owner === owner);
    if (earlier >= 0) this.queue.splice(earlier, 1)[0].resolve({ kind: 'superseded' });
    return new Promise((resolve) => {
      this.queue.push({ owner, source, options, resolve });
      void this.next();
    });
  }

  /** Forgets `owner`'s waiting request (its plant left the page). */
  forget(owner: object): void {
    const earlier = this.queue.findIndex((w) => w.owner === owner);
    if (earlier >= 0) this.queue.splice(earlier, 1)[0].resolve({ kind: 'superseded' });
  }

  private async next(): Promise<void> {
    if (this.running) return;
    const waiting = this.queue.shift();
    if (!waiting) return;
    this.running = true;
    const outcome = await this.client.request(waiting.source, waiting.options);
    this.running = false;
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
