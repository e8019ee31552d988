// Only the triangles that have begun to grow are drawn (issue 45: the n = 7 tree at 60 frames a
// second). At growth time t a vertex whose element starts at t0 ≥ t sits on its growth origin
// (./growth.ts), so a triangle whose three vertices share one origin and have not started is a
// point, which draws no pixel; yet a software rasterizer (SwiftShader, where these machines draw)
// still shades its vertices and sets it up: at t = 3.5 of 1.24d at n = 7, most of the frame's
// cost. So the GPU's copy of the index (never the mesh's, which picking and the provenance ranges
// read) is ordered once by each triangle's start within each draw group, and each frame draws, of
// each group, the prefix of triangles that have started. The picture is the same at every t.
import type { BufferGeometry, GLBufferAttribute, Mesh, Material } from 'three';

/**
 * Keys are times quantized down to 1/QUANTUM of a step (a triangle is drawn a little early, never
 * late), offset to be ≥ 0, and packed with the triangle's number into one float64 (exact below
 * 2^53): key · 2^TRIANGLE_BITS + triangle.
 */
const QUANTUM = 1024;
const KEY_MIN = -2 * QUANTUM;
const KEY_MAX = 2 ** 29;
const TRIANGLE_BITS = 23;

/** A geometry's triangles ordered by start: each group's range and the sorted starts of its triangles. */
interface Order {
  groups: { start: number; count: number; keys: Int32Array }[];
  /** The groups' counts before any was cut (three.js draws `geometry.groups`). */
  full: number[];
}

/** The order of each drawn index (a new one after a lost context), made by the first growth time shown. */
const orders = new WeakMap<object, Order | null>();

/**
 * The start of a triangle of vertices `a`, `b`, `c`, quantized down: before it the triangle is a
 * point. A triangle of different origins, or with a vertex that does not grow, is never a point:
 * KEY_MIN, always drawn.
 */
function triangleKey(a: number, b: number, c: number, origins: Float32Array, times: Float32Array): number {
  for (let k = 0; k < 3; k++) {
    const o = origins[3 * a + k];
    if (origins[3 * b + k] !== o || origins[3 * c + k] !== o) return KEY_MIN;
  }
  let start = Infinity;
  for (const v of [a, b, c]) {
    const t0 = times[2 * v];
    if (!(times[2 * v + 1] > t0)) return KEY_MIN; // drawn whole (./growth.ts)
    start = Math.min(start, t0);
  }
  return Math.max(KEY_MIN, Math.min(KEY_MAX, Math.floor(start * QUANTUM)));
}

/**
 * `indices` with each range `[start, start + count)` (of indices, 3 a triangle) ordered by its
 * triangles' start (stable), and the sorted keys of each; null when the index is too large to pack.
 */
export function orderByStart(
  indices: Uint32Array | Uint16Array,
  origins: Float32Array,
  times: Float32Array,
  ranges: readonly { start: number; count: number }[],
): { indices: Uint32Array | Uint16Array; keys: Int32Array[] } | null {
  if (indices.length / 3 >= 2 ** TRIANGLE_BITS) return null;
  const ordered = indices.slice();
  const keys = ranges.map(({ start, count }) => {
    const first = start / 3;
    const triangles = Math.floor(count / 3);
    const packed = new Float64Array(triangles);
    for (let i = 0; i < triangles; i++) {
      const j = 3 * (first + i);
      const key = triangleKey(indices[j], indices[j + 1], indices[j + 2], origins, times) - KEY_MIN;
      packed[i] = key * 2 ** TRIANGLE_BITS + i;
    }
    packed.sort();
    const sorted = new Int32Array(triangles);
    for (let i = 0; i < triangles; i++) {
      const triangle = packed[i] % 2 ** TRIANGLE_BITS;
      sorted[i] = (packed[i] - triangle) / 2 ** TRIANGLE_BITS + KEY_MIN;
      ordered.set(indices.subarray(3 * (first + triangle), 3 * (first + triangle) + 3), 3 * (first + i));
    }
    return sorted;
  });
  return { indices: ordered, keys };
}

/** How many of the sorted `keys` are below growth time `t` (the triangles begun by t, and a few more). */
export function startedBy(keys: Int32Array, t: number): number {
  const limit = Math.fround(t) * QUANTUM;
  let low = 0;
  let high = keys.length;
  while (low < high) {
    const mid = (low + high) >> 1;
    if (keys[mid] < limit) low = mid + 1;
    else high = mid;
  }
  return low;
}

/** The ranges ordered: the geometry's groups, or its whole index. */
function rangesOf(geometry: BufferGeometry): readonly { start: number; count: number }[] {
  return geometry.groups.length > 0 ? geometry.groups : [{ start: 0, count: geometry.index?.count ?? 0 }];
}

/** Orders the GPU's index of `geometry` (see the module's doc) once; null when it cannot be. */
function orderOf(geometry: BufferGeometry, source: BufferGeometry, gl: WebGL2RenderingContext): Order | null {
  const drawn = geometry.index as unknown as GLBufferAttribute | null;
  if (!drawn) return null;
  if (orders.has(drawn)) return orders.get(drawn)!;
  const indices = source.index?.array as Uint32Array | Uint16Array | undefined;
  const origins = source.getAttribute('growthOrigin')?.array as Float32Array | undefined;
  const times = source.getAttribute('growthTime')?.array as Float32Array | undefined;
  const ranges = rangesOf(geometry).map(({ start, count }) => ({ start, count }));
  const ordered = indices && origins && times && indices.length === drawn.count ? orderByStart(indices, origins, times, ranges) : null;
  let order: Order | null = null;
  if (ordered && drawn.buffer) {
    gl.bindBuffer(gl.COPY_WRITE_BUFFER, drawn.buffer);
    gl.bufferSubData(gl.COPY_WRITE_BUFFER, 0, ordered.indices);
    order = { groups: ranges.map(({ start, count }, k) => ({ start, count, keys: ordered.keys[k] })), full: geometry.groups.map(({ count }) => count) };
  }
  orders.set(drawn, order);
  return order;
}

/**
 * Draws of `mesh` (the plant on screen; `source` its plain twin, whose arrays are the mesh's) only
 * the triangles begun by growth time `t`, or all of them (`t` null: the whole plant). three.js
 * draws each group with an array of materials, else the draw range of the whole index: one group
 * at most can then be cut.
 */
export function drawGrown(mesh: Mesh<BufferGeometry, Material | Material[]>, source: BufferGeometry, gl: WebGL2RenderingContext, t: number | null): void {
  const geometry = mesh.geometry;
  const order = t === null ? null : orderOf(geometry, source, gl);
  const known = order ?? (geometry.index ? orders.get(geometry.index) : undefined);
  known?.full.forEach((count, k) => (geometry.groups[k].count = count));
  geometry.setDrawRange(0, Infinity);
  if (!order || t === null) return;
  if (Array.isArray(mesh.material) && geometry.groups.length > 0) {
    order.groups.forEach(({ keys }, k) => (geometry.groups[k].count = 3 * startedBy(keys, t)));
  } else if (order.groups.length === 1) {
    geometry.setDrawRange(order.groups[0].start, 3 * startedBy(order.groups[0].keys, t));
  }
}
