// Growth in time on the GPU (issue 45): each vertex of the plant carries the point it grows from
// and its growth times (`MeshBuffers.growthOrigins`, `growthTimes`, laid out in
// crate/src/mesh/buffers.rs), and one uniform, the growth time t, places it. Showing another t
// changes that uniform: no derivation, no meshing, no upload. The formula is the interfaces' one:
// `origin + (position − origin) · g(clamp((t − t0) / (t1 − t0), 0, 1))`, g the smoothstep; its
// JavaScript mirror ({@link grownFraction}) is what the tests and the framing read.
import { Box3, BufferAttribute, type BufferGeometry, type Material, Vector3 } from 'three';
import type { MeshBuffers } from '../core';

/** The growth arrays a mesh may carry (asked for by `MeshOptions.growth`; absent or empty if not). */
export interface GrowthArrays {
  /** 3 floats a vertex (or a line end): the point it grows from. */
  growthOrigins?: Float32Array;
  /** 2 floats a vertex (or a line end): its growth times (t0, t1), −1 ≤ t0 < t1 ≤ N. */
  growthTimes?: Float32Array;
}

/** A mesh, perhaps with its growth arrays. */
export type GrowingMesh = MeshBuffers & GrowthArrays;

/**
 * The uniform's value when no growth time is set: past every t1, so every vertex is where its
 * position says (a vertex without growth attributes reads times (0, 0) and is whole too).
 */
export const WHOLE = 1e9;

/** A uniform three.js reads (the growth time, shared by the plant's materials). */
export interface GrowthUniform {
  value: number;
}

/** The name of the time uniform in the shaders. */
const UNIFORM = 'meristemGrowthTime';

/** Declarations the vertex shader needs, before its `main`. */
export const GROWTH_DECLARATIONS = /* glsl */ `
#define MERISTEM_GROWTH
attribute vec3 growthOrigin;
attribute vec2 growthTime;
uniform float ${UNIFORM};
float meristemGrown = 1.0;
`;

/**
 * After three.js's `begin_vertex` chunk (which makes `transformed` of `position`): the vertex
 * moves towards its origin by the fraction grown. `meristemGrown` keeps that fraction (0: the
 * element is not there yet; what follows may use it to draw nothing of it).
 */
export const GROWTH_PLACEMENT = /* glsl */ `
  if (growthTime.y > growthTime.x) {
    float growthX = clamp((${UNIFORM} - growthTime.x) / (growthTime.y - growthTime.x), 0.0, 1.0);
    meristemGrown = growthX * growthX * (3.0 - 2.0 * growthX);
    transformed = growthOrigin + (transformed - growthOrigin) * meristemGrown;
  }
`;

/** The growth function g (smoothstep) of the fraction of [t0, t1] passed at `t`: 0 before t0, 1 after t1. */
export function grownFraction(t: number, t0: number, t1: number): number {
  if (!(t1 > t0)) return 1;
  const x = Math.min(1, Math.max(0, (t - t0) / (t1 - t0)));
  return x * x * (3 - 2 * x);
}

/**
 * Injects the growth into a vertex shader three.js made (`shader`, as `onBeforeCompile` gets it)
 * with `uniform` as the time; throws if three.js's chunks changed and the growth no longer fits.
 */
export function injectGrowth(shader: { vertexShader: string; uniforms: Record<string, unknown> }, uniform: GrowthUniform): void {
  const begin = '#include <begin_vertex>';
  if (!shader.vertexShader.includes(begin) || !shader.vertexShader.includes('void main()')) {
    throw new Error("three.js's vertex shader changed: the growth no longer fits it");
  }
  shader.uniforms[UNIFORM] = uniform;
  shader.vertexShader = GROWTH_DECLARATIONS + shader.vertexShader.replace(begin, `${begin}\n${GROWTH_PLACEMENT}`);
}

/**
 * Makes `material` grow its vertices with the time `uniform` (a geometry without growth
 * attributes is drawn whole), keeping its own `onBeforeCompile` (which runs first). Its programs
 * are cached apart from the same material without growth.
 */
export function growingMaterial<M extends Material>(material: M, uniform: GrowthUniform): M {
  const before = material.onBeforeCompile.bind(material);
  material.onBeforeCompile = (shader, renderer) => {
    before(shader, renderer);
    injectGrowth(shader, uniform);
  };
  const key = material.customProgramCacheKey.bind(material);
  material.customProgramCacheKey = () => `${key()}|growth`;
  return material;
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

/** N, the growth time at which the whole plant is grown: the last t1, up to a whole step; null without times. */
export function growthSpanOf(times: Float32Array | undefined): number | null {
  if (!times || times.length < 2) return null;
  let last = 0;
  for (let k = 1; k < times.length; k += 2) if (times[k] > last) last = times[k];
  return Math.max(0, Math.ceil(last - 1e-6));
}

/**
 * The boxes of the plant grown at each whole step 0 … `span` (3-float `points` with their
 * `times`): a point counts from the step its growth ends. What "follow the growth" frames, between
 * two steps the box of the later one.
 */
export function growthBoxes(points: Float32Array, times: Float32Array, span: number): Box3[] {
  const boxes = Array.from({ length: span + 1 }, () => new Box3());
  const point = new Vector3();
  for (let v = 0; 3 * v + 2 < points.length && 2 * v + 1 < times.length; v++) {
    const step = Math.min(span, Math.max(0, Math.ceil(times[2 * v + 1] - 1e-6)));
    boxes[step].expandByPoint(point.set(points[3 * v], points[3 * v + 1], points[3 * v + 2]));
  }
  for (let n = 1; n <= span; n++) boxes[n].union(boxes[n - 1]);
  return boxes;
}
