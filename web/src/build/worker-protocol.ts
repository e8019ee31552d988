// The messages between the page and the build worker (worker.ts), and the transfer lists that move
// typed arrays out of the worker without copying them.
import { columnBuffers, DiagnosticList, type BuildOptions, type BuildProgress, type DiagnosticColumns, type GpuArrays, type PlantBuild, type PlantInspector, type PlantSketch } from '../core';

/** The questions a kept build answers: the methods of `PlantInspector`, asked by name. */
export type InspectQuestion = Exclude<keyof PlantInspector, 'free'>;

/**
 * The page's first message to a build worker: the core's compiled module (`coreModule()`), so the
 * worker does not download it again; null when the page could not compile it (the worker fetches it).
 */
export interface CoreMessage {
  kind: 'core';
  module: WebAssembly.Module | null;
}

/** Page → worker. */
export type WorkerRequest =
  /**
   * Build `source` with `options`; `id` ties the answer to the request and names the kept build.
   * A plant of `sketchFrom` segments or more (default {@link SKETCH_MIN_SEGMENTS}) is sent as a sketch first.
   */
  | { kind: 'build'; id: number; source: string; options: BuildOptions; sketchFrom?: number }
  /**
   * Build `source` with `options` again and keep it as `build`, answering nothing: a plant still on
   * the page whose worker was replaced (Stop, a crash, an abandoned build) is kept by the new one,
   * so its panels go on answering. Questions posted after it are answered from it.
   */
  | { kind: 'keep'; build: number; source: string; options: BuildOptions }
  /** Ask kept build `build` a question; `id` ties the answer to it. */
  | { kind: 'inspect'; id: number; build: number; question: InspectQuestion; args: (number | string)[] }
  /** Release kept build `build`. */
  | { kind: 'free'; build: number }
  /**
   * Load the studio core (crate/pkg, built for speed) in the background: builds made once it has
   * loaded use it, and their inspectors answer every question (the page asks once its first load is
   * done; a failed load is logged and the first plant's core goes on building).
   */
  | { kind: 'studio-core' };

/** The build request alone. */
export type BuildRequest = Extract<WorkerRequest, { kind: 'build' }>;

/** What an inspect question answers (what the `PlantInspector` method returns). */
export type InspectAnswer = Awaited<ReturnType<PlantInspector[InspectQuestion]>>;

/** Plants of at least this many segments are first sent as a sketch (lines), then meshed. */
export const SKETCH_MIN_SEGMENTS = 20_000;

/** The shortest time between two progress messages of one build (ms): a stage's start always goes. */
export const PROGRESS_INTERVAL = 50;

/**
 * Whether a build's progress at stage `next` goes to the page `sinceMs` after the last one sent
 * (at stage `last`): every stage start, steps at most every {@link PROGRESS_INTERVAL} ms. Between
 * steps the environment's pass goes after any step (it may be the long part), a step after it
 * only in time: the line never says "step" while the environment works, nor sends two messages a
 * step.
 */
export function progressWanted(last: string, next: BuildProgress['stage'], sinceMs: number): boolean {
  if (sinceMs >= PROGRESS_INTERVAL) return true;
  return next !== last && !(last === 'environment' && next === 'deriving');
}

/**
 * A build as the worker posts it: its diagnostics as their columns, whose buffers are transferred
 * with the mesh's (a text of 100,000 problems posted as objects held the page 60–240 ms a build).
 */
export type PostedBuild = Omit<PlantBuild, 'diagnostics'> & { diagnostics: DiagnosticColumns };

/** What the worker posts of `build`. */
export function postedBuild(build: PlantBuild): PostedBuild {
  return { ...build, diagnostics: build.diagnostics.columns };
}

/** The build the worker posted, on the page (its diagnostics read from their columns, nothing copied). */
export function receivedBuild(posted: PostedBuild): PlantBuild {
  return { ...posted, diagnostics: new DiagnosticList(posted.diagnostics) };
}

/** Worker → page. */
export type WorkerResponse =
  /** Build `id` is at this stage or derivation step (at most one per {@link PROGRESS_INTERVAL}, besides stage starts). */
  | { kind: 'progress'; id: number; progress: BuildProgress }
  /** Build `id`'s plant as lines, before its tubes (only for big plants, see `sketchFrom`; the build follows). */
  | { kind: 'sketch'; id: number; sketch: PlantSketch }
  | {
      kind: 'built';
      id: number;
      build: PostedBuild;
      /** The mesh's normals and colours packed for the GPU (the view sends these, not the floats). */
      gpu: GpuArrays;
      /** Time of the core call inside the worker, copying the arrays out of wasm memory included. */
      workerMillis: number;
      /** Whether the studio core (crate/pkg) built it, rather than the first plant's. */
      studioCore: boolean;
    }
  | {
      /** The core threw (a panic is a bug); the worker's wasm instance is no longer trusted. */
      kind: 'crashed';
      id: number;
      message: string;
    }
  | { kind: 'inspected'; id: number; answer: InspectAnswer };

/** The build answer alone. */
export type BuildResponse = Extract<WorkerResponse, { kind: 'built' | 'crashed' }>;

/** The sketch answer alone. */
export type SketchResponse = Extract<WorkerResponse, { kind: 'sketch' }>;

/** The distinct non-empty buffers of `arrays`. */
function buffersOf(arrays: readonly ArrayBufferView[]): ArrayBuffer[] {
  const buffers = new Set<ArrayBuffer>();
  for (const array of arrays) if (array.buffer instanceof ArrayBuffer && array.buffer.byteLength > 0) buffers.add(array.buffer);
  return [...buffers];
}

/**
 * The buffers of every typed array in `build` (and `gpu`), each once: posting them with this transfer
 * list moves them to the other side (no copy) and leaves them detached (length 0) here.
 */
export function transferablesOf(build: PostedBuild, gpu?: GpuArrays): ArrayBuffer[] {
  // The mesh's optional arrays (its growth) are absent when not asked for.
  const mesh = Object.values(build.mesh).filter((a): a is ArrayBufferView => ArrayBuffer.isView(a));
  return [...new Set([...buffersOf([...mesh, build.origins, ...(gpu ? [gpu.normals, gpu.colors] : [])]), ...columnBuffers(build.diagnostics)])];
}

/** The buffers of an inspect answer (the typed arrays among its fields), for its transfer list. */
export function answerTransferables(answer: InspectAnswer): ArrayBuffer[] {
  if (answer === null || typeof answer !== 'object' || Array.isArray(answer)) return [];
  return buffersOf(Object.values(answer).filter((v): v is Uint32Array => v instanceof Uint32Array));
}
