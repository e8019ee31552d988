// The messages between the page and the build worker (worker.ts), and the transfer list that
// moves a build's typed arrays out of the worker without copying them.
import type { BuildOptions, PlantBuild } from '../core';

/** Page → worker: build `source` with `options`; `id` ties the answer to the request. */
export interface BuildRequest {
  id: number;
  source: string;
  options: BuildOptions;
}

/** Worker → page: the answer to request `id`. */
export type BuildResponse =
  | {
      kind: 'built';
      id: number;
      build: PlantBuild;
      /** Time of `buildPlant` inside the worker, copying the arrays out of wasm memory included. */
      workerMillis: number;
    }
  | {
      /** The core threw (a panic is a bug); the worker's wasm instance is no longer trusted. */
      kind: 'crashed';
      id: number;
      message: string;
    };

/**
 * The buffers of every typed array in `build`, each once: posting the build with this transfer
 * list moves them to the other side (no copy) and leaves them detached (length 0) here.
 */
export function transferablesOf(build: PlantBuild): ArrayBuffer[] {
  const arrays = [...Object.values(build.mesh), build.origins];
  const buffers = new Set<ArrayBuffer>();
  for (const array of arrays) if (array.buffer instanceof ArrayBuffer && array.buffer.byteLength > 0) buffers.add(array.buffer);
  return [...buffers];
}
