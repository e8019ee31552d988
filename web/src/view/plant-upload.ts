// A new plant's way to the GPU: its arrays into WebGL buffers (./gpu-geometry.ts), at once for a
// small plant, in slices over several tasks for a big one (the plant before stays on screen).
import type { BufferGeometry } from 'three';
import type { Bounds, GpuArrays, MeshBuffers } from '../core';
import { BufferPool, GpuGeometry } from './gpu-geometry';
import { plantGeometry } from './plant-geometry';

/**
 * A new plant goes to the GPU (see {@link GpuGeometry}) in slices of this many bytes, as many per
 * task as fit in {@link UPLOAD_TASK_MS}. A slice takes under 1 ms of the page's thread when the GPU
 * keeps up, and tens of ms when it does not (software GPU on a loaded machine, traced): small
 * slices keep such a wait short. A plant of at most {@link UPLOAD_AT_ONCE_BYTES} goes up whole and
 * is shown at once.
 */
const UPLOAD_SLICE_BYTES = 2 << 20;
const UPLOAD_TASK_MS = 8;
const UPLOAD_AT_ONCE_BYTES = 8 << 20;

/** A plant for the screen: its mesh and, unless drawn as lines, its geometry (plain and on the GPU). */
export interface IncomingPlant {
  mesh: MeshBuffers;
  flat: boolean;
  source?: BufferGeometry;
  onGpu?: GpuGeometry;
}

/**
 * Runs `task` in a task of its own, at once: ahead of other tasks where `scheduler.postTask` exists
 * (the user is waiting for the plant), else by a message (a `setTimeout` chain waits 4 ms a call
 * after five).
 */
function nextTask(task: () => void): void {
  const scheduler = (globalThis as { scheduler?: { postTask?: (task: () => void, options: { priority: string }) => Promise<unknown> } }).scheduler;
  if (scheduler?.postTask) {
    void scheduler.postTask(task, { priority: 'user-blocking' });
    return;
  }
  const channel = new MessageChannel();
  channel.port1.onmessage = () => {
    channel.port1.close();
    task();
  };
  channel.port2.postMessage(null);
}

/** Takes one plant at a time to the GPU, and hands it over (`arrived`) once all of it is there. */
export class PlantUpload {
  /** WebGL buffers of plants replaced, for the next plants' arrays. */
  readonly buffers: BufferPool;
  /** A plant on its way to the GPU; the one on screen stays until its last slice is there. */
  private incoming: IncomingPlant | undefined;

  /** `gpuIdle`: whether the GPU has drawn the frame before (a slice waits for it). */
  constructor(
    gl: WebGL2RenderingContext,
    private readonly gpuIdle: () => boolean,
    private readonly arrived: (plant: IncomingPlant) => void,
  ) {
    this.buffers = new BufferPool(gl);
  }

  /** The plant on its way to the GPU, if any. */
  get pending(): IncomingPlant | undefined {
    return this.incoming;
  }

  /** Drops the plant on its way, if any (a newer plant replaces it). */
  cancel(): void {
    this.incoming?.onGpu?.dispose();
    this.incoming = undefined;
  }

  /**
   * Sends `mesh` to the GPU (`gpu`, `bounds`: see {@link plantGeometry}): at once if it has at
   * most {@link UPLOAD_AT_ONCE_BYTES}, else a few milliseconds of slices per task.
   */
  send(mesh: MeshBuffers, flat: boolean, gpu?: GpuArrays, bounds?: Bounds): void {
    const source = plantGeometry(mesh, gpu, bounds);
    const onGpu = new GpuGeometry(this.buffers, source);
    const incoming: IncomingPlant = { mesh, flat, source, onGpu };
    this.incoming = incoming;
    if (onGpu.remaining <= UPLOAD_AT_ONCE_BYTES) {
      this.finish();
      return;
    }
    // A big plant: slices for a few milliseconds per task, once the GPU has drawn the frame before
    // (a frame of the sketch on a software GPU takes up to 300 ms, and an upload meanwhile waits).
    const next = () => {
      if (this.incoming !== incoming) return; // replaced by a newer plant, and disposed
      if (!this.gpuIdle()) {
        setTimeout(next, 2);
        return;
      }
      const start = performance.now();
      let done = onGpu.upload(UPLOAD_SLICE_BYTES);
      while (!done && performance.now() - start < UPLOAD_TASK_MS) done = onGpu.upload(UPLOAD_SLICE_BYTES);
      if (!done) nextTask(next);
      else this.finish();
    };
    next();
  }

  /** Uploads what is left of the incoming plant at once, and hands it over. */
  finish(): void {
    const incoming = this.incoming;
    if (!incoming) return;
    incoming.onGpu?.upload(Infinity);
    this.incoming = undefined;
    this.arrived(incoming);
  }

  /** `source` on the GPU again in new buffers, in place of `onGpu` (whose buffers went with the context). */
  again(onGpu: GpuGeometry, source: BufferGeometry): GpuGeometry {
    onGpu.dispose(true);
    const fresh = new GpuGeometry(this.buffers, source);
    fresh.upload(Infinity);
    return fresh;
  }

  /** The context is back: the plant on its way goes to the GPU again, at once, and is handed over. */
  restored(): void {
    const incoming = this.incoming;
    if (incoming?.onGpu && incoming.source) {
      incoming.onGpu = this.again(incoming.onGpu, incoming.source);
      this.finish();
    }
  }

  dispose(): void {
    this.cancel();
    this.buffers.clear();
  }
}
