// The plant's triangle mesh as three.js BufferGeometries.
import { Box3, BufferAttribute, BufferGeometry, Sphere, Vector3 } from 'three';
import type { Bounds, GpuArrays, MeshBuffers } from '../core';
import { addGrowthAttributes } from './growth-arrays';

/**
 * Wraps the core's mesh arrays (no copy: they are JavaScript-owned already) in a BufferGeometry
 * with `position`, `normal`, `color` (linear RGB) attributes and an index, bounds computed (the
 * sphere from the box: one pass over a million vertices instead of three), and the growth
 * attributes when the mesh has its growth arrays (./growth-arrays.ts). With `gpu`, its packed
 * normals and colours are used instead of the mesh's floats. `bounds`, when given, is a box around
 * every position (a build's `stats.bounds`, which the core computed), and no pass is made.
 */
export function plantGeometry(mesh: MeshBuffers, gpu?: GpuArrays, bounds?: Bounds): BufferGeometry {
  const geometry = new BufferGeometry();
  if (mesh.indices.length === 0 && mesh.lines.length > 0) return lineGeometry(mesh);
  // A build worker's mesh has no float normals and colours: they come packed, as `gpu`.
  if (!gpu && mesh.normals.length !== mesh.positions.length) throw new Error('plantGeometry: a mesh without its normals needs its packed GpuArrays');
  geometry.setAttribute('position', new BufferAttribute(mesh.positions, 3));
  geometry.setAttribute('normal', gpu ? new BufferAttribute(gpu.normals, 3, true) : new BufferAttribute(mesh.normals, 3));
  geometry.setAttribute('color', gpu ? new BufferAttribute(gpu.colors, 3, true) : new BufferAttribute(mesh.colors, 3));
  geometry.setIndex(new BufferAttribute(mesh.indices, 1));
  if (mesh.uvs.length === (mesh.positions.length / 3) * 2) geometry.setAttribute('uv', new BufferAttribute(mesh.uvs, 2));
  addGrowthAttributes(geometry, mesh.positions.length / 3, mesh);
  addMaterialGroups(geometry, mesh);
  setBox(geometry, bounds && mesh.positions.length > 0 ? new Box3(new Vector3(...bounds[0]), new Vector3(...bounds[1])) : pointsBox(mesh.positions));
  return geometry;
}

/**
 * One draw group per material range (`materialRanges`: first triangle, kind), its material index
 * the kind: 0 bark, 1 leaf, 2 plain, the order of the view's material arrays.
 */
export function addMaterialGroups(geometry: BufferGeometry, mesh: MeshBuffers): void {
  const ranges = mesh.materialRanges;
  const triangles = mesh.indices.length / 3;
  for (let k = 0; k + 1 < ranges.length; k += 2) {
    const first = ranges[k];
    const end = k + 2 < ranges.length ? ranges[k + 2] : triangles;
    if (end > first) geometry.addGroup(3 * first, 3 * (end - first), Math.min(ranges[k + 1], 2));
  }
}

/** Sets a geometry's bounding box and its bounding sphere around that box. */
export function setBox(geometry: BufferGeometry, box: Box3): void {
  geometry.boundingBox = box;
  geometry.boundingSphere = box.getBoundingSphere(new Sphere());
}

/**
 * The fallback for models too large to mesh (and a sketch's segments): the core's line ends and
 * their colours, for a `LineSegments` object.
 */
export function lineGeometry(mesh: Pick<MeshBuffers, 'lines' | 'lineColors' | 'growthOrigins' | 'growthTimes'>): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(mesh.lines, 3));
  geometry.setAttribute('color', new BufferAttribute(mesh.lineColors, 3));
  addGrowthAttributes(geometry, mesh.lines.length / 3, mesh); // (one entry per line end then)
  setBox(geometry, pointsBox(mesh.lines));
  return geometry;
}

/** The box around 3-float points (a plain loop: fast on a million vertices). Empty for no points. */
export function pointsBox(points: Float32Array): Box3 {
  const box = new Box3();
  if (points.length < 3) return box;
  let [minX, minY, minZ] = [Infinity, Infinity, Infinity];
  let [maxX, maxY, maxZ] = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i + 2 < points.length; i += 3) {
    const x = points[i];
    const y = points[i + 1];
    const z = points[i + 2];
    if (x < minX) minX = x;
    if (x > maxX) maxX = x;
    if (y < minY) minY = y;
    if (y > maxY) maxY = y;
    if (z < minZ) minZ = z;
    if (z > maxZ) maxZ = z;
  }
  return box.set(new Vector3(minX, minY, minZ), new Vector3(maxX, maxY, maxZ));
}
