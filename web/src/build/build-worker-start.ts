// Starting a build worker, and the one started early: the studio page's boot script (../boot.ts)
// starts it as soon as that small script has arrived, while the studio's own script still
// downloads, so the worker's script and the core's compilation are under way sooner (issue 22,
// the first load); the studio's first createBuildWorker adopts it.
import { coreModule } from '../core/compile';
import type { CoreMessage } from './worker-protocol';
import workerUrl from './worker.ts?worker&url';

let early: Worker | undefined;
/** The studio asked for its first worker: a boot script that runs later starts none. */
let asked = false;

/**
 * Starts the real build worker (vite bundles worker.ts as a module worker next to the page). A
 * page of another site (a plant embedded in a course page) may not start a worker from Meristem's
 * address: it starts one of its own that imports Meristem's (which the site must serve with CORS).
 */
export function startBuildWorker(): Worker {
  const url = new URL(workerUrl, import.meta.url);
  const options: WorkerOptions = { type: 'module', name: 'meristem-build' };
  let worker: Worker;
  if (url.origin === location.origin) worker = new Worker(url, options);
  else {
    const loader = new Blob([`import ${JSON.stringify(url.href)};`], { type: 'text/javascript' });
    worker = new Worker(URL.createObjectURL(loader), options);
  }
  // Its first message: the core the page compiled (or null: the worker then fetches its own).
  coreModule().then(
    (module) => worker.postMessage({ kind: 'core', module } satisfies CoreMessage),
    () => worker.postMessage({ kind: 'core', module: null } satisfies CoreMessage),
  );
  return worker;
}

/**
 * Starts the build worker early (the boot script); the studio adopts it with
 * {@link takeEarlyBuildWorker}. Nothing when the studio has already started its own (its script
 * ran first: no network to wait for).
 */
export function startEarlyBuildWorker(): void {
  if (!asked) early ??= startBuildWorker();
}

/** The worker {@link startEarlyBuildWorker} started, once (later calls: undefined). */
export function takeEarlyBuildWorker(): Worker | undefined {
  asked = true;
  const worker = early;
  early = undefined;
  return worker;
}
