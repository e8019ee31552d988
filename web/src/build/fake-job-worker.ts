// A fake Worker for the unit tests of the clients of workers (worker-job.ts's, the build client):
// it records what it is sent, answers when the test says so, and can fail to start.
import type { JobWorkerLike } from './worker-job';

export class FakeJobWorker<Request, Response> implements JobWorkerLike<Request, Response> {
  /** What it was sent, oldest first. */
  messages: Request[] = [];
  terminated = false;
  onMessage: ((event: MessageEvent<Response>) => void) | undefined;
  onError: ((event: ErrorEvent) => void) | undefined;
  postMessage(message: Request): void {
    this.messages.push(message);
  }
  terminate(): void {
    this.terminated = true;
  }
  addEventListener(type: 'message', listener: (event: MessageEvent<Response>) => void): void;
  addEventListener(type: 'error', listener: (event: ErrorEvent) => void): void;
  addEventListener(type: 'message' | 'error', listener: ((event: MessageEvent<Response>) => void) | ((event: ErrorEvent) => void)): void {
    if (type === 'message') this.onMessage = listener as (event: MessageEvent<Response>) => void;
    else this.onError = listener as (event: ErrorEvent) => void;
  }
  /** Answers as the worker would. */
  send(response: Response): void {
    this.onMessage?.({ data: response } as MessageEvent<Response>);
  }
  /** Fails as a worker that cannot start (`message` empty) or throws outside the job. */
  fail(message = ''): void {
    this.onError?.({ message, preventDefault() {} } as ErrorEvent);
  }
}
