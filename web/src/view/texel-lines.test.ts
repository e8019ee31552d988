import { describe, expect, it } from 'vitest';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { boxIndices, segmentRows, texelLineShader } from './texel-lines';

describe('texelLineShader', () => {
  it('turns LineMaterial\'s instance attributes, position and uv into values read from the texture', () => {
    const shader = texelLineShader(new LineMaterial().vertexShader);
    expect(shader).not.toMatch(/attribute vec3 instance/);
    expect(shader).not.toMatch(/\bposition\b/);
    expect(shader).toContain('vUv = lineUv;');
    expect(shader).toContain('vColor.xyz = ( lineCorner.y < 0.5 ) ? instanceColorStart : instanceColorEnd;');
    // The texture is read before anything uses what it holds.
    const main = shader.indexOf('void main() {');
    const read = shader.indexOf('instanceEnd = texelFetch(lineEnds, lineAt + ivec2(1, 0), 0).xyz;');
    expect(read).toBeGreaterThan(main);
    expect(read).toBeLessThan(shader.indexOf('vColor.xyz'));
  });

  it('refuses a shader it does not fit', () => {
    expect(() => texelLineShader('void main() { gl_Position = vec4(position, 1.0); }')).toThrow(/LineMaterial shader changed/);
  });
});

describe('segmentRows', () => {
  it('lays six floats a segment out in rows of whole segments, the last row padded', () => {
    const values = Float32Array.from({ length: 5 * 6 }, (_, i) => i);
    const { data, width, height } = segmentRows(values, 2);
    expect([width, height]).toEqual([4, 3]); // two texels of three floats a segment
    expect(data.length).toBe(4 * 3 * 3);
    // Segment 3: row 1, second slot: the floats 18 to 23, from float 12 × 1 + 6.
    expect([...data.subarray(18, 24)]).toEqual([18, 19, 20, 21, 22, 23]);
    expect([...data.subarray(30)]).toEqual([0, 0, 0, 0, 0, 0]); // the last row's empty slot
  });

  it('takes an array that fills its rows as it is', () => {
    const values = new Float32Array(4 * 6);
    expect(segmentRows(values, 2).data).toBe(values);
    expect(segmentRows(new Float32Array(0), 2)).toMatchObject({ width: 4, height: 1 });
  });
});

describe('boxIndices', () => {
  it('gives each segment LineSegmentsGeometry\'s six triangles over its own eight corners', () => {
    const indices = boxIndices(3);
    expect(indices.length).toBe(54);
    expect([...indices.subarray(18, 36)]).toEqual([8, 10, 9, 10, 11, 9, 10, 12, 11, 12, 13, 11, 12, 14, 13, 14, 15, 13]);
    expect(Math.max(...indices)).toBe(23);
  });
});
