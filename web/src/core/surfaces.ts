// One declared surface (`#surface X …`, `#patch X …`, docs/LANGUAGE.md "Surfaces") as the surface
// editor shows it: its patches tessellated as the plant draws them, its control points, and where
// each point's `x y z` is written in the text. The core answers (`surfacePreview` of
// ./surface-preview.ts, in crate/pkg), loaded with the editor's first use (`loadSurfacePreview`).
import { onDemand } from './on-demand';
import type { Diagnostic } from './types';

/** x, y, z. */
export type Point3 = [number, number, number];

/** A control point of a `#patch` line, where its three numbers are written. */
export interface WrittenPoint {
  /** Its patch (the surface's `#patch` lines in order) and its place in the 4 × 4 grid, row by row. */
  patch: number;
  index: number;
  /** x y z as written (before the surface's frame). */
  value: Point3;
  /** The text of its three numbers (UTF-16 offsets): from the first's start to the last's end. */
  from: number;
  to: number;
}

/** A surface of the grammar, in the turtle's frame at scale 1: x along L, y along H, z along U. */
export interface SurfacePreview {
  letter: string;
  /** The library shape it is (`#surface X petal`), which has no written points; else null. */
  organ: string | null;
  /** The control points, 16 per patch, row by row of each 4 × 4 grid. */
  net: Point3[];
  /** The `#patch` points as written (empty for a library shape). */
  written: WrittenPoint[];
  /**
   * The frame's map from written points to the turtle's frame (column-major 4 × 4, affine):
   * (p − contact) · scale / size in the declared heading and up.
   */
  toTurtle: number[];
  /** Where the turtle moves after drawing (`end`), if anywhere. */
  end: Point3 | null;
  /**
   * For a library shape: the changes (UTF-16 offsets into the text asked about) that write it out
   * as `#patch` lines of the same shape and precision, so that its points can be edited; else empty.
   */
  writeOut: { from: number; to: number; insert: string }[];
  /** Quads per patch along s and t. */
  precision: [number, number];
  /** The surface tessellated as the plant draws it: positions and normals (x y z each), triangles. */
  positions: Float32Array;
  normals: Float32Array;
  indices: Uint32Array;
  /**
   * Each patch's colour on its front and its back (linear r g b, 0 to 1) as the plant draws it:
   * the patch's own (`color`), else the turtle's at the plant's first `~X`, else leaf green.
   * Empty when not asked for (see {@link SurfacePreviewer}).
   */
  colors: [Point3, Point3][];
}

/** What the core says of a surface: the surface (null when the text declares none that resolves) and the text's diagnostics. */
export interface SurfaceAnswer {
  surface: SurfacePreview | null;
  /** The diagnostics of the whole text (UTF-8 spans, as every diagnostic of the core). */
  diagnostics: Diagnostic[];
}

/**
 * `surfacePreview` of ./surface-preview.ts: surface `letter` of `source`, with its colours unless
 * `colours` is false (they derive the plant; a drag, which changes no colour, goes without).
 */
export type SurfacePreviewer = (source: string, letter: string, colours?: boolean) => SurfaceAnswer;

/**
 * Loads the surface editor's core once (crate/pkg, with the importers and exporters) and resolves
 * to its `surfacePreview`; a failed load (the network) is tried again by the next call.
 */
export const loadSurfacePreview: () => Promise<SurfacePreviewer> = onDemand(async () => {
  const module = await import('./surface-preview');
  await module.initSurfacePreview();
  return module.surfacePreview;
});
