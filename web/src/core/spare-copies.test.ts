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

/** A sketch of `lines` lines: its ends and their colours, every value `value`. */
function sketchOf(value: number, lines: number): [Float32Array, Float32Array] {
  return [new Float32Array(6 * lines).fill(value), new Float32Array(6 * lines).fill(value)];
}

/** Spares whose pages are never touched (no timers in these tests). */
const untouchedSpares = () => new SpareBuffers(() => undefined as unknown as ReturnType<typeof setTimeout>);

/** Untouched spares that record the sizes asked for and make the first `keep` of them. */
class RecordingSpares extends SpareBuffers {
  prepared: readonly number[] = [];
  keep = Infinity;

  constructor() {
    super(() => undefined as unknown as ReturnType<typeof setTimeout>);
  }

  override prepare(sizes: readonly number[]): void {
    this.prepared = sizes;
    super.prepare(sizes.slice(0, this.keep));
  }
}

describe('copies of a build into spare buffers', () => {
  it('prepares, by default, spares for the arrays of the build it last copied', () => {
    const spares = untouchedSpares();
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

  it('copies a sketch into spares before its build, and prepares the sketch’s sizes first', () => {
    const spares = new RecordingSpares();
    const copies = new SpareCopies(spares);
    // 100,000 lines: their ends and colours 2.4 MB each; a mesh of 100,000 vertices (1.2 MB of
    // positions) and no segments drawn as a mesh.
    const counts = { vertices: 100_000, triangles: 50_000, segments: 0 };
    expect(copies.copySketch(...sketchOf(1, 100_000))).toEqual({ lines: undefined, lineColors: undefined });
    copies.copy(build(1), counts);
    // Room for two arrays only: the sketch's come first.
    spares.keep = 2;
    copies.prepare();
    expect(spares.prepared.slice(0, 3)).toEqual([2.4e6, 2.4e6, 1.2e6]);
    const sketch = copies.copySketch(...sketchOf(3, 100_000));
    expect(sketch.lines?.length).toBe(600_000);
    expect(sketch.lineColors?.every((v) => v === 3)).toBe(true);
    expect(spares.bytes).toBe(0);
    copies.copy(build(3), counts);
    // A build that is not sketched prepares its own arrays' sizes only.
    copies.copy(build(4), counts);
    copies.prepare();
    expect(spares.prepared).toEqual([1.2e6, 0.6e6, 0.8e6, 0.6e6, 0.3e6, 0, 0]);
  });
});
