// A plant's geometry on the GPU, uploaded a slice at a time (issue 20: typing into a
// million-vertex tree). three.js uploads each BufferAttribute whole, with one `bufferData` call,
// inside the first frame that draws it: for ABOP 1.24d at n = 10 that is 57 MB in one task, which
// held the page's thread 100 to 250 ms on a software GPU (profiled while typing,
// `tests/browser/responsiveness.test.ts`). Here the arrays go into WebGL buffers of the view's own,
// taken from a {@link BufferPool} and filled by `upload(bytes)` calls, and the geometry three.js
// draws refers to those buffers (`GLBufferAttribute`). When to call `upload` is the view's business.
import { BufferGeometry, GLBufferAttribute, type BufferAttribute } from 'three';

type TypedArray = BufferAttribute['array'];

/** At most this many bytes of a replaced plant's buffers are kept for the next plants. */
const POOL_BYTES = 128 << 20;

/** A WebGL buffer and the bytes it holds room for. */
interface PooledBuffer {
  buffer: WebGLBuffer;
  bytes: number;
}

/** A buffer given back, and whether it holds indices. */
interface GivenBuffer extends PooledBuffer {
  index: boolean;
}

/**
 * The WebGL buffers of plants no longer drawn, kept for the next plants. Filling a new buffer costs
 * a software GPU far more than filling one filled before: ABOP 1.24d at n = 10's 50 MB took 40–90
 * ms of `bufferSubData` into new buffers and 11–18 ms into the ones of the plant before (SwiftShader,
 * both Chromium setups, 2026-11-27). An edit's plant is as big as the one before, so each of its
 * arrays finds a buffer of the plant it replaces. A buffer is used again for an array that fills
 * at least half of it, and an index buffer only for indices (WebGL 2 §5.1: a buffer's first
 * binding fixes whether it can hold indices).
 */
export class BufferPool {
  private readonly kept: GivenBuffer[] = [];

  constructor(readonly gl: WebGL2RenderingContext) {}

  /**
   * A buffer with room for `bytes`, for indices when `index`: the first kept one that will do (the
   * arrays of a plant of the same size take the buffers of their own kind in the order given) or a
   * new one.
   */
  take(bytes: number, index: boolean): PooledBuffer {
    const k = this.kept.findIndex((kept) => kept.index === index && kept.bytes >= bytes && kept.bytes <= 2 * bytes);
    if (k >= 0) return this.kept.splice(k, 1)[0];
    const gl = this.gl;
    const buffer = gl.createBuffer();
    if (index) {
      // Binding an index buffer changes the vertex array object bound: none is bound meanwhile,
      // and three.js's is bound again after.
      const vertexArray = gl.getParameter(gl.VERTEX_ARRAY_BINDING) as WebGLVertexArrayObject | null;
      gl.bindVertexArray(null);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, buffer);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, bytes, gl.STATIC_DRAW);
      gl.bindVertexArray(vertexArray);
    } else {
      // The copy target is bound by no three.js state: nothing of its drawing is disturbed.
      gl.bindBuffer(gl.COPY_WRITE_BUFFER, buffer);
      gl.bufferData(gl.COPY_WRITE_BUFFER, bytes, gl.STATIC_DRAW);
    }
    return { buffer, bytes };
  }

  /**
   * Keeps the buffers of a plant replaced (`index`: which hold indices) for later {@link take}s,
   * as many as fit in {@link POOL_BYTES}, and deletes those kept before: the next plant is most
   * likely the size of this one, and a view keeps no more than one plant's worth of spares.
   */
  give(buffers: readonly GivenBuffer[]): void {
    this.clear();
    let total = 0;
    for (const buffer of buffers) {
      total += buffer.bytes;
      if (total <= POOL_BYTES) this.kept.push({ buffer: buffer.buffer, bytes: buffer.bytes, index: buffer.index });
      else this.gl.deleteBuffer(buffer.buffer);
    }
  }

  /** Deletes every buffer kept; lets go of them only when the context was `lost` (they went with it). */
  clear(lost = false): void {
    for (const { buffer } of this.kept.splice(0)) if (!lost) this.gl.deleteBuffer(buffer);
  }
}

/** One array on its way to its WebGL buffer. */
interface Part {
  array: TypedArray;
  buffer: PooledBuffer;
  /** Elements uploaded so far (from the start). */
  uploaded: number;
}

/**
 * The drawable twin of a geometry made of plain BufferAttributes (`source`, which keeps the arrays
 * for raycasting and is never drawn): the same attributes, index, groups and bounds, in WebGL
 * buffers filled by {@link upload}. Draw {@link geometry} only once `upload` returned true.
 */
export class GpuGeometry {
  readonly geometry = new BufferGeometry();
  private readonly parts = new Map<string | null, Part>();
  private readonly queue: Part[] = [];

  private readonly gl: WebGL2RenderingContext;

  constructor(
    private readonly pool: BufferPool,
    source: BufferGeometry,
  ) {
    this.gl = pool.gl;
    for (const [name, attribute] of Object.entries(source.attributes)) this.add(name, attribute as BufferAttribute);
    if (source.index) this.add(null, source.index);
    for (const { start, count, materialIndex } of source.groups) this.geometry.addGroup(start, count, materialIndex);
    this.geometry.boundingBox = source.boundingBox;
    this.geometry.boundingSphere = source.boundingSphere;
  }

  /** `name` null: the index. */
  private add(name: string | null, attribute: BufferAttribute): void {
    const array = attribute.array;
    const buffer = this.pool.take(array.byteLength, name === null);
    const bytes = array.BYTES_PER_ELEMENT as 1 | 2 | 4;
    const drawn = new GLBufferAttribute(buffer.buffer, glType(this.gl, array), attribute.itemSize, bytes, attribute.count, attribute.normalized);
    // three.js draws an index held in a GLBufferAttribute (its count, type and buffer are all it reads).
    if (name === null) this.geometry.index = drawn as unknown as BufferAttribute;
    else this.geometry.setAttribute(name, drawn as unknown as BufferAttribute);
    const part = { array, buffer, uploaded: 0 };
    this.parts.set(name, part);
    this.queue.push(part);
  }

  /** The bytes not uploaded yet. */
  get remaining(): number {
    let bytes = 0;
    for (const { array, uploaded } of this.queue) bytes += (array.length - uploaded) * array.BYTES_PER_ELEMENT;
    return bytes;
  }

  /** Uploads the next `bytes` (at least one element; `Infinity`: all); true once everything is on the GPU. */
  upload(bytes: number): boolean {
    const gl = this.gl;
    let left = bytes;
    while (this.queue.length > 0 && left > 0) {
      const part = this.queue[0];
      const { array } = part;
      const count = Math.min(array.length - part.uploaded, Math.max(1, Math.floor(left / array.BYTES_PER_ELEMENT)));
      if (count > 0) {
        gl.bindBuffer(gl.COPY_WRITE_BUFFER, part.buffer.buffer);
        gl.bufferSubData(gl.COPY_WRITE_BUFFER, part.uploaded * array.BYTES_PER_ELEMENT, array, part.uploaded, count);
        part.uploaded += count;
        left -= count * array.BYTES_PER_ELEMENT;
      }
      if (part.uploaded === array.length) this.queue.shift();
    }
    return this.queue.length === 0;
  }

  /**
   * After elements `first` to `first + count` of attribute `name`'s array changed in place: uploads
   * those already on the GPU (the rest go with the next {@link upload}).
   */
  patch(name: string, first: number, count: number): void {
    const part = this.parts.get(name);
    if (!part) return;
    const end = Math.min(first + count, part.uploaded);
    if (end <= first) return;
    const gl = this.gl;
    gl.bindBuffer(gl.COPY_WRITE_BUFFER, part.buffer.buffer);
    gl.bufferSubData(gl.COPY_WRITE_BUFFER, first * part.array.BYTES_PER_ELEMENT, part.array, first, end - first);
  }

  /**
   * Gives the buffers back to the pool (not when the context was `lost`, and they with it), and
   * frees whatever three.js made to draw the geometry.
   */
  dispose(lost = false): void {
    // three.js deletes the buffers of the attributes a disposed geometry still has: not these.
    for (const name of Object.keys(this.geometry.attributes)) this.geometry.deleteAttribute(name);
    this.geometry.setIndex(null);
    this.geometry.dispose();
    if (!lost) this.pool.give([...this.parts].map(([name, { buffer }]) => ({ ...buffer, index: name === null })));
    this.parts.clear();
    this.queue.length = 0;
  }
}

/** The WebGL type of an array's elements. */
function glType(gl: WebGL2RenderingContext, array: TypedArray): number {
  if (array instanceof Float32Array) return gl.FLOAT;
  if (array instanceof Uint32Array) return gl.UNSIGNED_INT;
  if (array instanceof Uint16Array) return gl.UNSIGNED_SHORT;
  if (array instanceof Int16Array) return gl.SHORT;
  if (array instanceof Uint8Array) return gl.UNSIGNED_BYTE;
  if (array instanceof Int8Array) return gl.BYTE;
  if (array instanceof Int32Array) return gl.INT;
  throw new Error(`no WebGL type for ${array.constructor.name}`);
}
