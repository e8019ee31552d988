import { describe, expect, it } from 'vitest';
import type { MeshBuffers } from '../core';
import { highlightOverlay, highlightSegments, moduleOfTriangle } from './highlight';

/** Three triangles over five vertices: triangles 0-1 from module 7, triangle 2 from module 9. */
function mesh(): MeshBuffers {
  return {
    positions: new Float32Array(15),
    normals: new Float32Array(15),
    colors: new Float32Array([0.2, 0.4, 0.6, 0.2, 0.4, 0.6, 0.2, 0.4, 0.6, 0.2, 0.4, 0.6, 0.2, 0.4, 0.6]),
    indices: new Uint32Array([0, 1, 2, 1, 3, 2, 3, 4, 2]),
    ranges: new Uint32Array([0, 7, 2, 9]),
    lines: new Float32Array(0),
    lineColors: new Float32Array(0),
    uvs: new Float32Array(0),
    materialRanges: new Uint32Array(0),
    segmentEnds: Float32Array.from({ length: 12 }, (_, i) => i),
    segmentColors: new Float32Array(12),
    segmentModules: new Uint32Array([7, 9]),
  };
}

describe('moduleOfTriangle', () => {
  it('finds the range a triangle falls in', () => {
    const ranges = new Uint32Array([0, 7, 2, 9, 10, 4]);
    expect([0, 1, 2, 9, 10, 500].map((t) => moduleOfTriangle(ranges, t))).toEqual([7, 7, 9, 9, 4, 4]);
    expect(moduleOfTriangle(new Uint32Array(0), 0)).toBeNull();
  });
});

describe('highlightOverlay', () => {
  it('copies the triangles of the chosen modules with their colour, and only those', () => {
    const m = mesh();
    m.positions = Float32Array.from({ length: 15 }, (_, i) => i);
    const overlay = highlightOverlay(m, (module) => (module === 9 ? [1, 0, 0] : null));
    // Module 9 drew triangle 2 = vertices 3, 4, 2.
    expect(Array.from(overlay.positions)).toEqual([9, 10, 11, 12, 13, 14, 6, 7, 8]);
    expect(Array.from(overlay.colors)).toEqual([1, 0, 0, 1, 0, 0, 1, 0, 0]);
    expect(overlay.normals.length).toBe(9);
    const both = highlightOverlay(m, (module) => (module === 7 ? [0, 1, 0] : [0, 0, 1]));
    expect(both.positions.length).toBe(27);
    expect(Array.from(both.colors.slice(0, 3))).toEqual([0, 1, 0]);
    expect(Array.from(both.colors.slice(18, 21))).toEqual([0, 0, 1]);
    expect(highlightOverlay(m, () => null).positions.length).toBe(0);
  });
});

describe('highlightOverlay with packed normals', () => {
  it('reads the normals the GPU has: floats, or 16-bit normalized integers', () => {
    const m = mesh();
    m.normals = Float32Array.from({ length: 15 }, (_, i) => (i % 3 === 1 ? -0.6 : 0.8));
    const packed = Int16Array.from(m.normals, (n) => Math.round(n * 32767));
    m.normals = new Float32Array(0); // what the build worker sends with packed normals
    const overlay = highlightOverlay(m, (module) => (module === 9 ? [1, 0, 0] : null), true, packed);
    const expected = [0.8, -0.6, 0.8, 0.8, -0.6, 0.8, 0.8, -0.6, 0.8];
    overlay.normals.forEach((n, i) => expect(n).toBeCloseTo(expected[i], 4));
  });
});

describe('highlightOverlay without tubes', () => {
  it('leaves out the triangles of modules that drew tubes (kind 0) and keeps the others', () => {
    const m = mesh();
    m.materialRanges = new Uint32Array([0, 0, 2, 1]); // triangles 0-1 bark (module 7), triangle 2 leaf (module 9)
    expect(highlightOverlay(m, () => [1, 0, 0], false).positions.length).toBe(9);
    expect(highlightOverlay(m, (module) => (module === 7 ? [1, 0, 0] : null), false).positions.length).toBe(0);
    expect(highlightOverlay(m, () => [1, 0, 0]).positions.length).toBe(27);
  });
});

describe('highlightSegments', () => {
  it('copies the lines of the chosen modules with their colour at both ends', () => {
    const overlay = highlightSegments(mesh(), (module) => (module === 9 ? [0, 1, 0] : null));
    expect(Array.from(overlay.ends)).toEqual([6, 7, 8, 9, 10, 11]);
    expect(Array.from(overlay.colors)).toEqual([0, 1, 0, 0, 1, 0]);
    expect(highlightSegments(mesh(), () => null).ends.length).toBe(0);
    expect(overlay.times, 'no growth times: none').toBeUndefined();
  });

  it("copies the chosen segments' growth times too (the highlight grows as its segments do)", () => {
    const overlay = highlightSegments({ ...mesh(), segmentGrowthTimes: new Float32Array([-1, 0, 1.5, 2]) }, (module) => (module === 9 ? [0, 1, 0] : null));
    expect(Array.from(overlay.times!)).toEqual([1.5, 2]);
  });
});
