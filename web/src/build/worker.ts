// The build worker: runs the core (parse → resolve → derive → interpret → mesh) off the page's
// main thread, so typing never waits for a big plant. It instantiates its own WebAssembly
// instance (of the module the page compiled and sends first) and answers each request in order:
// builds, whose typed arrays go back in a transfer list, and questions about a kept build (the
// context-sensitivity view's explanations and the derived-string panel's module texts), until the
// page frees it; a plant the page still shows after its worker was replaced is built again and
// kept (`keep`). Once the page's first load is done it asks for the studio core (`studio-core`),
// which later builds use: built for speed, it meshes a big plant in about two thirds of the time.
// Started by createBuildWorker (worker-client.ts). A big plant is first sent as a sketch (its
// segments as lines), then built; once the studio core is in use, its biggest arrays are copied
// into buffers made while the worker waited, sized as the last build's (`prepareSpares`). A build
// of the same text and options as a kept one but more iterations (a step forward, Play) derives
// only the new steps from it (continue-from.ts); a step back derives from the axiom again.
import { CoreCrashed, initCore, inspectPlant, loadStudioCore, needsStudioCore, prepareSpares, studioCoreInUse, type BuildOptions, type BuildProgress, type PlantInspector } from '../core';
import {
  answerTransferables,
  type CoreMessage,
  postedBuild,
  progressWanted,
  SKETCH_MIN_SEGMENTS,
  transferablesOf,
  type InspectAnswer,
  type InspectQuestion,
  type WorkerRequest,
  type WorkerResponse,
} from './worker-protocol';
import type { KeptBuild } from './continue-from';

/** Kept builds at most: the page frees what it does not show, this only bounds a leak. */
const MAX_KEPT = 4;

/** The core: the module the page compiled and sent first (createBuildWorker), else fetched here. */
const ready = new Promise<WebAssembly.Module | null>((resolve) => {
  const first = (event: MessageEvent<CoreMessage | WorkerRequest>) => {
    if (event.data.kind !== 'core') return;
    removeEventListener('message', first);
    resolve(event.data.module);
  };
  addEventListener('message', first);
}).then((module) => initCore(module ?? undefined));
/** A kept build: its inspector, what it was built from, and whether the studio core built it. */
interface Kept extends KeptBuild {
  inspector: PlantInspector;
  studio: boolean;
}
const kept = new Map<number, Kept>();

/**
 * The questions only the studio core answers (crate/pkg: explanations, match reports, the traced
 * derivation), which the first plant's core leaves out (issue 22, the first load). The first one
 * loads the studio core; a build the first plant's core kept is built again with it (the same
 * text and options give the same derivation), and later builds are made with it.
 */
const STUDIO_QUESTIONS: ReadonlySet<InspectQuestion> = new Set<InspectQuestion>(['explain', 'explainModule', 'matchReport', 'sequence', 'lineage', 'breakpoint']);

function reply(response: WorkerResponse, transfer: Transferable[] = []): void {
  postMessage(response, { transfer });
}

/** Keeps build `id` (made by `inspectPlant`), freeing the oldest past {@link MAX_KEPT}. */
function keep(id: number, made: { inspector: PlantInspector; build: { grammarIterations: number } }, source: string, options: BuildOptions): void {
  kept.get(id)?.inspector.free();
  kept.set(id, { inspector: made.inspector, source, options, grammarIterations: made.build.grammarIterations, studio: studioCoreInUse() });
  for (const [oldest, old] of kept) {
    if (kept.size <= MAX_KEPT) break;
    old.inspector.free();
    kept.delete(oldest);
  }
}

/** The inspector of kept build `id` that answers `question`: built again by the studio core if need be. */
async function inspectorFor(id: number, question: InspectQuestion): Promise<PlantInspector | undefined> {
  const entry = kept.get(id);
  if (!entry || entry.studio || !STUDIO_QUESTIONS.has(question)) return entry?.inspector;
  await loadStudioCore();
  buildAgainWithStudioCore(id); // nothing if it was freed meanwhile
  return kept.get(id)?.inspector;
}

/** Kept build `id`, built by the first plant's core, is built again by the studio core (the same text and options give the same derivation). */
function buildAgainWithStudioCore(id: number): void {
  const entry = kept.get(id);
  if (entry && !entry.studio) keep(id, inspectPlant(entry.source, entry.options), entry.source, entry.options);
}

/**
 * Once the studio core has loaded: the newest kept build (the plant on the page) is built again
 * with it, so its questions are answered at once, and the studio core's code for this plant's
 * paths gets compiled for speed before the next edit (V8 optimises a WebAssembly function only
 * after it has run a while, and a long loop stays in the baseline code until its next call: the
 * first edits of a big tree meshed about half as fast without this).
 */
function warmStudioCore(): void {
  const newest = [...kept.keys()].at(-1);
  if (newest === undefined) return;
  try {
    buildAgainWithStudioCore(newest);
  } catch (error) {
    console.error('Meristem: the studio core failed to build the plant shown again', error); // it built before: a bug
  }
}

/** What a question answers when its build is gone (freed, or never kept). */
const UNANSWERED: { [Q in InspectQuestion]: Awaited<ReturnType<PlantInspector[Q]>> } = {
  explain: null,
  explainModule: null,
  moduleTexts: [],
  derivedHash: '',
  matchReport: null,
  sequence: null,
  lineage: { error: '' },
  breakpoint: { error: '' },
  previousTexts: [],
  lastStep: { parents: new Uint32Array(0), previousCount: 0 },
};

/** Asks `inspector` the question by its method's name. */
function answer(inspector: PlantInspector | undefined, question: InspectQuestion, args: (number | string)[]): Promise<InspectAnswer> {
  if (!inspector || !(question in UNANSWERED)) return Promise.resolve(UNANSWERED[question] ?? null);
  const method = inspector[question] as (...args: (number | string)[]) => Promise<InspectAnswer>;
  return method.apply(inspector, args);
}

/** Tells the page build `id`'s progress, as much of it as {@link progressWanted} lets through. */
function progressTeller(id: number): (progress: BuildProgress) => void {
  let last = -Infinity;
  let stage = '';
  return (progress) => {
    const now = performance.now();
    if (!progressWanted(stage, progress.stage, now - last)) return;
    stage = progress.stage;
    last = now;
    reply({ kind: 'progress', id, progress });
  };
}

addEventListener('message', async (event: MessageEvent<WorkerRequest | CoreMessage>) => {
  const request = event.data;
  if (request.kind === 'core') return;
  try {
    await ready;
  } catch (error) {
    if (request.kind === 'build') reply({ kind: 'crashed', id: request.id, message: `the core could not start: ${String(error)}` });
    return;
  }
  if (request.kind === 'studio-core') {
    loadStudioCore().then(warmStudioCore, (error: unknown) => console.warn('Meristem: the studio core could not load; the first plant\'s core goes on building', error));
    return;
  }
  if (request.kind === 'free') {
    kept.get(request.build)?.inspector.free();
    kept.delete(request.build);
    return;
  }
  if (request.kind === 'keep') {
    try {
      keep(request.build, inspectPlant(request.source, request.options), request.source, request.options);
    } catch (error) {
      // It built before, so this is a bug; its questions get the empty answers.
      console.error('Meristem core failed to build a kept plant again', error);
    }
    return;
  }
  if (request.kind === 'inspect') {
    let result: InspectAnswer = UNANSWERED[request.question] ?? null;
    try {
      result = await answer(await inspectorFor(request.build, request.question), request.question, request.args);
    } catch (error) {
      console.error('Meristem core failed to answer', request.question, error);
    }
    reply({ kind: 'inspected', id: request.id, answer: result }, answerTransferables(result));
    return;
  }
  const { id, source, options, sketchFrom = SKETCH_MIN_SEGMENTS } = request;
  try {
    const start = performance.now();
    // Growth in time is the studio core's (the first plant's leaves it out): a build that asks for
    // it (a timeline in use, a link at a time, an animated embed) loads that core first.
    if (options.growth && !studioCoreInUse()) {
      await loadStudioCore().catch((error: unknown) => console.warn('Meristem: the studio core could not load; the plant is built without its growth', error));
    }
    // A big plant goes to the page as lines first: on screen while its tubes are meshed. A kept
    // build of fewer steps is continued (only the studio core continues; the core derives from
    // the axiom when it cannot).
    const made = async () =>
      inspectPlant(source, options, {
        from: studioCoreInUse() ? (await import('./continue-from')).continuable(kept.values(), source, options)?.inspector : undefined,
        sketch: {
          minSegments: sketchFrom,
          show: (sketch) => reply({ kind: 'sketch', id, sketch }, [sketch.lines.buffer as ArrayBuffer, sketch.lineColors.buffer as ArrayBuffer]),
        },
        onProgress: progressTeller(id),
        forGpu: true, // the normals and colours packed for the GPU, not as floats
      });
    let plant = await made();
    if (needsStudioCore(plant.build)) {
      // The first plant's core has no clock for timed modules (ABOP 6.1), draws no declared
      // surfaces (#surface, #patch) and runs no environment (#environment, #stand: no room in its
      // first load): the studio core builds them.
      plant.inspector.free();
      await loadStudioCore();
      plant = await made();
    }
    const { gpu } = plant;
    const build = postedBuild(plant.build);
    keep(id, plant, source, options);
    reply({ kind: 'built', id, build, gpu, workerMillis: performance.now() - start, studioCore: studioCoreInUse() }, transferablesOf(build, gpu));
    // While the page draws it and the user edits: buffers for the next build of this size.
    prepareSpares();
  } catch (error) {
    // A panic carries the core's own message; anything else thrown here is a bug of this file.
    const message = error instanceof CoreCrashed ? error.message : error instanceof Error ? `${error.name}: ${error.message}` : String(error);
    reply({ kind: 'crashed', id, message });
  }
});
