// The second WebAssembly module: the whole boundary (crate/pkg), with the importers of other
// dialects, the file writers (and the textures they embed) and branch editing. The first plant
// never waits for it: the export worker loads it, and the page on the first import of a file or
// the first branch edit (issue 22's first-load budget). Its panics come out as CoreCrashed like the
// first module's (see ./init.ts).
import init, { initSync, onPanic } from '../../../crate/pkg/meristem.js';
import wasmUrl from '../../../crate/pkg/meristem_bg.wasm?url';
import { notePanic } from './init';

let loading: Promise<void> | undefined;
let ready = false;

/**
 * Instantiates the importers, exporters and branch editing once; later calls return the same promise. In the
 * browser without arguments (the hashed `.wasm` asset is fetched); in node with the bytes of
 * `crate/pkg/meristem_bg.wasm`.
 */
export function initIo(wasm?: BufferSource): Promise<void> {
  if (loading) return loading;
  const started = () => {
    onPanic(notePanic);
    ready = true;
  };
  if (wasm !== undefined) {
    initSync({ module: wasm });
    started();
    loading = Promise.resolve();
  } else {
    loading = init({ module_or_path: wasmUrl }).then(started, (error: unknown) => {
      loading = undefined; // the next import or export tries again
      throw error;
    });
  }
  return loading;
}

/** Throws a clear error when an importer, an exporter or branch editing is used before {@link initIo} finished. */
export function assertIoReady(): void {
  if (!ready) throw new Error('Meristem importers, exporters and branch editing used before initIo() finished');
}
