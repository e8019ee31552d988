// The facade over the core's `build`: one call, plain data out, the wasm object freed.
import { build } from '../../../crate/pkg/meristem.js';
import { assertReady, ownedArray } from './init';
import {
  DERIVED_PREVIEW_CHARS,
  type BuildOptions,
  type Diagnostic,
  type PlantBuild,
  type PlantStats,
  type Severity,
  type StageTimings,
} from './types';

const NO_TIMINGS: StageTimings = { parseResolve: 0, derive: 0, interpret: 0, mesh: 0 };

/** A diagnostic as the core serialises it (byte offsets named `from`/`to`). */
interface RawDiagnostic {
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
 * core's `Build` object has been freed. Grammar errors never throw: they come back as
 * `diagnostics` with `ok: false`. A throw means the core itself failed (a bug, e.g. a panic).
 * Requires {@link initCore} to have finished.
 */
export function buildPlant(source: string, options: BuildOptions = {}): PlantBuild {
  assertReady();
  const result = build(
    source,
    options.iterations ?? undefined,
    options.seed ?? undefined,
    options.sides ?? undefined,
    options.smoothAll ?? undefined,
    () => performance.now(),
  );
  try {
    return {
      ok: result.ok,
      diagnostics: (JSON.parse(result.diagnostics()) as RawDiagnostic[]).map(toDiagnostic),
      stats: JSON.parse(result.stats()) as PlantStats,
      mesh: {
        positions: ownedArray(result.positions()),
        normals: ownedArray(result.normals()),
        colors: ownedArray(result.colors()),
        indices: ownedArray(result.indices()),
        ranges: ownedArray(result.ranges()),
        lines: ownedArray(result.lines()),
        lineColors: ownedArray(result.lineColors()),
      },
      origins: ownedArray(result.origins()),
      derived: result.derived(DERIVED_PREVIEW_CHARS),
      timings: (JSON.parse(result.timings()) as StageTimings | null) ?? NO_TIMINGS,
      flat: result.flat,
      grammarIterations: result.grammarIterations,
    };
  } finally {
    result.free();
  }
}

function toDiagnostic(raw: RawDiagnostic): Diagnostic {
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
