// One job in a worker of its own: the request posted, the answers handled until one ends the job,
// then the worker terminated. Cancelling, a failure of the worker and an optional time limit end it
// too, at once: a job never leaves the page waiting. The export and import clients run on this.

/** What a job needs of a Worker (a fake one in unit tests). */
export interface JobWorkerLike<Request, Response> {
  postMessage(message: Request): void;
  terminate(): void;
  addEventListener(type: 'message', listener: (event: MessageEvent<Response>) => void): void;
  addEventListener(type: 'error', listener: (event: ErrorEvent) => void): void;
}

/** A job under way. */
export interface WorkerJob<Outcome> {
  /** Settles once, with the job's outcome. */
  readonly done: Promise<Outcome>;
  /** Stops the job (its worker is terminated); `done` settles with the cancelled outcome. */
  cancel(): void;
}

/** How a job's worker answers and how it may end. */
export interface JobEnds<Response, Outcome> {
  /** Reads one answer: returns the outcome that ends the job, or undefined to wait for more. */
  answer(response: Response): Outcome | undefined;
  /** The outcome when the worker fails (it could not start, or threw outside the job's code). */
  failed(message: string): Outcome;
  /** The outcome of {@link WorkerJob.cancel}. */
  cancelled: Outcome;
  /** Ends the job with `outcome` when it runs longer than `ms`. */
  limit?: { ms: number; outcome: Outcome };
}

/** Posts `request` to a fresh worker from `createWorker` and follows it until it ends. */
export function runWorkerJob<Request, Response, Outcome>(
  createWorker: () => JobWorkerLike<Request, Response>,
  request: Request,
  ends: JobEnds<Response, Outcome>,
): WorkerJob<Outcome> {
  let finish: (outcome: Outcome) => void = () => {};
  let settled = false;
  const done = new Promise<Outcome>((resolve) => (finish = resolve));
  const worker = createWorker();
  const timer = ends.limit && setTimeout(() => end(ends.limit!.outcome), ends.limit.ms);
  function end(outcome: Outcome): void {
    if (settled) return;
    settled = true;
    clearTimeout(timer);
    worker.terminate();
    finish(outcome);
  }
  worker.addEventListener('message', (event) => {
    if (settled) return;
    const outcome = ends.answer(event.data);
    if (outcome !== undefined) end(outcome);
  });
  worker.addEventListener('error', (event) => {
    event.preventDefault?.();
    end(ends.failed(event.message || 'it could not start'));
  });
  worker.postMessage(request);
  return { done, cancel: () => end(ends.cancelled) };
}
