// The import worker: reads a grammar file of another dialect (cpfg, L-Py, Lparser, Green), or files
// opened together (a vlab object, an L-Py model, a .zip), through the core's importers, off the
// page's main thread, and sends back the Meristem text with its notes; or, when the model is to be
// run by Python (the core's rule), what to run, and later turns what Python derived into text.
// The page starts one worker per file and terminates it after, or to cancel, or when the import
// runs past its time limit (import-client.ts): an importer that takes minutes never freezes the page.
import { initIo } from '../../core';
import { openObjectBytes } from './grammar-files';
import { openDerivedBytes, pythonRequest } from './python-route';
import type { ImportRequest, ImportResponse } from './import-client';

function reply(response: ImportResponse): void {
  postMessage(response);
}

addEventListener('message', async (event: MessageEvent<ImportRequest>) => {
  const { files, derived } = event.data;
  try {
    await initIo(); // the core with its importers (the first plant's core has none)
  } catch (error) {
    reply({ kind: 'failed', message: `the core could not start: ${String(error)}` });
    return;
  }
  try {
    if (derived) {
      reply({ kind: 'done', opened: openDerivedBytes(derived.result, derived.main, files) });
      return;
    }
    const opened = openObjectBytes(files);
    const run = pythonRequest(files, opened);
    reply(run ? { kind: 'python', run, translated: opened } : { kind: 'done', opened });
  } catch (error) {
    // A panic of the core (a bug), said in its message.
    reply({ kind: 'failed', message: error instanceof Error ? error.message : String(error) });
  }
});
