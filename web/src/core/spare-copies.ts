// A studio-core build's biggest arrays copied into spare buffers (./spare-buffers.ts) rather than
// into new ones: what the build worker sends the view. Loaded with the studio core
// (./studio-core.ts), whose builds have the `…Into` methods, so the first load carries none of it.
import type { PlantBuild as StudioPlantBuild } from '../../../crate/pkg/meristem.js';
import { SpareBuffers } from './spare-buffers';

/** A studio-core build's methods that copy its big arrays into given ones. */
type CopiesInto = Pick<StudioPlantBuild, 'positionsInto' | 'indicesInto' | 'uvsInto' | 'packedNormalsInto' | 'packedColorsInto' | 'segmentEndsInto' | 'segmentColorsInto'>;

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

export class SpareCopies {
  /** The bytes of each array the last {@link copy} was given, taken or not: the next build's likely sizes. */
  private copied: number[] = [];

  constructor(private readonly spares = new SpareBuffers()) {}

  /**
   * The positions, indices, texture coordinates, packed normals and colours and the segments' ends
   * and colours of `result` (with `vertices`, `triangles` and `segments`) that fit a spare, copied
   * into it; `result` is a build of the studio core (else nothing is copied).
   */
  copy(result: object, { vertices, triangles, segments }: { vertices: number; triangles: number; segments: number }): SpareArrays {
    this.copied = [];
    if (!('positionsInto' in result)) return {};
    const core = result as unknown as CopiesInto;
    return {
      positions: this.into(Float32Array, 3 * vertices, (out) => core.positionsInto(out)),
      indices: this.into(Uint32Array, 3 * triangles, (out) => core.indicesInto(out)),
      uvs: this.into(Float32Array, 2 * vertices, (out) => core.uvsInto(out)),
      normals: this.into(Int16Array, 3 * vertices, (out) => core.packedNormalsInto(out)),
      colors: this.into(Uint8Array, 3 * vertices, (out) => core.packedColorsInto(out)),
      segmentEnds: this.into(Float32Array, 6 * segments, (out) => core.segmentEndsInto(out)),
      segmentColors: this.into(Float32Array, 6 * segments, (out) => core.segmentColorsInto(out)),
    };
  }

  /**
   * Spares of these sizes (bytes) for the next build, by default those of the arrays of the last
   * {@link copy} (an edit of a big plant seldom changes them): see {@link SpareBuffers.prepare}.
   */
  prepare(sizes: readonly number[] = this.copied): void {
    this.spares.prepare(sizes);
  }

  /** `length` values written by `write` into a spare of their size, or `undefined` when there is none. */
  private into<T>(Kind: TypedArrayKind<T>, length: number, write: (out: T) => void): T | undefined {
    const bytes = length * Kind.BYTES_PER_ELEMENT;
    this.copied.push(bytes);
    const spare = this.spares.take(bytes);
    if (!spare) return undefined;
    const out = new Kind(spare, 0, length);
    write(out);
    return out;
  }
}
