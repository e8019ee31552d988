// Loading the WebAssembly core, and what happens when it fails. This folder is the only
// TypeScript that imports crate/pkg-core (the core without importers and exporters, all the first
// plant needs) and crate/pkg (the whole boundary: ./io.ts loads it when a file is imported or
// exported).
import init, { initSync, onPanic } from '../../../crate/pkg-core/meristem_core.js';
import wasmUrl from '../../../crate/pkg-core/meristem_core_bg.wasm?url';

let memory: WebAssembly.Memory | undefined;
let loading: Promise<void> | undefined;
/** The message of the core's last panic, until the call that panicked throws. */
let panicMessage: string | undefined;

/**
 * A panic of the core (a bug): `message` is the core's own (`the core crashed (a bug): panicked
 * at …`). The core instance that threw it must not be used again: a worker is replaced, the page
 * asks for a reload.
 */
export class CoreCrashed extends Error {
  override name = 'CoreCrashed';
}

/**
 * Instantiates the core once; later calls return the same promise.
 *
 * - In the browser pass the module the page compiled (`coreModule` of ./compile.ts), or nothing:
 *   the `.wasm` file is then fetched from the URL vite gives it (a hashed asset next to the page)
 *   and compiled here.
 * - In node (vitest, scripts) pass the bytes of `crate/pkg-core/meristem_core_bg.wasm`, e.g. from
 *   `readFileSync`: they are compiled synchronously (node cannot `fetch` a `file:` URL).
 */
export function initCore(wasm?: BufferSource | WebAssembly.Module): Promise<void> {
  if (loading) return loading;
  const listen = () => onPanic(notePanic);
  if (wasm !== undefined && !(wasm instanceof WebAssembly.Module)) {
    memory = initSync({ module: wasm }).memory;
    listen();
    loading = Promise.resolve();
  } else {
    loading = init({ module_or_path: wasm ?? wasmUrl }).then((output) => {
        memory = output.memory;
        listen();
      });
  }
  return loading;
}

/** Keeps the message of a panic of either core module for {@link guarded}. */
export function notePanic(message: string): void {
  panicMessage = message;
}

/** Throws a clear error when the core is used before {@link initCore} finished. */
export function assertReady(): void {
  if (memory === undefined) throw new Error('Meristem core used before initCore() finished');
}

/**
 * Runs `call` on the core. A panic of the core comes out as {@link CoreCrashed} with the core's
 * message (instead of WebAssembly's bare "unreachable"); other errors pass unchanged.
 */
export function guarded<T>(call: () => T): T {
  try {
    return call();
  } catch (error) {
    if (!(error instanceof WebAssembly.RuntimeError)) throw error;
    const message = panicMessage ?? `the core crashed (a bug): ${error.message}`;
    panicMessage = undefined;
    throw new CoreCrashed(message, { cause: error });
  }
}

/**
 * Returns an array JavaScript owns: `array` itself when it already has its own buffer (the
 * wasm-bindgen glue copies `Vec<f32>`/`Vec<u32>` results out of wasm memory), or a copy when it is
 * a view into wasm memory (which dies when that memory grows). Either way the data is copied
 * exactly once.
 */
export function ownedArray<T extends Float32Array | Uint32Array | Int16Array | Uint8Array>(array: T): T {
  return array.buffer === memory?.buffer ? (array.slice() as T) : array;
}
