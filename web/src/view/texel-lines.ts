// Wide lines (three.js's `LineMaterial`, the look of `LineSegments2`) drawn without instancing:
// each segment's ends and end colours are two texels of two float textures, which the vertex
// shader reads by `gl_VertexID` (eight vertices a segment, the corners of `LineSegmentsGeometry`'s
// box). SwiftShader, Chromium's WebGL on a machine without a usable GPU, pays about 10 µs per
// instance: 116,050 segments as `LineSegments2` (an instance each) took 1.2–2.6 s a frame there.
// The upload stays 48 bytes a segment (the core's two arrays, each copied whole into its
// texture's rows); the index buffer (18 indices a segment) is one for every plant, grown when a
// plant needs more, so it is uploaded only then.
import { Box3, BufferAttribute, BufferGeometry, DataTexture, FloatType, Mesh, NearestFilter, RGBFormat, type WebGLRenderer, Vector4 } from 'three';
import type { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { setBox } from './plant-geometry';

/** Texels a segment takes in each texture: its start and its end (xyz, or rgb). */
const TEXELS = 2;
/** The box's triangles, as `LineSegmentsGeometry` has them: 6 a segment, over its 8 corners. */
const BOX = [0, 2, 1, 2, 3, 1, 2, 4, 3, 4, 5, 3, 4, 6, 5, 6, 7, 5];

/**
 * The segment and corner of each vertex, and the values `LineMaterial`'s vertex shader reads from
 * attributes, read from the texture instead: its attributes become plain variables, `position`
 * and `uv` the corner's (`LineSegmentsGeometry`'s: x ±1, y 2, 1, 0, -1 for the end cap, the end,
 * the start and the start cap; uv y 2, 1, -1, -2).
 */
const FETCH = /* glsl */ `
  int lineSegment = gl_VertexID >> 3;
  int lineCornerIndex = gl_VertexID & 7;
  float lineSide = (lineCornerIndex & 1) == 0 ? -1.0 : 1.0;
  float lineY = float(2 - (lineCornerIndex >> 1));
  vec3 lineCorner = vec3(lineSide, lineY, 0.0);
  vec2 lineUv = vec2(lineSide, lineY > 0.5 ? lineY : lineY - 1.0);
  ivec2 lineAt = ivec2((lineSegment % lineSegmentsPerRow) * ${TEXELS}, lineSegment / lineSegmentsPerRow);
  instanceStart = texelFetch(lineEnds, lineAt, 0).xyz;
  instanceEnd = texelFetch(lineEnds, lineAt + ivec2(1, 0), 0).xyz;
  instanceColorStart = texelFetch(lineColors, lineAt, 0).xyz;
  instanceColorEnd = texelFetch(lineColors, lineAt + ivec2(1, 0), 0).xyz;
`;

/** `LineMaterial`'s vertex shader, reading the texture rather than instance attributes. */
export function texelLineShader(vertexShader: string): string {
  const shader = vertexShader
    .replace(/attribute vec3 (instanceStart|instanceEnd|instanceColorStart|instanceColorEnd);/g, 'vec3 $1;')
    .replace(/\bposition\./g, 'lineCorner.')
    .replace(/\bvUv = uv;/g, 'vUv = lineUv;')
    .replace('void main() {', `uniform highp sampler2D lineEnds;\nuniform highp sampler2D lineColors;\nuniform int lineSegmentsPerRow;\nvoid main() {\n${FETCH}`);
  if (/attribute vec3 instance|\bposition\b|= uv;/.test(shader) || !shader.includes('lineEnds')) {
    throw new Error('three.js\'s LineMaterial shader changed: the texel lines no longer fit it');
  }
  return shader;
}

/**
 * `values` (6 floats a segment: two texels of 3) as the rows of a texture of `perRow` segments a
 * row: the array itself when it fills its last row, else a copy that does.
 */
export function segmentRows(values: Float32Array, perRow: number): { data: Float32Array; width: number; height: number } {
  const width = perRow * TEXELS;
  const height = Math.max(1, Math.ceil(values.length / 6 / perRow));
  const length = width * height * 3;
  if (values.length === length) return { data: values, width, height };
  const data = new Float32Array(length);
  data.set(values.subarray(0, length));
  return { data, width, height };
}

/** The indices of `segments` segments' boxes (18 each, over 8 vertices each). */
export function boxIndices(segments: number): Uint32Array {
  const indices = new Uint32Array(segments * BOX.length);
  for (let s = 0; s < segments; s++) {
    for (let k = 0; k < BOX.length; k++) indices[s * BOX.length + k] = 8 * s + BOX[k];
  }
  return indices;
}

/**
 * A mesh that draws segments with `material` (a `LineMaterial`, which it changes to read
 * textures: give it a material of its own), as `LineSegments2` would. {@link setSegments} replaces
 * them; `maxTextureSize` is the GPU's (a plant of more segments than its texture holds is not
 * drawn: {@link fits}).
 */
export class TexelLines {
  readonly mesh: Mesh<BufferGeometry, LineMaterial>;
  /** The shader's uniforms (the growth adds its own, ./line-growth.ts). */
  readonly uniforms: Record<string, { value: unknown }> & {
    lineEnds: { value: DataTexture | null };
    lineColors: { value: DataTexture | null };
    lineSegmentsPerRow: { value: number };
  } = {
    lineEnds: { value: null },
    lineColors: { value: null },
    lineSegmentsPerRow: { value: 1 },
  };
  /** Segments the index buffer has boxes for. */
  private capacity = 0;

  constructor(
    material: LineMaterial,
    private readonly maxTextureSize = 2048,
  ) {
    material.onBeforeCompile = (shader) => {
      shader.vertexShader = texelLineShader(shader.vertexShader);
      Object.assign(shader.uniforms, this.uniforms);
    };
    material.customProgramCacheKey = () => 'texel-lines';
    this.mesh = new Mesh(new BufferGeometry(), material);
    const viewport = new Vector4();
    // As `LineSegments2` does: the line width is in pixels of the viewport drawn into.
    this.mesh.onBeforeRender = (renderer: WebGLRenderer) => {
      renderer.getViewport(viewport);
      material.resolution.set(viewport.z, viewport.w);
    };
    this.setSegments(new Float32Array(0), new Float32Array(0), new Box3());
  }

  /** Segments per texture row (a row is at most `maxTextureSize` texels wide). */
  get perRow(): number {
    return Math.floor(this.maxTextureSize / TEXELS);
  }

  /** Whether `segments` segments fit a texture of this GPU. */
  fits(segments: number): boolean {
    return Math.ceil(segments / this.perRow) <= this.maxTextureSize;
  }

  /**
   * Draws the segments `ends` (start xyz, end xyz each) with `colors` (rgb at each end), within
   * `box`; none when they do not {@link fits}.
   */
  setSegments(ends: Float32Array, colors: Float32Array, box: Box3): void {
    const segments = this.fits(ends.length / 6) ? Math.floor(ends.length / 6) : 0;
    // None: no textures (a plant's show clears the highlight, each edit: no empty rows to upload).
    this.uniforms.lineEnds.value = this.texture(this.uniforms.lineEnds.value, ends.subarray(0, 6 * segments));
    this.uniforms.lineColors.value = this.texture(this.uniforms.lineColors.value, colors.subarray(0, 6 * segments));
    this.uniforms.lineSegmentsPerRow.value = this.perRow;
    if (segments > this.capacity) {
      // A new geometry: disposing of the old frees its index buffer on the GPU.
      this.mesh.geometry.dispose();
      this.mesh.geometry = new BufferGeometry();
      this.capacity = 2 ** Math.ceil(Math.log2(segments));
      this.mesh.geometry.setIndex(new BufferAttribute(boxIndices(this.capacity), 1));
    }
    this.mesh.geometry.setDrawRange(0, BOX.length * segments);
    setBox(this.mesh.geometry, box);
    this.mesh.visible = segments > 0;
  }

  /** A texture of `values`' rows (see {@link segmentRows}), or none for no values; `old` disposed of. */
  private texture(old: DataTexture | null, values: Float32Array): DataTexture | null {
    old?.dispose();
    if (values.length === 0) return null;
    const { data, width, height } = segmentRows(values, this.perRow);
    const texture = new DataTexture(data, width, height, RGBFormat, FloatType);
    texture.internalFormat = 'RGB32F'; // three.js names no sized format for RGB floats itself
    texture.minFilter = texture.magFilter = NearestFilter;
    texture.needsUpdate = true;
    return texture;
  }

  dispose(): void {
    this.uniforms.lineEnds.value?.dispose();
    this.uniforms.lineColors.value?.dispose();
    this.mesh.geometry.dispose();
  }
}
