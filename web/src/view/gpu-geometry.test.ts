import { BufferAttribute, BufferGeometry } from 'three';
import { describe, expect, it } from 'vitest';
import { BufferPool, GpuGeometry } from './gpu-geometry';

/** A WebGL 2 context that keeps each buffer's bytes, and which buffer was first bound as an index. */
function fakeGl() {
  const contents = new Map<object, Uint8Array>();
  const indexBuffers = new Set<object>();
  const bound = new Map<number, object | null>();
  let vertexArray: object | null = { name: 'three.js vertex array' };
  const gl = {
    ARRAY_BUFFER: 34962,
    ELEMENT_ARRAY_BUFFER: 34963,
    COPY_WRITE_BUFFER: 36663,
    STATIC_DRAW: 35044,
    VERTEX_ARRAY_BINDING: 34229,
    FLOAT: 5126,
    UNSIGNED_INT: 5125,
    UNSIGNED_SHORT: 5123,
    SHORT: 5122,
    UNSIGNED_BYTE: 5121,
    BYTE: 5120,
    INT: 5124,
    uploads: [] as number[],
    made: 0,
    createBuffer: () => (gl.made++, {}),
    boundTo: (target: number) => bound.get(target),
    deleteBuffer: (buffer: object) => contents.delete(buffer),
    getParameter: () => vertexArray,
    bindVertexArray: (array: object | null) => (vertexArray = array),
    bindBuffer(target: number, buffer: object) {
      if (target === gl.ELEMENT_ARRAY_BUFFER) {
        if (vertexArray !== null) throw new Error('an index buffer bound into a vertex array object');
        indexBuffers.add(buffer);
      }
      bound.set(target, buffer);
    },
    bufferData(target: number, size: number) {
      contents.set(bound.get(target)!, new Uint8Array(size));
    },
    bufferSubData(target: number, offset: number, data: ArrayBufferView & { BYTES_PER_ELEMENT: number }, first: number, count: number) {
      const bytes = new Uint8Array(data.buffer, data.byteOffset + first * data.BYTES_PER_ELEMENT, count * data.BYTES_PER_ELEMENT);
      contents.get(bound.get(target)!)!.set(bytes, offset);
      gl.uploads.push(bytes.length);
    },
  };
  return { gl, contents, indexBuffers, vertexArray: () => vertexArray };
}

function plant(): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(Float32Array.from({ length: 300 }, (_, i) => i), 3));
  geometry.setAttribute('color', new BufferAttribute(Uint8Array.from({ length: 300 }, (_, i) => i % 256), 3, true));
  geometry.setIndex(new BufferAttribute(Uint32Array.from({ length: 600 }, (_, i) => i % 100), 1));
  geometry.addGroup(0, 300, 0);
  geometry.addGroup(300, 300, 1);
  return geometry;
}

describe('GpuGeometry', () => {
  it('uploads the arrays in slices of at most the bytes asked for, into buffers equal to them', () => {
    const { gl, contents, indexBuffers, vertexArray } = fakeGl();
    const source = plant();
    const before = vertexArray();
    const onGpu = new GpuGeometry(new BufferPool(gl as unknown as WebGL2RenderingContext), source);
    expect(vertexArray(), "three.js's vertex array is bound again").toBe(before);
    expect(onGpu.remaining).toBe(1200 + 300 + 2400);
    let calls = 0;
    while (!onGpu.upload(500)) calls++;
    expect(calls).toBeGreaterThan(5);
    expect(Math.max(...gl.uploads)).toBeLessThanOrEqual(500);
    expect(onGpu.remaining).toBe(0);
    const drawn = onGpu.geometry;
    for (const name of ['position', 'color']) {
      const buffer = (drawn.getAttribute(name) as unknown as { buffer: object }).buffer;
      const array = source.getAttribute(name).array;
      expect(contents.get(buffer)).toEqual(new Uint8Array(array.buffer));
    }
    const index = drawn.index as unknown as { buffer: object; count: number; type: number };
    expect(contents.get(index.buffer)).toEqual(new Uint8Array(source.index!.array.buffer));
    expect(indexBuffers.has(index.buffer), 'the index buffer was first bound as one').toBe(true);
    expect([index.count, index.type]).toEqual([600, gl.UNSIGNED_INT]);
    expect(drawn.getAttribute('color').normalized).toBe(true);
    expect(drawn.groups).toEqual(source.groups);
  });

  it('patches only what is on the GPU already; the rest goes up with the next slices', () => {
    const { gl, contents } = fakeGl();
    const source = plant();
    const onGpu = new GpuGeometry(new BufferPool(gl as unknown as WebGL2RenderingContext), source);
    onGpu.upload(400); // the first 100 floats of the positions
    const positions = source.getAttribute('position').array as Float32Array;
    positions.fill(-1, 90, 120); // 10 on the GPU, 20 not yet
    gl.uploads.length = 0;
    onGpu.patch('position', 90, 30);
    expect(gl.uploads).toEqual([40]);
    while (!onGpu.upload(1000));
    const buffer = (onGpu.geometry.getAttribute('position') as unknown as { buffer: object }).buffer;
    expect(new Float32Array(contents.get(buffer)!.buffer)).toEqual(positions);
  });

  it('gives its buffers back to the pool, which the next plant of the same size fills again', () => {
    const { gl, contents, indexBuffers } = fakeGl();
    const pool = new BufferPool(gl as unknown as WebGL2RenderingContext);
    const first = new GpuGeometry(pool, plant());
    while (!first.upload(Infinity));
    const buffers = new Set(contents.keys());
    first.dispose();
    expect(contents.size, 'kept, not deleted').toBe(3);
    const made = gl.made;
    const next = plant();
    (next.getAttribute('position').array as Float32Array).fill(7);
    const second = new GpuGeometry(pool, next);
    while (!second.upload(Infinity));
    expect(gl.made, 'no buffer made').toBe(made);
    const position = (second.geometry.getAttribute('position') as unknown as { buffer: object }).buffer;
    expect(buffers.has(position)).toBe(true);
    expect(new Float32Array(contents.get(position)!.buffer)).toEqual(next.getAttribute('position').array);
    const index = (second.geometry.index as unknown as { buffer: object }).buffer;
    expect(indexBuffers.has(index), 'the indices went into the index buffer').toBe(true);
    pool.clear();
    expect(contents.size, 'the second plant\'s buffers are its own').toBe(3);
    second.dispose();
    pool.clear();
    expect(contents.size).toBe(0);
  });

  it('takes a kept buffer only for an array of its kind that fills half of it or more', () => {
    const { gl, indexBuffers } = fakeGl();
    const pool = new BufferPool(gl as unknown as WebGL2RenderingContext);
    const index = pool.take(1000, true);
    const vertices = pool.take(1000, false);
    pool.give([{ ...index, index: true }, { ...vertices, index: false }]);
    expect(pool.take(400, false).buffer, 'too small an array: a new buffer').not.toBe(vertices.buffer);
    expect(pool.take(600, false).buffer).toBe(vertices.buffer);
    const forIndices = pool.take(600, true);
    expect(forIndices.buffer).toBe(index.buffer);
    expect(indexBuffers.has(forIndices.buffer)).toBe(true);
    expect(pool.take(1001, true).buffer, 'too big: a new one').not.toBe(index.buffer);
  });

  it('keeps the buffers of the last plant given back only, at most 128 MB of them', () => {
    const { gl, contents } = fakeGl();
    // Buffers of no bytes: their sizes, which the pool counts, are the test's business, not their contents.
    gl.bufferData = (target: number) => void contents.set(gl.boundTo(target)!, new Uint8Array(0));
    const pool = new BufferPool(gl as unknown as WebGL2RenderingContext);
    const mb = 1 << 20;
    const [a, b, c, d] = [pool.take(60 * mb, false), pool.take(60 * mb, false), pool.take(20 * mb, true), pool.take(1 * mb, false)];
    pool.give([{ ...d, index: false }]);
    pool.give([a, b, c].map((buffer, k) => ({ ...buffer, index: k === 2 })));
    expect(contents.has(d.buffer), 'the plant given back before: deleted').toBe(false);
    expect([a, b, c].map((buffer) => contents.has(buffer.buffer)), 'beyond 128 MB: deleted').toEqual([true, true, false]);
    expect(pool.take(50 * mb, false).buffer).toBe(a.buffer);
  });
});
