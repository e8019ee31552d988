// The Lines mode growing in time (issue 45): each segment ./texel-lines.ts draws grows from its
// start as the tubes do (the same growth function and time uniform as ./growth.ts): its growth
// times (t0, t1), `MeshBuffers.segmentGrowthTimes`, are one texel of a float texture read by the
// segment's index, and its end is drawn at `start + (end − start) · g`. A segment not started yet
// draws nothing (not the dot of its round ends). Showing another time changes the uniform alone;
// the texture is made once a plant. On the CPU, {@link grownSegmentEnds} gives the same segments
// for picking.
import { DataTexture, FloatType, NearestFilter, RGFormat, type ShaderMaterial } from 'three';
import { grownFraction, UNIFORM } from './growth-function';
import { WHOLE, type GrowthUniform } from './growth-arrays';
import type { TexelLines } from './texel-lines';

/** The uniform of the texture of growth times. */
const TIMES = 'lineGrowth';

/**
 * After the segment's ends are fetched (./texel-lines.ts's `FETCH`): its times read, and its end
 * moved towards its start by the fraction grown.
 */
const PLACEMENT = /* glsl */ `
  vec2 lineTimes = texelFetch(${TIMES}, ivec2(lineSegment % lineSegmentsPerRow, lineSegment / lineSegmentsPerRow), 0).xy;
  float lineGrown = 1.0;
  if (lineTimes.y > lineTimes.x) {
    float lineX = clamp((${UNIFORM} - lineTimes.x) / (lineTimes.y - lineTimes.x), 0.0, 1.0);
    lineGrown = lineX * lineX * (3.0 - 2.0 * lineX);
    instanceEnd = instanceStart + (instanceEnd - instanceStart) * lineGrown;
  }
`;

/** After the corner is placed: a segment not started is put beyond the far plane, every corner at one point. */
const HIDDEN = /* glsl */ `
  if (lineGrown <= 0.0) gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
`;

/** The texel lines' vertex shader (./texel-lines.ts `texelLineShader`'s) with each segment grown to the time. */
export function growingLineShader(vertexShader: string): string {
  const fetched = /^.*instanceColorEnd = texelFetch.*$/m;
  const placed = /^\s*gl_Position = clip;.*$/m;
  if (!fetched.test(vertexShader) || !placed.test(vertexShader)) {
    throw new Error("the texel lines' shader changed: the growth no longer fits it");
  }
  const grown = vertexShader.replace(fetched, (line) => `${line}\n${PLACEMENT}`).replace(placed, (line) => `${line}\n${HIDDEN}`);
  return `uniform highp sampler2D ${TIMES};\nuniform float ${UNIFORM};\n${grown}`;
}

/**
 * `times` ((t0, t1) a segment) as the rows of a texture of `perRow` texels a row, the segments'
 * order as ./texel-lines.ts's textures have it (one texel a segment here).
 */
export function timeRows(times: Float32Array, perRow: number): { data: Float32Array; width: number; height: number } {
  const height = Math.max(1, Math.ceil(times.length / 2 / perRow));
  const data = new Float32Array(perRow * height * 2);
  data.set(times.subarray(0, data.length));
  return { data, width: perRow, height };
}

/**
 * The segments `ends` (start xyz, end xyz each) at growth time `t` by their `times` (two a
 * segment): each end moved towards its start by the fraction grown; a segment not started yet
 * (nothing grown) has NaN ends, so that nothing draws or picks it. `ends` themselves when `times`
 * are not two a segment.
 */
export function grownSegmentEnds(ends: Float32Array, times: Float32Array, t: number): Float32Array {
  if (times.length * 3 !== ends.length) return ends;
  const grown = new Float32Array(ends.length);
  for (let s = 0, o = 0; o < ends.length; s++, o += 6) {
    const g = grownFraction(t, times[2 * s], times[2 * s + 1]);
    if (g <= 0) {
      grown.fill(NaN, o, o + 6);
      continue;
    }
    for (let k = 0; k < 3; k++) {
      grown[o + k] = ends[o + k];
      grown[o + 3 + k] = ends[o + k] + (ends[o + 3 + k] - ends[o + k]) * g;
    }
  }
  return grown;
}

/** What {@link LineGrowth.attach} makes grow: the Lines mode's lines (./segment-lines.ts), the plant's and the highlighted ones, with their growth times. */
export interface GrowingLines {
  plant: TexelLines;
  overlay: TexelLines;
  times?: Float32Array | undefined;
  overTimes?: Float32Array | undefined;
  growth?: LineGrowth | undefined;
}

/** The Lines mode's growth at the view's growth time: its lines' shaders and textures, and their segments on the CPU. */
export class LineGrowth {
  /** The segments last grown on the CPU, by the ends they were grown from. */
  private readonly grownAt = new WeakMap<Float32Array, { t: number; times: Float32Array; grown: Float32Array }>();

  /** `time`: the view's growth time (./plant-materials.ts's). */
  constructor(private readonly time: GrowthUniform) {}

  /**
   * Makes the Lines mode's `lines` (./segment-lines.ts) grow with the time, each segment from its
   * start by its growth times (the mesh's `segmentGrowthTimes`), and grow their segments from now on.
   */
  attach(lines: GrowingLines): void {
    lines.growth = this;
    this.grow(lines.plant);
    this.grow(lines.overlay);
    this.times(lines.plant, lines.times);
    this.times(lines.overlay, lines.overTimes);
  }

  /** Makes `lines` grow with the time: their program is made again for the next frame. */
  grow(lines: TexelLines): void {
    const material = lines.mesh.material as unknown as ShaderMaterial;
    // (The texel lines give their uniforms to the shader they compile: these too.)
    lines.uniforms[TIMES] = { value: null };
    lines.uniforms[UNIFORM] = this.time;
    const before = material.onBeforeCompile.bind(material);
    material.onBeforeCompile = (shader, renderer) => {
      before(shader, renderer);
      shader.vertexShader = growingLineShader(shader.vertexShader);
    };
    const key = material.customProgramCacheKey.bind(material);
    material.customProgramCacheKey = () => `${key()}|growth`;
    material.needsUpdate = true;
  }

  /** Gives the segments `lines` draws their growth `times` (two a segment; none: drawn whole). */
  times(lines: TexelLines, times: Float32Array | undefined): void {
    const uniform = lines.uniforms[TIMES] as { value: DataTexture | null } | undefined;
    if (!uniform) return;
    uniform.value?.dispose();
    uniform.value = null;
    if (!times || times.length === 0) return;
    const { data, width, height } = timeRows(times, lines.perRow);
    const texture = new DataTexture(data, width, height, RGFormat, FloatType);
    texture.minFilter = texture.magFilter = NearestFilter;
    texture.needsUpdate = true;
    uniform.value = texture;
  }

  /** `ends` grown by `times` to the time shown ({@link grownSegmentEnds}); `ends` while the plant is whole. */
  grown(ends: Float32Array, times: Float32Array | undefined): Float32Array {
    const t = this.time.value;
    if (!times || t >= WHOLE) return ends;
    const last = this.grownAt.get(ends);
    if (last?.t === t && last.times === times) return last.grown;
    const grown = grownSegmentEnds(ends, times, t);
    this.grownAt.set(ends, { t, times, grown });
    return grown;
  }

  /** Frees the textures of `lines`' times. */
  dispose(...lines: TexelLines[]): void {
    for (const l of lines) this.times(l, undefined);
  }
}
