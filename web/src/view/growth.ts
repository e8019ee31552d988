// Growth in time on the GPU (issue 45): each vertex of the plant carries the point it grows from
// and its growth times (`MeshBuffers.growthOrigins`, `growthTimes`, laid out in
// crate/src/mesh/buffers.rs), and one uniform, the growth time t, places it. Showing another t
// changes that uniform: no derivation, no meshing, no upload. The formula is the interfaces' one:
// `origin + (position − origin) · g(clamp((t − t0) / (t1 − t0), 0, 1))`, g the smoothstep; its
// JavaScript mirror ({@link grownFraction}) is what the tests read. This module loads with the
// first growth time shown (the first load's budget, tests/browser/first-load.test.ts); what every
// plant needs is in ./growth-arrays.ts.
import { Box3, type Material, Vector3 } from 'three';
import type { Bounds } from '../core';
import type { GrowthUniform } from './growth-arrays';
import type { ShownPlant } from './shown-plant';
import { grownFraction, UNIFORM } from './growth-function';
import { GROWN } from './scene-setup';

export { drawGrown } from './grown-triangles';
export { grownFraction };
export { grownSegmentEnds, LineGrowth } from './line-growth';

/** Declarations the vertex shader needs, before its `main`. */
export const GROWTH_DECLARATIONS = /* glsl */ `
attribute vec3 growthOrigin;
attribute vec2 growthTime;
uniform float ${UNIFORM};
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

/**
 * Injects the growth into a vertex shader three.js made (`shader`, as `onBeforeCompile` gets it)
 * with `uniform` as the time; throws if three.js's chunks changed and the growth no longer fits.
 */
export function injectGrowth(shader: { vertexShader: string; uniforms: Record<string, unknown> }, uniform: GrowthUniform): void {
  // (After the line that includes three.js's begin_vertex chunk.)
  const begin = /^.*<begin_vertex>.*$/m;
  if (!begin.test(shader.vertexShader) || !shader.vertexShader.includes('void main()')) {
    throw new Error("three.js's vertex shader changed: the growth no longer fits it");
  }
  shader.uniforms[UNIFORM] = uniform;
  // `meristemGrown` is declared by the plant's materials (./scene-setup.ts), else here.
  const grown = shader.vertexShader.includes(GROWN) ? '' : GROWN;
  shader.vertexShader = `${GROWTH_DECLARATIONS}${grown}\n${shader.vertexShader.replace(begin, (line) => `${line}\n${GROWTH_PLACEMENT}`)}`;
}

/**
 * Makes `material` grow its vertices with the time `uniform` (a geometry without growth
 * attributes is drawn whole), keeping its own `onBeforeCompile` (which runs first). Its programs
 * are cached apart from the same material without growth. A material made to grow already is left as it is.
 */
export function growingMaterial<M extends Material>(material: M, uniform: GrowthUniform): M {
  if (material.userData.meristemGrowth === uniform) return material; // (grows already)
  material.userData.meristemGrowth = uniform;
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
 * The boxes of the plant grown at each whole step 0 … `span` (3-float `points` with their
 * `times`, one (t0, t1) for each `perTime` points: 2 for segments' ends): a point counts from the
 * step its growth ends. What "follow the growth" frames ({@link blendedBox} between two steps).
 */
export function growthBoxes(points: Float32Array, times: Float32Array, span: number, perTime = 1): Box3[] {
  const boxes = Array.from({ length: span + 1 }, () => new Box3());
  const point = new Vector3();
  for (let v = 0; 3 * v + 2 < points.length && 2 * Math.floor(v / perTime) + 1 < times.length; v++) {
    const step = Math.min(span, Math.max(0, Math.ceil(times[2 * Math.floor(v / perTime) + 1] - 1e-6)));
    boxes[step].expandByPoint(point.set(points[3 * v], points[3 * v + 1], points[3 * v + 2]));
  }
  for (let n = 1; n <= span; n++) boxes[n].union(boxes[n - 1]);
  return boxes;
}

/** The box at `t` between `boxes[⌊t⌋]` and `boxes[⌈t⌉]` (clamped to the steps there are), corner by corner. */
export function blendedBox(boxes: readonly Box3[], t: number): Box3 {
  const last = boxes.length - 1;
  const at = Math.min(last, Math.max(0, t));
  const before = boxes[Math.floor(at)];
  const after = boxes[Math.ceil(at)];
  if (before.isEmpty()) return after.clone();
  const f = at - Math.floor(at);
  return new Box3(before.min.clone().lerp(after.min, f), before.max.clone().lerp(after.max, f));
}

/** The boxes of each step of a plant's points (its vertices, its segments' ends), made once (see {@link growthBoxes}). */
const stepBoxes = new WeakMap<Float32Array, Box3[]>();

/**
 * The bounds of the plant on screen grown by growth time `t`, blended between the steps around it
 * (what a camera following the growth frames): its mesh's and its segments' (drawn as lines in
 * the Lines mode, beside a mesh that may hold nothing); null without growth arrays or without anything grown.
 */
export function grownBounds(shown: ShownPlant, t: number): Bounds | null {
  const span = shown.growthSpan;
  if (span === null) return null;
  const geometry = shown.drawn.geometry.getAttribute('position') ? shown.pickable.geometry : shown.lines.geometry;
  const points = geometry.getAttribute('position')?.array as Float32Array | undefined;
  const times = geometry.getAttribute('growthTime')?.array as Float32Array | undefined;
  const box = new Box3();
  const parts: [Float32Array | undefined, Float32Array | undefined, number][] = [
    [points, times, 1],
    [shown.mesh?.segmentEnds, shown.mesh?.segmentGrowthTimes, 2],
  ];
  for (const [at, when, perTime] of parts) {
    if (!at || !when) continue;
    let boxes = stepBoxes.get(at);
    if (!boxes) stepBoxes.set(at, (boxes = growthBoxes(at, when, span, perTime)));
    box.union(blendedBox(boxes, t));
  }
  return box.isEmpty() ? null : [box.min.toArray(), box.max.toArray()];
}
