import { describe, expect, it } from 'vitest';
import { SpareBuffers } from './spare-buffers';
import { SpareCopies } from './spare-copies';

/** A stand-in for a studio-core build: each `…Into` fills its array with `value`. */
function build(value: number): object {
  const fill = (out: { fill(v: number): unknown }) => void out.fill(value);
  return {
    positionsInto: fill,
    indicesInto: fill,
    uvsInto: fill,
    packedNormalsInto: fill,
    packedColorsInto: fill,
    segmentEndsInto: fill,
    segmentColorsInto: fill,
  };
}

describe('copies of a build into spare buffers', () => {
  it('prepares, by default, spares for the arrays of the build it last copied', () => {
    const spares = new SpareBuffers(() => undefined as unknown as ReturnType<typeof setTimeout>);
    const copies = new SpareCopies(spares);
    // 300,000 vertices and triangles, 100,000 segments: each of the seven arrays over a megabyte
    // but the packed colours (0.9 MB, copied as usual).
    const counts = { vertices: 300_000, triangles: 300_000, segments: 100_000 };
    expect(Object.values(copies.copy(build(1), counts)).filter(Boolean)).toEqual([]); // none made yet
    copies.prepare();
    expect(spares.bytes).toBe(3.6e6 + 3.6e6 + 2.4e6 + 1.8e6 + 2.4e6 + 2.4e6);
    const arrays = copies.copy(build(2), counts);
    expect(Object.keys(arrays).filter((k) => arrays[k as keyof typeof arrays] !== undefined)).toEqual(['positions', 'indices', 'uvs', 'normals', 'segmentEnds', 'segmentColors']);
    expect(arrays.positions?.length).toBe(900_000);
    expect(arrays.segmentColors?.every((v) => v === 2)).toBe(true);
    expect(spares.bytes).toBe(0);
  });
});
