// Loading the WebAssembly core. This folder is the only TypeScript that imports crate/pkg.
import init, { initSync, version } from '../../../crate/pkg/meristem.js';
import wasmUrl from '../../../crate/pkg/meristem_bg.wasm?url';

let memory: WebAssembly.Memory | undefined;
let loading: Promise<void> | undefined;

/**
 * Instantiates the core once; later calls return the same promise.
 *
 * - In the browser call it without arguments: the `.wasm` file is fetched from the URL vite
 *   gives it (a hashed asset next to the page).
 * - In node (vitest, scripts) pass the bytes of `crate/pkg/meristem_bg.wasm`, e.g. from
 *   `readFileSync`: they are compiled synchronously (node cannot `fetch` a `file:` URL).
 */
export function initCore(wasm?: BufferSource): Promise<void> {
  if (loading) return loading;
  if (wasm !== undefined) {
    memory = initSync({ module: wasm }).memory;
    loading = Promise.resolve();
  } else {
    loading = init({ module_or_path: wasmUrl }).then((output) => {
      memory = output.memory;
    });
  }
  return loading;
}

/** The core's version (the crate version), for the about line and bug reports. */
export function coreVersion(): string {
  assertReady();
  return version();
}

/** Throws a clear error when the core is used before {@link initCore} finished. */
export function assertReady(): void {
  if (memory === undefined) throw new Error('Meristem core used before initCore() finished');
}

/**
 * Returns an array JavaScript owns: `array` itself when it already has its own buffer (the
 * wasm-bindgen glue copies `Vec<f32>`/`Vec<u32>` results out of wasm memory), or a copy when it is
 * a view into wasm memory (which dies when that memory grows). Either way the data is copied
 * exactly once.
 */
export function ownedArray<T extends Float32Array | Uint32Array>(array: T): T {
  return array.buffer === memory?.buffer ? (array.slice() as T) : array;
}
