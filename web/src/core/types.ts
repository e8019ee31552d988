// The plain data that crosses from the core into the studio. Nothing here refers to WebAssembly
// (the options type is the core's declaration, a type only): the rest of the front end programs
// against these types only.
import type { BuildOptions as CoreBuildOptions } from '../../../crate/pkg-core/meristem_core.js';
import type { DiagnosticList } from './diagnostic-list';

/** How bad a diagnostic is; an `error` means the build produced no geometry. */
export type Severity = 'error' | 'warning';

/**
 * One problem found in a grammar, exactly as the core reports it (`diagnostics.rs`,
 * `LocatedDiagnostic`). Offsets are UTF-8 **byte** offsets into the source text: convert them
 * with {@link byteOffsetToUtf16} before handing them to anything that counts UTF-16 units
 * (CodeMirror, `String.prototype.slice`).
 */
export interface Diagnostic {
  severity: Severity;
  /** Stable code such as `E0101`, listed in docs/LANGUAGE.md. */
  code: string;
  message: string;
  /** Start of the span: UTF-8 byte offset into the source. */
  fromByte: number;
  /** End of the span (exclusive): UTF-8 byte offset into the source. */
  toByte: number;
  /** 1-based line of `fromByte`. */
  line: number;
  /** 1-based column of `fromByte`, counted in Unicode scalar values. */
  column: number;
}

/** An axis-aligned box as `[[minX, minY, minZ], [maxX, maxY, maxZ]]`. */
export type Bounds = [[number, number, number], [number, number, number]];

/** Sizes of one build, as reported by the core (and by `meristem derive --stats`). */
export interface PlantStats {
  /** Modules in the derived string. */
  modules: number;
  /** Segments the turtle drew. */
  segments: number;
  /** Mesh vertices (`mesh.positions.length / 3`). */
  vertices: number;
  /** Mesh triangles (`mesh.indices.length / 3`). */
  triangles: number;
  /** Segments drawn as lines because the model was too large to mesh (0 normally). */
  lines: number;
  /** Derivation steps actually applied. */
  iterations: number;
  /** Bounding box of the plant in world units (+Y is up). */
  bounds: Bounds;
}

/**
 * The triangle mesh of a plant as flat typed arrays, owned by JavaScript (copied out of wasm
 * memory, so they stay valid however the core's memory grows).
 *
 * The layout is defined once, on the core's `MeshBuffers` (`crate/src/mesh/buffers.rs`); in short:
 * `positions`, `normals` and `colors` hold 3 floats per vertex, `indices` 3 per triangle;
 * `ranges` holds (first triangle, derived-string module) pairs; `lines`/`lineColors` hold two
 * 3-float ends per segment, only when the model was too large to mesh (the triangles are then empty);
 * `uvs` holds 2 floats (texture coordinates) per vertex and `materialRanges` (first triangle,
 * material kind) pairs: 0 bark (tubes), 1 leaf (leaves, petals, polygons), 2 plain (spheres).
 * `segmentEnds`/`segmentColors` hold every segment as a line (two 3-float ends each) whatever the
 * mesh, and `segmentModules` the derived-string module that drew each: the view's Lines mode.
 * `growthOrigins` (3 floats) and `growthTimes` (2 floats: t0, t1 in derivation steps) per vertex
 * (per line end when the mesh is lines) are there only when `BuildOptions.growth` asked for the
 * plant's growth in time: a vertex at growth time t is at
 * `origin + (position − origin) · smoothstep(clamp((t − t0) / (t1 − t0), 0, 1))`. With them,
 * `segmentGrowthTimes` holds each segment's (t0, t1) (2 floats, in the order of `segmentEnds`): the
 * Lines mode's line grows from its start by the same formula.
 */
export interface MeshBuffers {
  positions: Float32Array;
  normals: Float32Array;
  colors: Float32Array;
  indices: Uint32Array;
  ranges: Uint32Array;
  uvs: Float32Array;
  materialRanges: Uint32Array;
  lines: Float32Array;
  lineColors: Float32Array;
  segmentEnds: Float32Array;
  segmentColors: Float32Array;
  segmentModules: Uint32Array;
  growthOrigins?: Float32Array;
  growthTimes?: Float32Array;
  segmentGrowthTimes?: Float32Array;
}

/**
 * A mesh's normals and colours packed for the GPU by the core (`crate/src/mesh/pack.rs`): normals
 * as 16-bit and colours as 8-bit normalized integers, 6 and 3 bytes a vertex instead of 12 and 12.
 * What the build worker sends the view in place of the floats (`inspectPlant`'s `forGpu` request).
 */
export interface GpuArrays {
  normals: Int16Array;
  colors: Uint8Array;
}

/**
 * Options of {@link buildPlant}: the core's own `BuildOptions` (generated from the table of
 * `crate/src/wasm/options.rs`) without `sketch` and `sketchFirst`, which the facade sets itself,
 * and `tubes`: whether a sketched build ({@link inspectPlant} with a sketch request, the studio's
 * worker) meshes the
 * segments as tubes. `false` leaves them out (the Lines mode draws the segments as lines: the mesh
 * holds only leaves, polygons and spheres); `'unlessFlat'` leaves them out of flat plants (the
 * `auto` render mode draws those as lines); `true` or absent meshes them. Builds without a sketch
 * and exports always mesh them.
 */
export type BuildOptions = Omit<CoreBuildOptions, 'sketch' | 'sketchFirst'> & { tubes?: boolean | 'unlessFlat' };

/**
 * A stage of a build, as the core reports it (in this order); `environment` alternates with
 * `deriving` while the environment answers `?E` between steps (docs/LANGUAGE.md, "Environment").
 */
export type BuildStage = 'parsing' | 'deriving' | 'environment' | 'interpreting' | 'meshing';

/**
 * Where a build is: the stage that just started, and while deriving, `step` of the `steps`
 * derivation steps done (told from 0 of n, then after each step; both 0 in the other stages);
 * `environment`: the environment answers the `?E` of the plant of step `step` (0: the axiom).
 */
export interface BuildProgress {
  stage: BuildStage;
  step: number;
  steps: number;
}

/**
 * How long each stage of one build took, in milliseconds, measured with `performance.now()` read
 * by the core between its stages (the core has no clock of its own). A stage that did not run
 * (after an error) took 0.
 */
export interface StageTimings {
  /** Parsing the text and resolving it into a model. */
  parseResolve: number;
  /** Deriving the string (including the turtle runs that answer query modules). */
  derive: number;
  /** Interpreting the string with the turtle. */
  interpret: number;
  /** Building the mesh. */
  mesh: number;
}

/** Everything one run of the pipeline (parse → resolve → derive → interpret → mesh) produced. */
export interface PlantBuild {
  /** True when no diagnostic is an error; only then do `mesh` and `stats` describe a plant. */
  ok: boolean;
  /** In source order (by span), as columns: an object made for each one read (./diagnostic-list.ts). */
  diagnostics: DiagnosticList;
  stats: PlantStats;
  mesh: MeshBuffers;
  /** The derived string, cut to its first {@link DERIVED_PREVIEW_CHARS} characters (then ending in "…"). */
  derived: string;
  /** Time per stage. */
  timings: StageTimings;
  /** Everything drawn lies in the plane z = 0 (a grammar that only turns with `+` and `-`). */
  flat: boolean;
  /** The grammar's own `#iterations` (0 when it has none), whatever `BuildOptions.iterations` asked. */
  grammarIterations: number;
  /** The seed the derivation used: `BuildOptions.seed`, or the grammar's `#seed`. */
  seed: number;
  /** Modules in the derived string. */
  moduleCount: number;
  /**
   * The grammar has timed modules (`#terminal_age`, ABOP 6.1): its plant at a growth time t is
   * derived at t (`BuildOptions.time`), not grown on the GPU from the whole plant's.
   */
  timed: boolean;
  /**
   * The grammar declares surfaces (`#surface`, `#patch`), which only the studio core draws: the
   * build worker builds it with that core (the first plant's resolves it without them).
   */
  declaresSurfaces: boolean;
  /**
   * The grammar declares an environment (`#environment`, `#stand`, `#plant`), which only the studio
   * core runs: the build worker builds it with that core (the first plant's resolves it without).
   */
  declaresEnvironment: boolean;
  /**
   * The grammar places the turtle by coordinates or draws its frame (`@LineTo`, `@R`, `@Frame`,
   * L-Py's commands), which only the studio core draws: the build worker builds it with that core.
   */
  placesByCoordinates: boolean;
  /**
   * What the build knows of its environment after its last step (the views draw it): present when
   * the grammar declares one and the studio core built it.
   */
  environment?: EnvironmentData;
  /**
   * The grammar is stepwise: a `#dt` without timed modules (L-Py's and cpfg's continuous growth,
   * whose modules change with their age at every step). Its plant at growth time t is its
   * derivation's at step ⌊t⌋, not grown on the GPU from the whole plant's (which would show every
   * organ at its final size). Known from the studio core only (false from the first plant's).
   */
  stepwise: boolean;
  /**
   * The step the derivation went on from when it continued an earlier build's (`inspectPlant`'s
   * `from`: only the steps after it were derived); absent when it derived from the axiom.
   */
  continuedFrom?: number;
  /** The productions of the productions section, in source order (indices as in `origins`). */
  productions: ProductionInfo[];
  /**
   * Provenance of the last step: for each module of the derived string, the index of the production
   * that wrote it, or {@link NOT_REWRITTEN} when it was copied.
   */
  origins: Uint32Array;
}

/** In `PlantBuild.origins`: no production wrote this module in the last step. */
export const NOT_REWRITTEN = 0xffffffff;

/** One production of the grammar, located in the source text. */
export interface ProductionInfo {
  /** Index among the productions (what `origins` and `explain` use). */
  index: number;
  /** UTF-16 range of the production in the source text. */
  from: number;
  to: number;
  label: string | null;
  /** Whether it has a left or right context. */
  context: boolean;
  /** UTF-16 range of its condition in the source text, or null. */
  condition: { from: number; to: number } | null;
}

/** Why and where one production fired in the last step (module indices of the derived string). */
export interface Explanation {
  production: number;
  /** Modules it rewrote. */
  fired: number;
  /** Modules whose predecessor and contexts matched it. */
  contextMatched: number;
  /** Of those, modules whose condition was false. */
  conditionFailed: number;
  /** Modules of the derived string it wrote. */
  produced: Uint32Array;
  /** Modules descending from the modules that served as its left / right context. */
  leftContext: Uint32Array;
  rightContext: Uint32Array;
}

/** How one context of a production met the string around a module (see {@link MatchReport}). */
export interface ContextCheck {
  /** The whole context matched (also when the production has none). */
  matched: boolean;
  /** The modules that matched it (indices of the string the last step read). */
  modules: number[];
  /** Where it did not match: the element the production expected (`C`, `[`, `]`)… */
  expected: string | null;
  /** …and the module found there instead, with its text. */
  found: number | null;
  foundText: string | null;
}

/**
 * Why a production did or did not rewrite a module in the last step: each part of the production
 * checked against the module of the string that step read (`module`, an index of that string).
 */
export interface MatchReport {
  production: number;
  module: number;
  moduleText: string;
  /** The module is the production's predecessor (name and number of parameters). */
  predecessor: boolean;
  left: ContextCheck;
  right: ContextCheck;
  /** The condition's value when there is one and the predecessor and contexts matched. */
  condition: boolean | null;
  /** The production that did rewrite the module in the last step (null: it was copied). */
  rewrittenBy: number | null;
}

/** One step of the derivation as a sequence: its string, and where each module comes from. */
export interface DerivationStep {
  /** Each module as written. */
  texts: string[];
  /** For each module, the module of the step before it comes from (empty at step 0). */
  parent: number[];
  /** For each module, the production that wrote it in this step ({@link NOT_REWRITTEN}: copied). */
  origin: number[];
  /**
   * A timed grammar's growth time of this string, in steps (ABOP 6.1: each step a round of
   * replacements at the moment it happened; after the last round, a step that only ages every
   * module to the time asked, each module its own parent). Absent for other grammars.
   */
  time?: number;
}

/** One step of a module's lineage (the debugger): its ancestor at that step, and what made it. */
export interface LineageRow {
  /** The step (0: the axiom). */
  step: number;
  /** The ancestor's index in that step's string, and its text. */
  module: number;
  text: string;
  /** The production that wrote it in that step (absent: copied, or the axiom's). */
  production?: number;
  /** A timed grammar's growth time of that step, in steps. */
  time?: number;
  /** The modules of the derived string that descend from it: `first` to `last`. */
  first: number;
  last: number;
}

/** A module's lineage, the last step first, back to the axiom; or why there is none. */
export type Lineage = { rows: LineageRow[] } | { error: string };

/**
 * Where Play pauses for a breakpoint: the step, how many times its production fired there (or
 * for how many modules its watch held), and the first such module of that step's string; `never`
 * when it does not pause in the steps derived.
 */
export type BreakpointAnswer = { pause: { step: number; count: number; module: number } } | { never: object } | { error: string };

/** The last step's links: for each module of the derived string, the module of the string before. */
export interface LastStepLinks {
  parents: Uint32Array;
  /** Modules in the string the last step read. */
  previousCount: number;
}

/** Questions about one build that need the core's full derivation (kept alive until `free`). */
export interface PlantInspector {
  /** Explains a production on the last step; null before the first step. */
  explain(production: number): Promise<Explanation | null>;
  /**
   * Explains how one module of the derived string was made: the production that wrote it and the
   * contexts of that one rewriting (the counts cover the whole string); null when it was copied.
   */
  explainModule(module: number): Promise<Explanation | null>;
  /** The text of modules `start .. start + count` of the derived string. */
  moduleTexts(start: number, count: number): Promise<string[]>;
  /** A fingerprint of the derived string (16 hex digits; '' once freed): equal for equal derivations. */
  derivedHash(): Promise<string>;
  /**
   * Why production `production` did or did not rewrite the module that module `module` of the
   * derived string comes from; null before the first step.
   */
  matchReport(production: number, module: number): Promise<MatchReport | null>;
  /** Every step of the derivation when all their strings hold `maxModules` modules or fewer together; else null. */
  sequence(maxModules: number): Promise<DerivationStep[] | null>;
  /** The lineage of one module of the derived string (derived again, step by step). */
  lineage(module: number): Promise<Lineage>;
  /**
   * Where a breakpoint pauses: with `watch` empty, at the first firing of production `production`;
   * else at the first step where the watch (`A(x) : x > 3`, read with the grammar `source`) holds.
   */
  breakpoint(source: string, production: number, watch: string): Promise<BreakpointAnswer>;
  /** The text of modules `start .. start + count` of the string the last step read. */
  previousTexts(start: number, count: number): Promise<string[]>;
  /** Where each module of the derived string comes from in the string before. */
  lastStep(): Promise<LastStepLinks>;
  /** Releases the core's memory; later questions answer null / []. */
  free(): void;
}


/** How many characters of the derived string {@link buildPlant} keeps. */
export const DERIVED_PREVIEW_CHARS = 10_000;

/**
 * One program's grid of values (the light program's exposure, 0 to 1): `values` has
 * `dims[0] × dims[1] × dims[2]` entries, x fastest; voxel (i, j, k) spans `origin + cell × (i, j, k)`
 * to `origin + cell × (i + 1, j + 1, k + 1)`. A grid above a million voxels comes averaged over
 * blocks (a larger `cell`).
 */
export interface EnvironmentField {
  /** The program's index among the grammar's `#environment` lines. */
  program: number;
  /** The program's name (`light`). */
  name: string;
  origin: [number, number, number];
  cell: number;
  dims: [number, number, number];
  /** The smallest and largest value. */
  min: number;
  max: number;
  values: Float32Array;
}

/** An obstacle's solid, in the model's coordinates (+Y up). */
export type EnvironmentSolid =
  | { shape: 'box'; min: [number, number, number]; max: [number, number, number] }
  | { shape: 'sphere'; center: [number, number, number]; radius: number }
  /** The half-space behind the plane through `point`; `normal` (unit) points to the free side. */
  | { shape: 'plane'; point: [number, number, number]; normal: [number, number, number] };

/** What a build knows of its environment after its last step (`PlantBuild.environment`). */
export interface EnvironmentData {
  fields: EnvironmentField[];
  solids: EnvironmentSolid[];
  /** The attraction points left, x, y, z each (at most 100,000). */
  points: Float32Array;
  /** The names of the values a `?E` is answered with, every program's in the order declared. */
  replies: string[];
}
