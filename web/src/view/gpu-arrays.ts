// The mesh arrays the GPU gets, packed smaller than the core's floats. No three.js here: the build
// worker packs them, and it does not load three.js.
import type { MeshBuffers } from '../core';

/**
 * A mesh's normals and colours packed for the GPU: normals as 16-bit and colours as 8-bit
 * normalized integers (6 and 3 bytes a vertex instead of 12 and 12), so a million-vertex plant
 * sends 38 MB to the GPU instead of 52 MB. Normals lose nothing visible (1/32767), colours are
 * the palette's flat linear values to 1/255.
 */
export interface GpuArrays {
  normals: Int16Array;
  colors: Uint8Array;
}

/**
 * Packs a mesh's normals and colours (see {@link GpuArrays}); the studio does it in its build worker.
 * Each value is `Math.round` of the value clamped to -1..1 (normals) or 0..1 (colours) and scaled,
 * written as the clamp of the scaled value and `Math.floor(y + 0.5)`: the same integers (the scaled
 * `f32` is exact in a double, so `y + 0.5` does not round), without the two calls a value. A
 * vertex's colour is mostly the one before (a tube's ring has one), so colours are converted once
 * per run. Together about twice as fast on a million-vertex plant (issue 20).
 */
export function packForGpu(mesh: MeshBuffers): GpuArrays {
  const source = mesh.normals;
  const normals = new Int16Array(source.length);
  for (let i = 0; i < source.length; i++) {
    const y = source[i] * 32767;
    // NaN falls through to Math.floor(NaN), stored as 0, as Math.round's NaN was.
    normals[i] = y >= 32767 ? 32767 : y <= -32767 ? -32767 : Math.floor(y + 0.5);
  }
  const floats = mesh.colors;
  const colors = new Uint8Array(floats.length);
  let r = NaN;
  let g = NaN;
  let b = NaN;
  let pr = 0;
  let pg = 0;
  let pb = 0;
  for (let i = 0; i + 2 < floats.length; i += 3) {
    const x = floats[i];
    const y = floats[i + 1];
    const z = floats[i + 2];
    if (x !== r || y !== g || z !== b) {
      r = x;
      g = y;
      b = z;
      pr = colorByte(x);
      pg = colorByte(y);
      pb = colorByte(z);
    }
    colors[i] = pr;
    colors[i + 1] = pg;
    colors[i + 2] = pb;
  }
  return { normals, colors };
}

/** A colour component (linear, 0..1, clamped) as a byte: `Math.round(clamped × 255)`. */
function colorByte(value: number): number {
  const y = value * 255;
  return y >= 255 ? 255 : y > 0 ? Math.floor(y + 0.5) : 0;
}
