// A studio-core build's biggest arrays copied into spare buffers (./spare-buffers.ts) rather than
// into new ones: what the build worker sends the view. Loaded with the studio core
// (./studio-core.ts), whose builds have the `…Into` methods, so the first load carries none of it.
import type { PlantBuild as StudioPlantBuild } from '../../../crate/pkg/meristem.js';
import { SpareBuffers } from './spare-buffers';

/** A studio-core build's methods that copy its big arrays into given ones. */
type CopiesInto = Pick<
  StudioPlantBuild,
  'positionsInto' | 'indicesInto' | 'uvsInto' | 'packedNormalsInto' | 'packedColorsInto' | 'segmentEndsInto' | 'segmentColorsInto'
>;

type TypedArrayKind<T> = { new (buffer: ArrayBuffer, offset: number, length: number): T; BYTES_PER_ELEMENT: number };

/** The arrays of one build that went into spares (the others are not there: copy them as usual). */
export interface SpareArrays {
  positions?: Float32Array;
  indices?: Uint32Array;
  uvs?: Float32Array;
  normals?: Int16Array;
  colors?: Uint8Array;
  segmentEnds?: Float32Array;
  segmentColors?: Float32Array;
}

/** A sketch's arrays that went into spares (as {@link SpareArrays}). */
export interface SpareSketch {
  lines?: Float32Array;
  lineColors?: Float32Array;
}

export class SpareCopies {
  /**
   * The bytes of each array the last build gave {@link copySketch} and {@link copy}, taken or not:
   * the next build's likely sizes.
   */
  private copied: number[] = [];
  /** Those of the sketch of the build under way, until its {@link copy}. */
  private sketched: number[] = [];

  constructor(private readonly spares = new SpareBuffers()) {}

  /**
   * The positions, indices, texture coordinates, packed normals and colours and the segments' ends
   * and colours of `result` (with `vertices`, `triangles` and `segments`) that fit a spare, copied
   * into it; `result` is a build of the studio core (else nothing is copied).
   */
  copy(result: object, { vertices, triangles, segments }: { vertices: number; triangles: number; segments: number }): SpareArrays {
    // The sketch's sizes first: when the spares cannot hold everything, the first frame's come first.
    const sizes = (this.copied = this.sketched);
    this.sketched = [];
    if (!('positionsInto' in result)) return {};
    const core = result as unknown as CopiesInto;
    return {
      positions: this.into(sizes, Float32Array, 3 * vertices, (out) => core.positionsInto(out)),
      indices: this.into(sizes, Uint32Array, 3 * triangles, (out) => core.indicesInto(out)),
      uvs: this.into(sizes, Float32Array, 2 * vertices, (out) => core.uvsInto(out)),
      normals: this.into(sizes, Int16Array, 3 * vertices, (out) => core.packedNormalsInto(out)),
      colors: this.into(sizes, Uint8Array, 3 * vertices, (out) => core.packedColorsInto(out)),
      segmentEnds: this.into(sizes, Float32Array, 6 * segments, (out) => core.segmentEndsInto(out)),
      segmentColors: this.into(sizes, Float32Array, 6 * segments, (out) => core.segmentColorsInto(out)),
    };
  }

  /**
   * The lines of a sketch and their colours (views of the core's memory, as the core's
   * `sketchFirst.show` gives them) that fit a spare, copied into it: the worker sends them to the
   * page before the build's {@link copy}, which then prepares their sizes too.
   */
  copySketch(lines: Float32Array, lineColors: Float32Array): SpareSketch {
    const sizes = (this.sketched = []);
    return {
      lines: this.into(sizes, Float32Array, lines.length, (out) => out.set(lines)),
      lineColors: this.into(sizes, Float32Array, lineColors.length, (out) => out.set(lineColors)),
    };
  }

  /**
   * Spares of these sizes (bytes) for the next build, by default those of the arrays of the last
   * build's {@link copySketch} and {@link copy} (an edit of a big plant seldom changes them): see
   * {@link SpareBuffers.prepare}.
   */
  prepare(sizes: readonly number[] = this.copied): void {
    this.spares.prepare(sizes);
  }

  /**
   * `length` values written by `write` into a spare of their size, or `undefined` when there is
   * none; their bytes added to `sizes`.
   */
  private into<T>(sizes: number[], Kind: TypedArrayKind<T>, length: number, write: (out: T) => void): T | undefined {
    const bytes = length * Kind.BYTES_PER_ELEMENT;
    sizes.push(bytes);
    const spare = this.spares.take(bytes);
    if (!spare) return undefined;
    const out = new Kind(spare, 0, length);
    write(out);
    return out;
  }
}
