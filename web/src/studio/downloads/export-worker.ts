// The export worker: writes one model file off the page's main thread (parse → derive → interpret
// → mesh → edits → write, in the core), telling the page each stage as it starts, then sends the
// file's bytes in a transfer list. The page starts one worker per export and terminates it after
// (or to cancel): a big export grows a WebAssembly memory, which never shrinks, so it dies with it.
import { CoreCrashed, exportModelWithProgress, initIo } from '../../core';
import type { ExportRequest, ExportResponse } from './export-client';

function reply(response: ExportResponse, transfer: Transferable[] = []): void {
  postMessage(response, { transfer });
}

addEventListener('message', async (event: MessageEvent<ExportRequest>) => {
  const { source, format, options } = event.data;
  try {
    await initIo(); // the core with its file writers (the first plant's core has none)
  } catch (error) {
    reply({ kind: 'failed', message: `the core could not start: ${String(error)}`, crashed: true });
    return;
  }
  try {
    const file = exportModelWithProgress(source, format, options, (progress) => reply({ kind: 'progress', progress }));
    reply({ kind: 'done', file }, [file.bytes.buffer as ArrayBuffer]);
  } catch (error) {
    // CoreCrashed is a panic of the core (a bug); anything else is the core's refusal (errors in
    // the grammar, a malformed edits document), said in its message.
    const crashed = error instanceof CoreCrashed;
    reply({ kind: 'failed', message: error instanceof Error ? error.message : String(error), crashed });
  }
});
