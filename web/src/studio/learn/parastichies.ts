// The parastichies of a plant's florets, for lesson checks (docs/LESSONS.md, "Checks"): ABOP
// chapter 4's reasoning read off the mesh. A floret is a module that drew a sphere (`@O`); its
// position is the mean of its sphere's vertices. The eye joins each floret to its nearest
// neighbours, the m-th and n-th florets before and after it, into m spirals one way and n the other:
// the contact parastichy pair (m, n). Counted on the middle third of the florets in the order they
// were drawn (Vogel's head from the centre out, a cylinder from the base up), away from the centre,
// the rim and the ends, where the pattern changes.
import type { MeshBuffers } from '../../core';

/** The material kind of spheres in `materialRanges` (the core's `MATERIAL_PLAIN`). */
const MATERIAL_PLAIN = 2;

/** Fewer florets than this have no parastichies worth counting. */
export const MIN_FLORETS = 12;

/**
 * The most florets a check counts parastichies among: the count compares a third of them with all
 * (quadratic), which at this size takes some tens of milliseconds.
 */
export const MAX_FLORETS = 5_000;

/** The mesh arrays the florets are read from. */
export type FloretMesh = Pick<MeshBuffers, 'positions' | 'indices' | 'ranges' | 'materialRanges'>;

/** The centre of each sphere of the mesh, in the order drawn, as x, y, z triples. */
export function floretPositions(mesh: FloretMesh): number[][] {
  const { positions, indices, ranges, materialRanges } = mesh;
  const triangles = indices.length / 3;
  const florets: number[][] = [];
  let material = 0; // the material range of the current triangle: both arrays are sorted by first triangle
  for (let r = 0; r < ranges.length; r += 2) {
    const first = ranges[r];
    const end = r + 2 < ranges.length ? ranges[r + 2] : triangles;
    while (material + 2 < materialRanges.length && materialRanges[material + 2] <= first) material += 2;
    if (end <= first || materialRanges[material + 1] !== MATERIAL_PLAIN) continue;
    const sum = [0, 0, 0];
    for (let i = first * 3; i < end * 3; i++) {
      const v = indices[i] * 3;
      sum[0] += positions[v];
      sum[1] += positions[v + 1];
      sum[2] += positions[v + 2];
    }
    florets.push(sum.map((s) => s / ((end - first) * 3)));
  }
  return florets;
}

/** The index differences of the four florets nearest to floret `i`. */
function nearestDifferences(points: readonly number[][], i: number): number[] {
  const best: { d: number; k: number }[] = [];
  const [x, y, z] = points[i];
  for (let j = 0; j < points.length; j++) {
    if (j === i) continue;
    const p = points[j];
    const d = (p[0] - x) ** 2 + (p[1] - y) ** 2 + (p[2] - z) ** 2;
    if (best.length === 4 && d >= best[3].d) continue;
    best.push({ d, k: Math.abs(i - j) });
    best.sort((a, b) => a.d - b.d);
    if (best.length > 4) best.pop();
  }
  return [...new Set(best.map((b) => b.k))];
}

/** The contact parastichy pair (m, n), m < n, of florets in the order drawn; [0, 0] for too few. */
export function parastichyPair(points: readonly number[][]): [number, number] {
  if (points.length < MIN_FLORETS) return [0, 0];
  const seen = new Map<number, number>();
  const from = Math.floor(points.length / 3);
  const to = Math.floor((2 * points.length) / 3);
  for (let i = from; i < to; i++) for (const k of nearestDifferences(points, i)) seen.set(k, (seen.get(k) ?? 0) + 1);
  const ranked = [...seen].sort((a, b) => b[1] - a[1] || a[0] - b[0]);
  if (ranked.length < 2) return [0, 0];
  const [m, n] = [ranked[0][0], ranked[1][0]];
  return [Math.min(m, n), Math.max(m, n)];
}
