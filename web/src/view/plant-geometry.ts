// The plant's triangle mesh as a three.js BufferGeometry.
import { BufferAttribute, BufferGeometry } from 'three';
import type { MeshBuffers } from '../core';

/**
 * Wraps the core's mesh arrays (no copy: they are JavaScript-owned already) in a BufferGeometry
 * with `position`, `normal`, `color` (linear RGB) attributes and an index, bounds computed.
 */
export function plantGeometry(mesh: MeshBuffers): BufferGeometry {
  const geometry = new BufferGeometry();
  if (mesh.indices.length === 0 && mesh.lines.length > 0) return lineGeometry(mesh);
  geometry.setAttribute('position', new BufferAttribute(mesh.positions, 3));
  geometry.setAttribute('normal', new BufferAttribute(mesh.normals, 3));
  geometry.setAttribute('color', new BufferAttribute(mesh.colors, 3));
  geometry.setIndex(new BufferAttribute(mesh.indices, 1));
  geometry.computeBoundingBox();
  geometry.computeBoundingSphere();
  return geometry;
}

/**
 * The fallback for models too large to mesh: the core's line ends and their colours, for a
 * `LineSegments` object.
 */
export function lineGeometry(mesh: MeshBuffers): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(mesh.lines, 3));
  geometry.setAttribute('color', new BufferAttribute(mesh.lineColors, 3));
  geometry.computeBoundingBox();
  geometry.computeBoundingSphere();
  return geometry;
}
