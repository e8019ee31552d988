import { BufferAttribute, BufferGeometry, Mesh, MeshBasicMaterial } from 'three';
import { describe, expect, it } from 'vitest';
import { grownFraction } from './growth';
import { drawGrown, orderByStart, startedBy } from './grown-triangles';

/**
 * Four triangles of 3 vertices each: triangle k's element grows over [starts[k], starts[k] + 1]
 * about origin (k, 0, 0); a start of null: a triangle that does not grow (times (0, 0)).
 */
function elements(starts: (number | null)[]): { indices: Uint32Array; origins: Float32Array; times: Float32Array } {
  const indices = new Uint32Array(3 * starts.length).map((_, i) => i);
  const origins = new Float32Array(9 * starts.length);
  const times = new Float32Array(6 * starts.length);
  starts.forEach((start, k) => {
    for (let v = 3 * k; v < 3 * k + 3; v++) {
      origins[3 * v] = k;
      if (start !== null) times.set([start, start + 1], 2 * v);
    }
  });
  return { indices, origins, times };
}

describe('orderByStart', () => {
  it('orders each range by its triangles’ starts, stably, with their keys', () => {
    const { indices, origins, times } = elements([3, -1, 0.5, 3, 2, 0.5]);
    const ordered = orderByStart(indices, origins, times, [
      { start: 0, count: 12 },
      { start: 12, count: 6 },
    ])!;
    // The first group (triangles 0-3) by start: 1 (−1), 2 (0.5), 0 (3), 3 (3); the second: 5 (0.5), 4 (2).
    expect([...ordered.indices].map((v) => Math.floor(v / 3))).toEqual([1, 1, 1, 2, 2, 2, 0, 0, 0, 3, 3, 3, 5, 5, 5, 4, 4, 4]);
    expect([...ordered.keys[0]]).toEqual([-1024, 512, 3072, 3072]);
    expect([...ordered.keys[1]]).toEqual([512, 2048]);
    expect([...indices]).toEqual([...Array(18).keys()]); // the mesh's own index is left as it was
  });

  it('never leaves out a triangle that does not grow, or whose vertices grow from different points', () => {
    const { indices, origins, times } = elements([5, null, 5]);
    origins[3 * 7 + 1] = 0.25; // triangle 2's second vertex grows from elsewhere
    const ordered = orderByStart(indices, origins, times, [{ start: 0, count: 9 }])!;
    expect([...ordered.indices].map((v) => Math.floor(v / 3))).toEqual([1, 1, 1, 2, 2, 2, 0, 0, 0]);
    expect(startedBy(ordered.keys[0], 0)).toBe(2);
  });
});

describe('startedBy', () => {
  it('counts the triangles begun by t: every one with some vertex grown, none that is still a point', () => {
    const starts = [-1, 0, 0.3, 1, 1.5, 2.75, 4];
    const { indices, origins, times } = elements(starts);
    const { keys } = orderByStart(indices, origins, times, [{ start: 0, count: indices.length }])!;
    for (const t of [0, 0.1, 0.3, 0.31, 1, 1.2, 2.75, 3.9, 4, 4.5, 7]) {
      const begun = starts.filter((start) => grownFraction(t, start, start + 1) > 0).length;
      const drawn = startedBy(keys[0], t);
      // Every triangle grown at all is drawn; a triangle drawn and not grown starts within 1/1024 of t.
      expect(drawn).toBeGreaterThanOrEqual(begun);
      for (const start of starts.slice(begun, drawn)) expect(start).toBeGreaterThan(t - 1 / 1024);
      expect(drawn).toBeLessThanOrEqual(starts.filter((start) => start < t + 1 / 1024).length);
    }
  });
});

describe('drawGrown', () => {
  /** A mesh drawn from `source` (its GPU twin stands in: the same index) and a WebGL stand-in that records uploads. */
  function scene(starts: number[], groups: [number, number][], material: MeshBasicMaterial | MeshBasicMaterial[]) {
    const { indices, origins, times } = elements(starts);
    const source = new BufferGeometry();
    source.setIndex(new BufferAttribute(indices, 1));
    source.setAttribute('growthOrigin', new BufferAttribute(origins, 3));
    source.setAttribute('growthTime', new BufferAttribute(times, 2));
    const geometry = new BufferGeometry();
    const drawnIndex = { count: indices.length, buffer: {} };
    geometry.index = drawnIndex as unknown as BufferAttribute;
    for (const [start, count] of groups) geometry.addGroup(start, count, 0);
    const uploads: Uint32Array[] = [];
    const gl = { COPY_WRITE_BUFFER: 1, bindBuffer: () => undefined, bufferSubData: (_: number, __: number, data: Uint32Array) => uploads.push(data.slice()) } as unknown as WebGL2RenderingContext;
    return { mesh: new Mesh(geometry, material), source, gl, uploads };
  }

  it('cuts each group to its begun triangles with an array of materials, and restores them for the whole plant', () => {
    const { mesh, source, gl, uploads } = scene([2, 0, 1, 3], [[0, 6], [6, 6]], [new MeshBasicMaterial()]);
    drawGrown(mesh, source, gl, 0.5);
    expect(uploads).toHaveLength(1);
    expect([...uploads[0]].map((v) => Math.floor(v / 3))).toEqual([1, 1, 1, 0, 0, 0, 2, 2, 2, 3, 3, 3]);
    expect(mesh.geometry.groups.map((g) => g.count)).toEqual([3, 0]);
    drawGrown(mesh, source, gl, 2.5);
    expect(mesh.geometry.groups.map((g) => g.count)).toEqual([6, 3]);
    expect(uploads).toHaveLength(1); // ordered once
    drawGrown(mesh, source, gl, null);
    expect(mesh.geometry.groups.map((g) => g.count)).toEqual([6, 6]);
    expect(mesh.geometry.drawRange.count).toBe(Infinity);
  });

  it('cuts the draw range with one material (three.js then ignores the groups), but only of one group', () => {
    const one = scene([2, 0, 1], [], new MeshBasicMaterial());
    drawGrown(one.mesh, one.source, one.gl, 0.5);
    expect(one.mesh.geometry.drawRange).toEqual({ start: 0, count: 3 });
    const two = scene([2, 0, 1, 3], [[0, 6], [6, 6]], new MeshBasicMaterial());
    drawGrown(two.mesh, two.source, two.gl, 0.5);
    expect(two.mesh.geometry.drawRange.count).toBe(Infinity);
    expect(two.mesh.geometry.groups.map((g) => g.count)).toEqual([6, 6]);
  });
});
