// The growth arrays of a mesh (`MeshBuffers.growthOrigins`, `growthTimes`, asked for by
// `MeshOptions.growth`; the layout is crate/src/mesh/buffers.rs's) as attributes of the plant's
// geometry, and the growth time's uniform: what every plant needs. The shaders that read them load
// with the first growth time shown (./growth.ts).
import { BufferAttribute, type BufferGeometry } from 'three';
import type { MeshBuffers } from '../core';

/** The growth arrays of a mesh (absent or empty when the build did not ask for them). */
export type GrowthArrays = Pick<MeshBuffers, 'growthOrigins' | 'growthTimes'>;

/**
 * The uniform's value when no growth time is set: past every t1, so every vertex is where its
 * position says (a vertex without growth attributes reads times (0, 0) and is whole too).
 */
export const WHOLE = 1e9;

/** A uniform three.js reads (the growth time, shared by the plant's materials). */
export interface GrowthUniform {
  value: number;
}

/**
 * Adds the growth attributes to `geometry` when `origins` and `times` fit its `count` vertices (3
 * and 2 floats each); returns whether they did.
 */
export function addGrowthAttributes(geometry: BufferGeometry, count: number, { growthOrigins, growthTimes }: GrowthArrays): boolean {
  if (count === 0 || growthOrigins?.length !== count * 3 || growthTimes?.length !== count * 2) return false;
  geometry.setAttribute('growthOrigin', new BufferAttribute(growthOrigins, 3));
  geometry.setAttribute('growthTime', new BufferAttribute(growthTimes, 2));
  return true;
}

/**
 * N, the growth time at which the whole plant is grown: the last t1 of all `times` ((t0, t1)
 * pairs: the vertices', the segments'), up to a whole step; null without times.
 */
export function growthSpanOf(...times: (Float32Array | undefined)[]): number | null {
  let last = -1;
  for (const pairs of times) for (let k = 1; k < (pairs?.length ?? 0); k += 2) last = Math.max(last, pairs![k]);
  return last < -0.5 ? null : Math.max(0, Math.ceil(last - 1e-6));
}
