import { describe, expect, it } from 'vitest';
import type { MeshBuffers } from '../core';
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

describe('plantGeometry with the core\'s bounds', () => {
  it('takes the box it is given instead of measuring the points, and measures them without one', () => {
    const mesh = strip(10);
    const given = plantGeometry(mesh, undefined, [[-1, -2, -3], [11, 2, 3]]);
    expect(given.boundingBox!.min.toArray()).toEqual([-1, -2, -3]);
    expect(given.boundingBox!.max.toArray()).toEqual([11, 2, 3]);
    expect(given.boundingSphere!.radius).toBeCloseTo(Math.hypot(6, 2, 3));
    expect(plantGeometry(mesh).boundingBox!.max.toArray()).toEqual([10, 1, 0]);
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

describe('plantGeometry with packed normals and colours', () => {
  it('gives them as normalized attributes', () => {
    const mesh = strip(2);
    const vertices = mesh.positions.length / 3;
    const geometry = plantGeometry(mesh, { normals: new Int16Array(3 * vertices), colors: new Uint8Array(3 * vertices) });
    expect(geometry.getAttribute('normal').normalized).toBe(true);
    expect(geometry.getAttribute('normal').array).toBeInstanceOf(Int16Array);
    expect(geometry.getAttribute('color').normalized).toBe(true);
    expect(geometry.getAttribute('color').array).toBeInstanceOf(Uint8Array);
  });

  it('refuses a mesh without its float normals unless the packed ones come with it', () => {
    const mesh = { ...strip(2), normals: new Float32Array(0), colors: new Float32Array(0) };
    expect(() => plantGeometry(mesh)).toThrow(/packed/);
  });
});
