// The build worker: runs the core (parse → resolve → derive → interpret → mesh) off the page's
// main thread, so typing never waits for a big plant. It initialises its own WebAssembly
// instance and answers each BuildRequest in order, moving the typed arrays back in a transfer
// list. Started by createBuildWorker (worker-client.ts).
import { buildPlant, initCore } from '../core';
import { transferablesOf, type BuildRequest, type BuildResponse } from './worker-protocol';

const ready = initCore();

function reply(response: BuildResponse, transfer: Transferable[] = []): void {
  postMessage(response, { transfer });
}

addEventListener('message', async (event: MessageEvent<BuildRequest>) => {
  const { id, source, options } = event.data;
  try {
    await ready;
    const start = performance.now();
    const build = buildPlant(source, options);
    reply({ kind: 'built', id, build, workerMillis: performance.now() - start }, transferablesOf(build));
  } catch (error) {
    reply({ kind: 'crashed', id, message: error instanceof Error ? `${error.name}: ${error.message}` : String(error) });
  }
});
