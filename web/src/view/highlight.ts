// Colouring the plant by module: the context-sensitivity view paints the triangles of chosen modules
// of the derived string (through the mesh's provenance ranges) and dims the rest.
import type { MeshBuffers } from '../core';

/** Linear RGB, 0..1. */
export type Rgb = readonly [number, number, number];

/** The highlight colours, shared by the 3D view, the string panel (CSS) and the editor. */
export const HIGHLIGHT = {
  /** Modules a production wrote in the last step. */
  produced: [1.0, 0.08, 0.75] as Rgb,
  /** Modules descending from a left context. */
  left: [0.1, 0.42, 1.0] as Rgb,
  /** Modules descending from a right context. */
  right: [1.0, 0.45, 0.0] as Rgb,
  /** The module picked in the 3D view or the panel. */
  selected: [1.0, 0.9, 0.0] as Rgb,
} as const;

/** Distinct colours for "colour by production" (production i takes entry i modulo the length). */
export const PRODUCTION_COLOURS: readonly Rgb[] = [
  [0.9, 0.1, 0.45],
  [0.1, 0.45, 0.95],
  [0.95, 0.55, 0.0],
  [0.0, 0.65, 0.45],
  [0.6, 0.25, 0.9],
  [0.85, 0.8, 0.0],
  [0.0, 0.75, 0.9],
  [0.55, 0.3, 0.1],
];

/** The index of the module that drew triangle `triangle`, from the (first triangle, module) ranges. */
export function moduleOfTriangle(ranges: Uint32Array, triangle: number): number | null {
  const count = ranges.length / 2;
  if (count === 0 || triangle < ranges[0]) return null;
  let lo = 0;
  let hi = count - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (ranges[2 * mid] <= triangle) lo = mid;
    else hi = mid - 1;
  }
  return ranges[2 * lo + 1];
}

/** Triangles copied out of a mesh with one flat colour each: the highlight overlay. */
export interface Overlay {
  positions: Float32Array;
  normals: Float32Array;
  colors: Float32Array;
}

/** The material kind of tubes in `materialRanges` (the core's `MATERIAL_BARK`). */
export const MATERIAL_BARK = 0;

/**
 * The triangles of every module `colourOf` names, copied (not indexed, so neighbouring modules that
 * share a joint ring keep crisp colours) and painted in that module's colour. `withTubes: false`
 * leaves out the tubes' triangles (the Lines mode draws segments as lines instead). `normals` are
 * the mesh's, as floats or packed for the GPU (16-bit normalized, `GpuArrays`).
 */
export function highlightOverlay(mesh: MeshBuffers, colourOf: (module: number) => Rgb | null, withTubes = true, normals: Float32Array | Int16Array = mesh.normals): Overlay {
  const triangles = mesh.indices.length / 3;
  const ranges = mesh.ranges;
  const picked: { first: number; end: number; colour: Rgb }[] = [];
  let count = 0;
  for (let r = 0; r < ranges.length; r += 2) {
    const colour = colourOf(ranges[r + 1]);
    if (!colour) continue;
    // One module draws one thing: its first triangle's kind is the kind of all of them.
    if (!withTubes && moduleOfTriangle(mesh.materialRanges, ranges[r]) === MATERIAL_BARK) continue;
    const end = r + 2 < ranges.length ? ranges[r + 2] : triangles;
    picked.push({ first: ranges[r], end, colour });
    count += end - ranges[r];
  }
  const positions = new Float32Array(count * 9);
  const overlayNormals = new Float32Array(count * 9);
  const colors = new Float32Array(count * 9);
  const scale = normals instanceof Int16Array ? 1 / 32767 : 1;
  let o = 0;
  for (const { first, end, colour } of picked) {
    for (let t = first; t < end; t++) {
      for (let k = 0; k < 3; k++) {
        const v = mesh.indices[3 * t + k] * 3;
        positions.set(mesh.positions.subarray(v, v + 3), o);
        for (let c = 0; c < 3; c++) overlayNormals[o + c] = normals[v + c] * scale;
        colors.set(colour, o);
        o += 3;
      }
    }
  }
  return { positions, normals: overlayNormals, colors };
}

/** Segments as lines (two 3-float ends each) with a colour per end, and their growth times (two each) if the plant has them. */
export interface LineOverlay {
  ends: Float32Array;
  colors: Float32Array;
  times?: Float32Array;
}

/** The segments (lines) of every module `colourOf` names, painted in that module's colour. */
export function highlightSegments(mesh: MeshBuffers, colourOf: (module: number) => Rgb | null): LineOverlay {
  const picked: { segment: number; colour: Rgb }[] = [];
  mesh.segmentModules.forEach((module, segment) => {
    const colour = colourOf(module);
    if (colour) picked.push({ segment, colour });
  });
  const ends = new Float32Array(picked.length * 6);
  const colors = new Float32Array(picked.length * 6);
  const grows = mesh.segmentGrowthTimes;
  const times = grows && new Float32Array(picked.length * 2);
  picked.forEach(({ segment, colour }, k) => {
    ends.set(mesh.segmentEnds.subarray(6 * segment, 6 * segment + 6), 6 * k);
    colors.set(colour, 6 * k);
    colors.set(colour, 6 * k + 3);
    times?.set(grows!.subarray(2 * segment, 2 * segment + 2), 2 * k);
  });
  return { ends, colors, times };
}

/** CSS colour of linear RGB (the view's vertex colours are linear; CSS is sRGB). */
export function cssColour(rgb: Rgb): string {
  const encode = (c: number) => Math.round(255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055));
  return `rgb(${encode(rgb[0])}, ${encode(rgb[1])}, ${encode(rgb[2])})`;
}
