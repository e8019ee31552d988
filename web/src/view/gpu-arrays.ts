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

/** Packs a mesh's normals and colours (see {@link GpuArrays}); the studio does it in its build worker. */
export function packForGpu(mesh: MeshBuffers): GpuArrays {
  const normals = new Int16Array(mesh.normals.length);
  for (let i = 0; i < normals.length; i++) normals[i] = Math.round(Math.max(-1, Math.min(1, mesh.normals[i])) * 32767);
  const colors = new Uint8Array(mesh.colors.length);
  for (let i = 0; i < colors.length; i++) colors[i] = Math.round(Math.max(0, Math.min(1, mesh.colors[i])) * 255);
  return { normals, colors };
}
