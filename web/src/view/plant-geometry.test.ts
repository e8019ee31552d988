import { describe, expect, it } from 'vitest';
import type { MeshBuffers } from '../core';
import { packForGpu } from './gpu-arrays';
import { plantGeometry, pointsBox } from './plant-geometry';

/** A strip of `quads` quads (2 triangles each) along x: vertices 2k, 2k+1 at x = k. */
function strip(quads: number): MeshBuffers {
  const vertices = 2 * (quads + 1);
  const positions = new Float32Array(3 * vertices);
  for (let v = 0; v < vertices; v++) positions.set([v >> 1, v & 1, 0], 3 * v);
  const indices = new Uint32Array(6 * quads);
  for (let q = 0; q < quads; q++) indices.set([2 * q, 2 * q + 2, 2 * q + 1, 2 * q + 1, 2 * q + 2, 2 * q + 3], 6 * q);
  const empty = new Float32Array(0);
  return { positions, normals: positions.slice(), colors: positions.slice(), indices, ranges: new Uint32Array(0), uvs: new Float32Array(0), materialRanges: new Uint32Array(0), lines: empty, lineColors: empty, segmentEnds: empty, segmentColors: empty, segmentModules: new Uint32Array(0) };
}

describe('plantGeometry', () => {
  it('wraps the arrays without copying them, with bounds', () => {
    const mesh = strip(10);
    const geometry = plantGeometry(mesh);
    expect(geometry.getAttribute('color').array).toBe(mesh.colors);
    expect(geometry.boundingBox!.max.toArray()).toEqual([10, 1, 0]);
    expect(geometry.boundingSphere!.radius).toBeGreaterThan(5);
  });
});

describe('pointsBox', () => {
  it('bounds the points, and is empty without any', () => {
    const box = pointsBox(new Float32Array([1, 2, 3, -1, 5, 0]));
    expect(box.min.toArray()).toEqual([-1, 2, 0]);
    expect(box.max.toArray()).toEqual([1, 5, 3]);
    expect(pointsBox(new Float32Array(0)).isEmpty()).toBe(true);
  });
});

describe('packForGpu', () => {
  it('packs unit normals to 16 bits and colours to 8 bits, within a rounding step', () => {
    const mesh = strip(4);
    mesh.normals.set([0, 0, 1, 0.6, -0.8, 0, -1, 0, 0]);
    mesh.colors.set([0.5, 0.25, 1, 0, 0.0031, 2]);
    const gpu = packForGpu(mesh);
    expect(gpu.normals).toBeInstanceOf(Int16Array);
    expect(Array.from(gpu.normals.slice(0, 9))).toEqual([0, 0, 32767, 19660, -26214, 0, -32767, 0, 0]);
    expect(Array.from(gpu.colors.slice(0, 6))).toEqual([128, 64, 255, 0, 1, 255]);
    for (let i = 0; i < 9; i++) expect(Math.abs(gpu.normals[i] / 32767 - mesh.normals[i])).toBeLessThan(1e-4);
  });

  it('gives every value Math.round of the clamped, scaled value, colours changing from vertex to vertex', () => {
    const count = 3000;
    const mesh = strip(count / 2);
    let seed = 20;
    const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648) * 2.4 - 1.2;
    // Runs of one colour (as a tube's rings), then a change every vertex; rounding ties and
    // out-of-range values included.
    for (let i = 0; i < mesh.normals.length; i++) mesh.normals[i] = random();
    for (let v = 0; v < count; v++) {
      const run = v < count / 2 ? Math.floor(v / 7) : v;
      for (let k = 0; k < 3; k++) mesh.colors[3 * v + k] = ((run * 3 + k) * 0.37) % 1.3 - 0.1;
    }
    mesh.normals.set([0.5 / 32767, -0.5 / 32767, 1.5 / 32767, -1.5 / 32767, NaN, -0, 1, -1, 2]);
    mesh.colors.set([0.5 / 255, 1.5 / 255, 254.5 / 255, NaN, -0, 1, 0.2, 0.2, 0.2]);
    const gpu = packForGpu(mesh);
    mesh.normals.forEach((n, i) => expect(gpu.normals[i], `normal ${i}`).toBe(Math.round(Math.max(-1, Math.min(1, n)) * 32767) || 0));
    mesh.colors.forEach((c, i) => expect(gpu.colors[i], `colour ${i}`).toBe(Math.round(Math.max(0, Math.min(1, c)) * 255) || 0));
  });

  it('gives plantGeometry normalized attributes', () => {
    const mesh = strip(2);
    const geometry = plantGeometry(mesh, packForGpu(mesh));
    expect(geometry.getAttribute('normal').normalized).toBe(true);
    expect(geometry.getAttribute('color').array).toBeInstanceOf(Uint8Array);
  });
});
