// The core's answer about one declared surface (./surfaces.ts): crate/pkg's `surfacePreview`,
// read into owned arrays with its spans in UTF-16. Loaded with the surface editor's first use.
import { surfacePreview as corePreview } from '../../../crate/pkg/meristem.js';
import { toDiagnostic, type RawDiagnostic } from './build';
import { guarded } from './init';
import { initIo } from './io';
import { utf16Offsets } from './offsets';
import type { Point3, SurfaceAnswer, SurfacePreview } from './surfaces';

/** Loads crate/pkg once (the browser's hashed asset); then {@link surfacePreview} works. */
export function initSurfacePreview(): Promise<void> {
  return initIo();
}

/** The surface as the core writes it (JSON; spans in UTF-8 bytes). */
interface RawSurface {
  letter: string;
  organ: string | null;
  net: number[];
  written: { patch: number; index: number; value: Point3; from: number; to: number }[];
  toTurtle: number[];
  end: Point3 | null;
  writeOut: { from: number; to: number; insert: string }[];
  precision: [number, number];
  positions: number[];
  normals: number[];
  indices: number[];
  colors: [Point3, Point3][];
}

/** Surface `letter` of `source` (see {@link SurfaceAnswer}), its colours unless `colours` is false; requires {@link initSurfacePreview}. */
export function surfacePreview(source: string, letter: string, colours = true): SurfaceAnswer {
  const raw = JSON.parse(guarded(() => corePreview(source, letter, colours))) as { surface: RawSurface | null; diagnostics: RawDiagnostic[] };
  const diagnostics = raw.diagnostics.map(toDiagnostic);
  const s = raw.surface;
  if (!s) return { surface: null, diagnostics };
  const offset = utf16Offsets(source);
  const net: Point3[] = [];
  for (let k = 0; k + 2 < s.net.length; k += 3) net.push([s.net[k], s.net[k + 1], s.net[k + 2]]);
  const surface: SurfacePreview = {
    letter: s.letter,
    organ: s.organ,
    net,
    written: s.written.map((w) => ({ ...w, from: offset(w.from), to: offset(w.to) })),
    toTurtle: s.toTurtle,
    end: s.end,
    writeOut: s.writeOut.map((c) => ({ ...c, from: offset(c.from), to: offset(c.to) })),
    precision: s.precision,
    positions: Float32Array.from(s.positions),
    normals: Float32Array.from(s.normals),
    indices: Uint32Array.from(s.indices),
    colors: s.colors,
  };
  return { surface, diagnostics };
}
