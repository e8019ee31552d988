// Picking a segment drawn as a wide line: the one whose line, as drawn (a width in pixels of the
// viewport), covers the pointer, nearest to the eye; else, within a few pixels of it, the nearest
// on screen (a thin line is hard to hit exactly: issue 48). What three.js's `LineSegments2`
// raycast does in screen space, over the plain array of segment ends the Lines mode draws from a
// texture.
import { Vector3, Vector4, type OrthographicCamera, type PerspectiveCamera, type Ray, type Vector2 } from 'three';

const pointer = new Vector3();
const start4 = new Vector4();
const end4 = new Vector4();
const start = new Vector3();
const end = new Vector3();
const onRay = new Vector3();

/** How far beside a line, in pixels, a pointer still picks it (beyond the line's own half width). */
export const PICK_SLACK = 4;

/**
 * The segment of `ends` (start xyz, end xyz each, in world coordinates) whose line `width` pixels
 * wide, in a viewport of `resolution` pixels seen by `camera`, the pointer's `ray` (from that
 * camera) meets or passes within `slack` pixels of, and the distance from the ray's origin to the
 * nearest point of the segment; of the lines that cover the pointer the nearest to the eye, else
 * the nearest on screen, or null. The part of a segment behind the near plane is cut off.
 */
export function pickSegment(ends: Float32Array, camera: PerspectiveCamera | OrthographicCamera, ray: Ray, width: number, resolution: Vector2, slack = PICK_SLACK): { segment: number; distance: number } | null {
  if (resolution.x === 0 || resolution.y === 0) return null; // not drawn yet
  const [halfX, halfY] = [resolution.x / 2, resolution.y / 2];
  const view = camera.matrixWorldInverse;
  const projection = camera.projectionMatrix;
  // The pointer on screen: a point one unit along the ray (its origin, the eye, would give w = 0).
  ray.at(1, pointer);
  const at = new Vector4(pointer.x, pointer.y, pointer.z, 1).applyMatrix4(view).applyMatrix4(projection);
  const [px, py] = [(at.x / at.w) * halfX, (at.y / at.w) * halfY];
  const near = -camera.near;
  let best: { segment: number; distance: number; gap: number } | null = null;
  for (let i = 0; i + 5 < ends.length; i += 6) {
    start4.set(ends[i], ends[i + 1], ends[i + 2], 1).applyMatrix4(view);
    end4.set(ends[i + 3], ends[i + 4], ends[i + 5], 1).applyMatrix4(view);
    if (start4.z > near && end4.z > near) continue; // behind the near plane
    if (start4.z > near) start4.lerp(end4, (start4.z - near) / (start4.z - end4.z));
    else if (end4.z > near) end4.lerp(start4, (end4.z - near) / (end4.z - start4.z));
    start4.applyMatrix4(projection).multiplyScalar(1 / start4.w);
    end4.applyMatrix4(projection).multiplyScalar(1 / end4.w);
    const [ax, ay, dx, dy] = [start4.x * halfX, start4.y * halfY, end4.x * halfX - start4.x * halfX, end4.y * halfY - start4.y * halfY];
    const length2 = dx * dx + dy * dy;
    const t = length2 > 0 ? Math.min(1, Math.max(0, ((px - ax) * dx + (py - ay) * dy) / length2)) : 0;
    const z = start4.z + (end4.z - start4.z) * t;
    // (Written to skip NaN too: a segment not grown yet at the growth time shown has NaN ends.)
    // Pixels between the pointer and the line's edge (0: the line covers it).
    const gap = Math.max(0, Math.hypot(ax + dx * t - px, ay + dy * t - py) - width / 2);
    if (!(z >= -1 && z <= 1 && gap <= slack) || (best && gap > best.gap)) continue;
    start.set(ends[i], ends[i + 1], ends[i + 2]);
    end.set(ends[i + 3], ends[i + 4], ends[i + 5]);
    ray.distanceSqToSegment(start, end, onRay);
    const distance = ray.origin.distanceTo(onRay);
    if (!best || gap < best.gap || distance < best.distance) best = { segment: i / 6, distance, gap };
  }
  return best && { segment: best.segment, distance: best.distance };
}
