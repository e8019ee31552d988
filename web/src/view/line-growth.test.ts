import { Box3, type DataTexture } from 'three';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { describe, expect, it } from 'vitest';
import { WHOLE } from './growth-arrays';
import { grownFraction } from './growth';
import { growingLineShader, grownSegmentEnds, LineGrowth, timeRows } from './line-growth';
import { TexelLines, texelLineShader } from './texel-lines';

describe('growingLineShader', () => {
  const shader = growingLineShader(texelLineShader(new LineMaterial().vertexShader));

  it("grows the segment's end after its ends are read, before anything uses them", () => {
    expect(shader).toMatch(/^uniform highp sampler2D lineGrowth;\nuniform float meristemGrowthTime;/);
    const read = shader.indexOf('instanceColorEnd = texelFetch(lineColors');
    const grown = shader.indexOf('instanceEnd = instanceStart + (instanceEnd - instanceStart) * lineGrown;');
    expect(read).toBeGreaterThan(0);
    expect(grown).toBeGreaterThan(read);
    expect(grown).toBeLessThan(shader.indexOf('vec4 end = modelViewMatrix * vec4( instanceEnd, 1.0 );'));
    // The same smoothstep as the tubes' (./growth.ts), of the same uniform.
    expect(shader).toContain('clamp((meristemGrowthTime - lineTimes.x) / (lineTimes.y - lineTimes.x), 0.0, 1.0)');
    expect(shader).toContain('lineGrown = lineX * lineX * (3.0 - 2.0 * lineX);');
  });

  it('puts a segment not started yet out of sight after its corner is placed', () => {
    const placed = shader.indexOf('gl_Position = clip;');
    const hidden = shader.indexOf('if (lineGrown <= 0.0) gl_Position = vec4(0.0, 0.0, 2.0, 1.0);');
    expect(placed).toBeGreaterThan(0);
    expect(hidden).toBeGreaterThan(placed);
  });

  it('refuses a shader it does not fit', () => {
    expect(() => growingLineShader(new LineMaterial().vertexShader)).toThrow(/no longer fits/);
  });
});

describe('timeRows', () => {
  it('lays two times a segment out one texel a segment, in rows of `perRow`, the last padded', () => {
    const times = Float32Array.from({ length: 5 * 2 }, (_, i) => i);
    const { data, width, height } = timeRows(times, 2);
    expect([width, height]).toEqual([2, 3]);
    expect([...data]).toEqual([0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 0, 0]);
  });
});

describe('grownSegmentEnds', () => {
  // Two segments: (0,0,0)-(0,2,0) grown over [0, 1], (0,2,0)-(2,2,0) over [1, 3].
  const ends = new Float32Array([0, 0, 0, 0, 2, 0, 0, 2, 0, 2, 2, 0]);
  const times = new Float32Array([0, 1, 1, 3]);

  it('moves each end towards its start by the fraction grown, as the shader does', () => {
    const grown = grownSegmentEnds(ends, times, 2);
    expect([...grown.subarray(0, 6)]).toEqual([0, 0, 0, 0, 2, 0]); // whole since t = 1
    const g = grownFraction(2, 1, 3); // 0.5
    expect([...grown.subarray(6, 9)]).toEqual([0, 2, 0]);
    expect(grown[9]).toBeCloseTo(2 * g, 6);
    expect(grown[10]).toBe(2);
    expect(grownSegmentEnds(ends, times, 0.5)[4]).toBeCloseTo(2 * grownFraction(0.5, 0, 1), 6);
  });

  it('gives a segment not started yet no ends to draw or pick (NaN)', () => {
    const grown = grownSegmentEnds(ends, times, 1);
    expect([...grown.subarray(0, 6)]).toEqual([0, 0, 0, 0, 2, 0]);
    expect([...grown.subarray(6)].every(Number.isNaN)).toBe(true);
  });

  it('keeps the ends when the times are not two a segment', () => {
    expect(grownSegmentEnds(ends, new Float32Array([0, 1]), 0.5)).toBe(ends);
  });
});

describe('LineGrowth', () => {
  it("makes texel lines' program grow (cached apart), with their times as a texture", () => {
    const material = new LineMaterial();
    const lines = new TexelLines(material);
    const plain = material.customProgramCacheKey();
    const time = { value: 1.5 };
    const growth = new LineGrowth(time);
    growth.grow(lines);
    expect(material.customProgramCacheKey()).toBe(`${plain}|growth`);
    const shader = { vertexShader: material.vertexShader, fragmentShader: '', uniforms: {} as Record<string, unknown> };
    material.onBeforeCompile(shader as never, undefined as never);
    expect(shader.vertexShader).toContain('instanceEnd = instanceStart + (instanceEnd - instanceStart) * lineGrown;');
    expect(shader.uniforms.meristemGrowthTime).toBe(time);
    growth.times(lines, new Float32Array([0, 1, 1, 3]));
    const texture = (shader.uniforms.lineGrowth as { value: DataTexture }).value;
    expect(texture.image).toMatchObject({ width: lines.perRow, height: 1 });
    expect([...(texture.image.data as Float32Array).subarray(0, 4)]).toEqual([0, 1, 1, 3]);
    growth.times(lines, undefined);
    expect((shader.uniforms.lineGrowth as { value: unknown }).value).toBeNull();
    lines.setSegments(new Float32Array(0), new Float32Array(0), new Box3());
  });

  it('grows ends on the CPU at the time shown, the same array while it stays, the ends themselves when whole', () => {
    const time = { value: 2 };
    const growth = new LineGrowth(time);
    const ends = new Float32Array([0, 0, 0, 0, 2, 0]);
    const times = new Float32Array([1, 3]);
    const grown = growth.grown(ends, times);
    expect(grown[4]).toBeCloseTo(1, 6);
    expect(growth.grown(ends, times)).toBe(grown);
    time.value = 3;
    expect(growth.grown(ends, times)[4]).toBe(2);
    time.value = WHOLE;
    expect(growth.grown(ends, times)).toBe(ends);
    expect(growth.grown(ends, undefined)).toBe(ends);
  });
});
