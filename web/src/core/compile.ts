// The first plant's core compiled, apart from its instance (./init.ts): the studio page compiles
// it and hands it to its build worker, and needs none of the wasm-bindgen glue for that (the glue
// stays out of the page's first load, issue 22).
import corePackage from '../../../crate/pkg-core/package.json';
import wasmUrl from '../../../crate/pkg-core/meristem_core_bg.wasm?url';

/** The core's version (the crate version, as wasm-pack wrote it), for the about line and bug reports. */
export const CORE_VERSION: string = corePackage.version;

let compiled: Promise<WebAssembly.Module> | undefined;

/**
 * The core's compiled module, fetched and compiled once (browser only). The page hands it to its
 * build workers (createBuildWorker), which instantiate it, so the first plant downloads the core
 * once, whatever the host's caching (issue 22, the first load).
 */
export function coreModule(): Promise<WebAssembly.Module> {
  return (compiled ??= compileCore());
}

async function compileCore(): Promise<WebAssembly.Module> {
  const response = await fetch(wasmUrl);
  if (!response.ok) throw new Error(`the core could not be fetched: HTTP ${response.status} ${response.statusText}`); // (a damaged offline copy: public/sw-heal.js says so)
  // Streaming needs `application/wasm`; a host that says otherwise gets the bytes compiled whole.
  if (response.headers.get('Content-Type')?.startsWith('application/wasm')) return WebAssembly.compileStreaming(response);
  return WebAssembly.compile(await response.arrayBuffer());
}
