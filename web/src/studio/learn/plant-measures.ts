// Two measures of the plant on screen for lesson checks (docs/LESSONS.md, "Checks"), read off the
// mesh as the student sees it, not off the grammar's text: the trunk's proportion (ABOP chapter 2:
// the first internode's drawn width ÷ the plant's height) and the divergence angle (ABOP chapter
// 4: the angle about the plant's axis between consecutive organs, the spheres `@O` drawn in order).
import type { MeshBuffers, PlantStats } from '../../core';

/** The mesh arrays the trunk is read from. */
export type TrunkMesh = Pick<MeshBuffers, 'positions' | 'indices' | 'ranges' | 'segmentEnds' | 'segmentModules'>;

type Vec = [number, number, number];

const sub = (a: readonly number[], b: readonly number[]): Vec => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: readonly number[], b: readonly number[]): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const scale = (a: readonly number[], s: number): Vec => [a[0] * s, a[1] * s, a[2] * s];

/**
 * The drawn diameter of the first segment the turtle drew, at its base: twice the largest distance
 * from its axis of the vertices of its tube's first half. NaN when it has no tube (the Lines mode,
 * or a plant without segments).
 */
export function trunkWidth(mesh: TrunkMesh): number {
  const { positions, indices, ranges, segmentEnds, segmentModules } = mesh;
  if (segmentModules.length === 0) return Number.NaN;
  const start = Array.from(segmentEnds.subarray(0, 3));
  const axis = sub(Array.from(segmentEnds.subarray(3, 6)), start);
  const length2 = dot(axis, axis);
  if (length2 === 0) return Number.NaN;
  const triangles = indices.length / 3;
  let radius = Number.NaN;
  for (let r = 0; r < ranges.length; r += 2) {
    if (ranges[r + 1] !== segmentModules[0]) continue;
    const end = r + 2 < ranges.length ? ranges[r + 2] : triangles;
    for (let i = ranges[r] * 3; i < end * 3; i++) {
      const v = indices[i] * 3;
      const d = sub([positions[v], positions[v + 1], positions[v + 2]], start);
      const along = dot(d, axis) / length2;
      if (along > 0.5) continue; // the ring at the far joint may be the next segment's
      const off = sub(d, scale(axis, along));
      const distance = Math.sqrt(dot(off, off));
      radius = Number.isNaN(radius) ? distance : Math.max(radius, distance);
    }
  }
  return 2 * radius;
}

/** The first segment's drawn width ÷ the plant's height (its extent along y); NaN without either. */
export function trunkWidthRatio(mesh: TrunkMesh, stats: Pick<PlantStats, 'bounds'>): number {
  const height = stats.bounds[1][1] - stats.bounds[0][1];
  return height > 0 ? trunkWidth(mesh) / height : Number.NaN;
}

/** The eigenvectors of a symmetric 3×3 matrix (rows), by Jacobi rotations, with their eigenvalues. */
function eigen(m: number[][]): { values: number[]; vectors: Vec[] } {
  const a = m.map((row) => [...row]);
  const v = [
    [1, 0, 0],
    [0, 1, 0],
    [0, 0, 1],
  ];
  for (let sweep = 0; sweep < 50; sweep++) {
    const off = a[0][1] ** 2 + a[0][2] ** 2 + a[1][2] ** 2;
    if (off < 1e-30 * (a[0][0] ** 2 + a[1][1] ** 2 + a[2][2] ** 2 + 1e-300)) break;
    for (const [p, q] of [
      [0, 1],
      [0, 2],
      [1, 2],
    ]) {
      if (a[p][q] === 0) continue;
      const theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
      const t = Math.sign(theta || 1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
      const c = 1 / Math.sqrt(t * t + 1);
      const s = t * c;
      for (let k = 0; k < 3; k++) {
        const [akp, akq] = [a[k][p], a[k][q]];
        a[k][p] = c * akp - s * akq;
        a[k][q] = s * akp + c * akq;
      }
      for (let k = 0; k < 3; k++) {
        const [apk, aqk] = [a[p][k], a[q][k]];
        a[p][k] = c * apk - s * aqk;
        a[q][k] = s * apk + c * aqk;
      }
      for (let k = 0; k < 3; k++) {
        const [vkp, vkq] = [v[k][p], v[k][q]];
        v[k][p] = c * vkp - s * vkq;
        v[k][q] = s * vkp + c * vkq;
      }
    }
  }
  const vectors = [0, 1, 2].map((j): Vec => [v[0][j], v[1][j], v[2][j]]);
  return { values: [a[0][0], a[1][1], a[2][2]], vectors };
}

/**
 * The axis the organs sit around, through their centroid: along their greatest spread when it
 * dominates (a stem, a cylinder, a cone: over four times the next; organs in two ranks on a stem lie
 * in a plane too), else along the normal of their plane when they lie in one (a Vogel head: the
 * least spread under a fifth of the middle one), else along the greatest spread.
 */
function organAxis(points: readonly number[][]): { centre: Vec; direction: Vec } {
  const centre = scale(
    points.reduce((s, p) => [s[0] + p[0], s[1] + p[1], s[2] + p[2]], [0, 0, 0]),
    1 / points.length,
  );
  const m = [0, 1, 2].map(() => [0, 0, 0]);
  for (const p of points) {
    const d = sub(p, centre);
    for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) m[i][j] += d[i] * d[j];
  }
  const { values, vectors } = eigen(m);
  const order = [0, 1, 2].sort((i, j) => values[i] - values[j]);
  const long = values[order[2]] > 4 * values[order[1]];
  const flat = !long && values[order[0]] < 0.2 * values[order[1]];
  return { centre, direction: vectors[flat ? order[0] : order[2]] };
}

/** The median of some numbers (NaN for none). */
function median(values: number[]): number {
  if (values.length === 0) return Number.NaN;
  const sorted = [...values].sort((a, b) => a - b);
  const mid = Math.floor(sorted.length / 2);
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
}

/** Fewer organs than this have no divergence angle worth measuring. */
export const MIN_ORGANS = 3;

/**
 * The divergence angle of organs given in the order they were made (x, y, z each): the angle, in
 * degrees from 0 to 180, between consecutive organs seen along the axis they sit around, the median
 * over the pairs (an organ on the axis itself is skipped). 0 for fewer than {@link MIN_ORGANS}.
 * 137.5° and 222.5° are one pattern turned either way: both read 137.5.
 */
export function divergence(points: readonly number[][]): number {
  if (points.length < MIN_ORGANS) return 0;
  const { centre, direction } = organAxis(points);
  const around = points.map((p) => {
    const d = sub(p, centre);
    return sub(d, scale(direction, dot(d, direction)));
  });
  const size = Math.max(...around.map((v) => Math.sqrt(dot(v, v))));
  const angles: number[] = [];
  for (let i = 0; i + 1 < around.length; i++) {
    const [a, b] = [around[i], around[i + 1]];
    const la = Math.sqrt(dot(a, a));
    const lb = Math.sqrt(dot(b, b));
    if (la < 1e-6 * size || lb < 1e-6 * size) continue;
    const cosine = Math.min(1, Math.max(-1, dot(a, b) / (la * lb)));
    angles.push((Math.acos(cosine) * 180) / Math.PI);
  }
  return angles.length === 0 ? 0 : median(angles);
}
