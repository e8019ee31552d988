// The facade over the core's `build`: one call, plain data out, the wasm object freed (or turned
// into the inspector or the editor that mirror it).
import {
  build,
  type BuildOptions as CoreBuildOptions,
  type PlantBuild as WasmPlantBuild,
  type PlantInspector as WasmPlantInspector,
  type SketchFirst,
} from '../../../crate/pkg-core/meristem_core.js';
import type {
  build as studioBuildType,
  buildOn as studioBuildOnType,
  Explanation as WasmExplanation,
  PlantEditor as WasmPlantEditor,
  PlantInspector as StudioPlantInspector,
} from '../../../crate/pkg/meristem.js';
import { diagnosticList } from './diagnostic-list';
import { utf16Offsets } from './offsets';
import { assertReady, guarded, ownedArray } from './init';
import type { SpareArrays, SpareCopies } from './spare-copies';
import {
  DERIVED_PREVIEW_CHARS,
  type BuildOptions,
  type BuildProgress,
  type BuildStage,
  type Diagnostic,
  type DerivationStep,
  type EnvironmentData,
  type Explanation,
  type GpuArrays,
  type BreakpointAnswer,
  type LastStepLinks,
  type Lineage,
  type MatchReport,
  type MeshBuffers,
  type PlantBuild,
  type PlantInspector,
  type ProductionInfo,
  type PlantStats,
  type Severity,
  type StageTimings,
} from './types';

/** The timings of a build made without a clock (none is: this facade always lends one). */
const NO_TIMINGS: StageTimings = { parseResolve: 0, derive: 0, interpret: 0, mesh: 0 };

/** A diagnostic as the core serialises it (byte offsets named `from`/`to`). */
export interface RawDiagnostic {
  severity: Severity;
  code: string;
  message: string;
  from: number;
  to: number;
  line: number;
  column: number;
}

/**
 * Runs the whole pipeline (parse → resolve → derive → interpret → mesh) on `source` and returns
 * plain data that stays valid after the call: the typed arrays are owned by JavaScript and the
 * core's `PlantBuild` object has been freed. Grammar errors never throw: they come back as
 * `diagnostics` with `ok: false`. A throw means the core itself failed (a bug, e.g. a panic).
 * Requires {@link initCore} to have finished.
 */
export function buildPlant(source: string, options: BuildOptions = {}): PlantBuild {
  const result = runBuild(source, options);
  try {
    return plainBuild(source, result);
  } finally {
    result.free();
  }
}

/** The studio core's `build` (crate/pkg), once {@link useStudioCore} gave it. */
let studioBuild: typeof studioBuildType | undefined;

/** Its copies of a big build into spare buffers (./spare-copies.ts), given with it. */
let spareCopies: SpareCopies | undefined;

/** The studio core's `buildOn` (a build that continues a kept one's derivation), given with it. */
let studioBuildOn: typeof studioBuildOnType | undefined;

/** The studio core's copy of a build's environment (./environment.ts), given with it. */
let environmentOf: ((result: object) => EnvironmentData | undefined) | undefined;

/**
 * Makes {@link inspectPlant} build with the whole boundary's module (crate/pkg, already
 * instantiated), whose inspectors also explain, report matches and trace the derivation: what
 * the first plant's core leaves out (issue 22), and copy a big plant for the GPU into `copies`'s
 * spare buffers where it has some. Called by ./studio-core.ts.
 */
export function useStudioCore(core: typeof studioBuildType, copies?: SpareCopies, on?: typeof studioBuildOnType, environment?: typeof environmentOf): void {
  studioBuild = core;
  spareCopies = copies;
  studioBuildOn = on;
  environmentOf = environment;
}

/**
 * Spare buffers of these sizes (bytes; by default the sizes of the last build's arrays that go
 * into spares) for the next build for the GPU's biggest arrays, their pages touched while the
 * build worker waits (./spare-buffers.ts); nothing until the studio core is in use.
 */
export function prepareSpares(sizes?: readonly number[]): void {
  spareCopies?.prepare(sizes);
}

/** Whether {@link inspectPlant}'s inspectors answer every question (the studio core is in use). */
export function studioCoreInUse(): boolean {
  return studioBuild !== undefined;
}

/**
 * Whether the first plant's core built `build` without what its grammar needs (the clock of timed
 * modules, declared surfaces, an environment, L-Py's placing commands: no room in its first load), so that it must be built
 * again once {@link loadStudioCore} is done.
 */
export function needsStudioCore(build: Pick<PlantBuild, 'timed' | 'declaresSurfaces' | 'declaresEnvironment' | 'placesByCoordinates'>): boolean {
  return buildsWithStudioCore(build) && !studioCoreInUse();
}

/** Whether `build`'s grammar needs what only the studio core builds (see {@link needsStudioCore}). */
export function buildsWithStudioCore(build: Pick<PlantBuild, 'timed' | 'declaresSurfaces' | 'declaresEnvironment' | 'placesByCoordinates'>): boolean {
  return build.timed || build.declaresSurfaces || build.declaresEnvironment || build.placesByCoordinates;
}

/** How {@link inspectPlant} builds: a sketch first, progress, arrays for the GPU. */
export interface InspectRequest {
  /** A sketch of a big plant, shown while its tubes are meshed in the same call into the core. */
  sketch?: SketchRequest;
  /**
   * Told each stage as it starts and each derivation step as it ends (the core calls it while it
   * works, so it can only post messages, not wait for an answer).
   */
  onProgress?: (progress: BuildProgress) => void;
  /**
   * The mesh's normals and colours packed for the GPU (`gpu`) in place of `build.mesh.normals`
   * and `.colors` (then empty): what the build worker sends the view.
   */
  forGpu?: boolean;
  /**
   * An inspector of an earlier build of the same text and options but fewer iterations: its
   * derivation goes on from there (only the new steps are derived; `build.continuedFrom` says
   * from which), when the studio core built it and the grammar allows (docs/LANGUAGE.md,
   * "Stepping"); otherwise the build derives from the axiom. The plant is the same either way.
   * `from` is only read: it stays the caller's, to keep or free.
   */
  from?: PlantInspector;
}

/**
 * Like {@link buildPlant}, and also keeps the core's derivation alive behind a
 * {@link PlantInspector} (explanations, module texts) until its `free` is called. One call into
 * the core makes the plant (with `request.sketch`, its sketch first). Built by the first plant's
 * core, the inspector gives module texts and the last step's links, and throws on the questions
 * only the studio core answers (`explain`, `explainModule`, `matchReport`, `sequence`): after
 * `loadStudioCore`, every inspector answers them all.
 */
export function inspectPlant(source: string, options?: BuildOptions, request?: InspectRequest & { forGpu?: false }): { build: PlantBuild; inspector: PlantInspector };
export function inspectPlant(source: string, options: BuildOptions, request: InspectRequest & { forGpu: true }): { build: PlantBuild; inspector: PlantInspector; gpu: GpuArrays };
export function inspectPlant(source: string, options: BuildOptions = {}, request: InspectRequest = {}): { build: PlantBuild; inspector: PlantInspector; gpu?: GpuArrays } {
  const { sketch, onProgress, forGpu = false, from } = request;
  assertReady(); // (the first plant's core: the studio core goes with it)
  const core = coreFor(from);
  const result = runBuildWith(core, source, { ...options, sketchFirst: sketch && sketchFirst(sketch, options) }, onProgress);
  let plain: PlantBuild;
  let gpu: GpuArrays | undefined;
  try {
    const stats = guarded(() => JSON.parse(result.stats()) as PlantStats);
    // For the GPU (the build worker): the biggest arrays into spare buffers where there are some.
    const spares = forGpu ? guarded(() => spareCopies?.copy(result, stats) ?? {}) : {};
    plain = plainBuild(source, result, { forGpu, spares, stats });
    if (forGpu) {
      gpu = guarded(() => ({
        normals: spares.normals ?? ownedArray(result.packedNormals()),
        colors: spares.colors ?? ownedArray(result.packedColors()),
      }));
    }
  } catch (error) {
    result.free();
    throw error;
  }
  const moduleCount = plain.moduleCount;
  return { build: plain, inspector: new LiveInspector(guarded(() => result.intoInspector()), moduleCount, studioBuild !== undefined), gpu };
}

/**
 * The core's `build` for {@link inspectPlant}: the studio core's when loaded (the first plant's
 * otherwise), continuing `from`'s derivation when the studio core built `from` too (an inspector
 * of one module cannot be read by the other).
 */
function coreFor(from: PlantInspector | undefined): (...args: Parameters<typeof build>) => WasmPlantBuild {
  const kept = from instanceof LiveInspector ? from.studioInspector() : undefined;
  const on = studioBuildOn;
  if (kept && on) return (source, options, clock, progress) => on(source, options, kept, clock, progress);
  return studioBuild ?? build;
}

/** A big plant's skeleton as lines, shown while its tubes are meshed (see {@link inspectPlant}). */
export interface PlantSketch {
  /** Line ends, x, y, z each: two per segment. */
  lines: Float32Array;
  /** Linear RGB per line end. */
  lineColors: Float32Array;
  /** As {@link PlantBuild.flat}. */
  flat: boolean;
  segments: number;
}

/** Asks {@link inspectPlant} for a sketch of plants of at least `minSegments` segments. */
export interface SketchRequest {
  minSegments: number;
  /** Called with the sketch before the tubes are meshed (not called for smaller plants or errors). */
  show: (sketch: PlantSketch) => void;
}

/**
 * The core's `sketchFirst` for `request`: the sketch's arrays, which the core lends as views of
 * its memory, copied (into spare buffers where there are some: the build worker's) before
 * `request.show` sees them; the mesh after it without the tubes when `options.tubes` says so.
 */
function sketchFirst(request: SketchRequest, options: BuildOptions): SketchFirst {
  return {
    minSegments: request.minSegments,
    tubes: options.tubes,
    show: (lines, lineColors, flat, segments) => {
      const spares = spareCopies?.copySketch(lines, lineColors) ?? {};
      request.show({ lines: spares.lines ?? lines.slice(), lineColors: spares.lineColors ?? lineColors.slice(), flat, segments });
    },
  };
}

/** Runs the core's `build` (for this folder's facades; the caller frees the result). */
export function runBuild(source: string, options: CoreBuildOptions, onProgress?: (progress: BuildProgress) => void): WasmPlantBuild {
  assertReady();
  return runBuildWith(build, source, options, onProgress);
}

/**
 * Runs `core`, the `build` of either core module (the first plant's, or the whole boundary's for
 * what only it has: branch editing, ./branches.ts), which the caller has checked is instantiated
 * (the page has no instance of the first plant's core, only of the whole boundary's once it edits
 * branches). The caller frees the result.
 */
export function runBuildWith<B>(core: (...args: Parameters<typeof build>) => B, source: string, options: CoreBuildOptions, onProgress?: (progress: BuildProgress) => void): B {
  const { iterations, seed, time, sides, smoothAll, sketch, sketchFirst, growth } = options;
  const progress = onProgress && ((stage: BuildStage, step: number, steps: number) => onProgress({ stage, step, steps }));
  // The core reads no clock: it reads ours between its stages.
  return guarded(() => core(source, { iterations, seed, time, sides, smoothAll, sketch, sketchFirst, growth }, () => performance.now(), progress));
}

interface RawProduction {
  index: number;
  from: number;
  to: number;
  label: string | null;
  context: boolean;
  condition: [number, number] | null;
}

/** How {@link plainBuild} copies a build. */
export interface PlainCopy {
  /** Without the mesh's float normals and colours (empty arrays): the caller takes them packed for the GPU. */
  forGpu?: boolean;
  /** Arrays already copied ({@link copyMesh}). */
  spares?: SpareArrays;
  /** The build's stats, when the caller has already read them (they are read once a build). */
  stats?: PlantStats;
}

/** Copies a wasm build into plain data (for this folder's facades; the caller frees the build). */
export function plainBuild(source: string, result: WasmPlantBuild, { forGpu = false, spares = {}, stats }: PlainCopy = {}): PlantBuild {
  const toUtf16 = utf16Offsets(source);
  return guarded(() => ({
    ok: result.ok,
    diagnostics: diagnosticList((JSON.parse(result.diagnostics()) as RawDiagnostic[]).map(toDiagnostic)),
    stats: stats ?? (JSON.parse(result.stats()) as PlantStats),
    mesh: copyMesh(result, { forGpu, spares }),
    derived: result.derived(DERIVED_PREVIEW_CHARS),
    moduleCount: result.moduleCount,
    productions: (JSON.parse(result.productions()) as RawProduction[]).map(
      (p): ProductionInfo => ({
        index: p.index,
        from: toUtf16(p.from),
        to: toUtf16(p.to),
        label: p.label,
        context: p.context,
        condition: p.condition && { from: toUtf16(p.condition[0]), to: toUtf16(p.condition[1]) },
      }),
    ),
    origins: ownedArray(result.origins()),
    timings: (JSON.parse(result.timings()) as StageTimings | null) ?? NO_TIMINGS,
    flat: result.flat,
    grammarIterations: result.grammarIterations,
    seed: result.seed,
    timed: result.timed,
    declaresSurfaces: result.declaresSurfaces,
    placesByCoordinates: result.placesByCoordinates,
    declaresEnvironment: result.declaresEnvironment,
    environment: environmentOf?.(result),
    // (A getter of the studio core's builds only.)
    stepwise: 'stepwise' in result && result.stepwise === true,
    ...(result.continuedFrom === undefined ? {} : { continuedFrom: result.continuedFrom }),
  }));
}

/** The core's classes that hold a plant's mesh: a build and an editor. */
type MeshHolder = WasmPlantBuild | WasmPlantEditor;

/**
 * Copies every mesh array of a wasm build or editor out of wasm memory (`forGpu`: see
 * {@link PlainCopy}), but those already in `spares`.
 */
export function copyMesh(result: MeshHolder, { forGpu = false, spares = {} }: Pick<PlainCopy, 'forGpu' | 'spares'> = {}): MeshBuffers {
  return guarded(() => ({
    ...growthOf(result),
    positions: spares.positions ?? ownedArray(result.positions()),
    normals: forGpu ? new Float32Array(0) : ownedArray(result.normals()),
    colors: forGpu ? new Float32Array(0) : ownedArray(result.colors()),
    indices: spares.indices ?? ownedArray(result.indices()),
    ranges: ownedArray(result.ranges()),
    uvs: spares.uvs ?? ownedArray(result.uvs()),
    materialRanges: ownedArray(result.materialRanges()),
    lines: ownedArray(result.lines()),
    lineColors: ownedArray(result.lineColors()),
    segmentEnds: spares.segmentEnds ?? ownedArray(result.segmentEnds()),
    segmentColors: spares.segmentColors ?? ownedArray(result.segmentColors()),
    segmentModules: ownedArray(result.segmentModules()),
  }));
}

/**
 * The mesh's growth arrays, when the build asked for them (`BuildOptions.growth`) and the studio
 * core made it (the first plant's core has no growth in time); else nothing.
 */
function growthOf(result: MeshHolder): Pick<MeshBuffers, 'growthOrigins' | 'growthTimes' | 'segmentGrowthTimes'> {
  if (!('growthTimes' in result)) return {};
  const owned = (values: Float32Array) => (values.length > 0 ? ownedArray(values) : undefined);
  return { growthOrigins: owned(result.growthOrigins()), growthTimes: owned(result.growthTimes()), segmentGrowthTimes: owned(result.segmentGrowthTimes()) };
}

/** Copies a wasm explanation into plain data and frees it. */
function toExplanation(explained: WasmExplanation | undefined): Explanation | null {
  if (!explained) return null;
  try {
    return {
      production: explained.production,
      fired: explained.fired,
      contextMatched: explained.contextMatched,
      conditionFailed: explained.conditionFailed,
      produced: ownedArray(explained.produced()),
      leftContext: ownedArray(explained.leftContext()),
      rightContext: ownedArray(explained.rightContext()),
    };
  } finally {
    explained.free();
  }
}

/** The questions only the studio core's inspector answers (feature `studio-extras`). */
type StudioQuestions = Pick<StudioPlantInspector, 'explain' | 'explainModule' | 'matchReport' | 'sequence' | 'lineage' | 'breakpoint'>;

/** An inspector of either core module: the first plant's has none of {@link StudioQuestions}. */
type AnyWasmInspector = WasmPlantInspector & Partial<StudioQuestions>;

/** A {@link PlantInspector} over the core's `PlantInspector` on this thread. */
class LiveInspector implements PlantInspector {
  constructor(
    private result: AnyWasmInspector | undefined,
    private readonly moduleCount: number,
    /** Whether the studio core built it (then `result` is one of its inspectors). */
    private readonly byStudioCore: boolean,
  ) {}

  /** The studio core's inspector behind this one, while not freed (what `buildOn` continues). */
  studioInspector(): StudioPlantInspector | undefined {
    return this.byStudioCore ? (this.result as StudioPlantInspector | undefined) : undefined;
  }

  /** The core's inspector for a studio question; throws when it was built by the first plant's core. */
  private studio(): Partial<StudioQuestions> {
    const result = this.result;
    if (result && !result.explain) throw new Error('this plant was built by the first plant\'s core: load the studio core (loadStudioCore) and build it again');
    return result ?? {};
  }

  explain(production: number): Promise<Explanation | null> {
    const core = this.studio();
    return Promise.resolve(toExplanation(guarded(() => core.explain?.(production))));
  }

  explainModule(module: number): Promise<Explanation | null> {
    if (!Number.isInteger(module) || module < 0) return Promise.resolve(null);
    const core = this.studio();
    return Promise.resolve(toExplanation(guarded(() => core.explainModule?.(module))));
  }

  moduleTexts(start: number, count: number): Promise<string[]> {
    const result = this.result;
    if (!result) return Promise.resolve([]);
    const from = Math.max(0, Math.min(start, this.moduleCount));
    const n = Math.max(0, Math.min(count, this.moduleCount - from));
    return Promise.resolve(JSON.parse(guarded(() => result.moduleTexts(from, n))) as string[]);
  }

  derivedHash(): Promise<string> {
    return Promise.resolve(guarded(() => this.result?.derivedHash()) ?? '');
  }

  matchReport(production: number, module: number): Promise<MatchReport | null> {
    if (!Number.isInteger(module) || module < 0) return Promise.resolve(null);
    const core = this.studio();
    const json = guarded(() => core.matchReport?.(production, module));
    return Promise.resolve(json ? (JSON.parse(json) as MatchReport) : null);
  }

  sequence(maxModules: number): Promise<DerivationStep[] | null> {
    const core = this.studio();
    const json = guarded(() => core.sequence?.(maxModules));
    return Promise.resolve(json ? (JSON.parse(json) as DerivationStep[]) : null);
  }

  lineage(module: number): Promise<Lineage> {
    const core = this.studio();
    const json = guarded(() => core.lineage?.(module));
    return Promise.resolve(json ? (JSON.parse(json) as Lineage) : { error: 'no lineage' });
  }

  breakpoint(source: string, production: number, watch: string): Promise<BreakpointAnswer> {
    const core = this.studio();
    const json = guarded(() => core.breakpoint?.(source, production, watch));
    return Promise.resolve(json ? (JSON.parse(json) as BreakpointAnswer) : { error: 'no answer' });
  }

  previousTexts(start: number, count: number): Promise<string[]> {
    const result = this.result;
    if (!result) return Promise.resolve([]);
    const total = result.previousCount;
    const from = Math.max(0, Math.min(start, total));
    const n = Math.max(0, Math.min(count, total - from));
    return Promise.resolve(JSON.parse(guarded(() => result.previousTexts(from, n))) as string[]);
  }

  lastStep(): Promise<LastStepLinks> {
    const result = this.result;
    if (!result) return Promise.resolve({ parents: new Uint32Array(0), previousCount: 0 });
    return Promise.resolve(guarded(() => ({ parents: ownedArray(result.parents()), previousCount: result.previousCount })));
  }

  free(): void {
    this.result?.free();
    this.result = undefined;
  }
}

export function toDiagnostic(raw: RawDiagnostic): Diagnostic {
  return {
    severity: raw.severity,
    code: raw.code,
    message: raw.message,
    fromByte: raw.from,
    toByte: raw.to,
    line: raw.line,
    column: raw.column,
  };
}
