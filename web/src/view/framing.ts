// Where to put the camera so a box fills the view.
import type { Box3} from 'three';
import { MathUtils, OrthographicCamera, PerspectiveCamera, Vector3 } from 'three';

/** A camera placement: eye position, point looked at, and clip planes that suit the distance. */
export interface CameraPose {
  position: Vector3;
  target: Vector3;
  near: number;
  far: number;
}

/** Share of the view the plant may fill: a margin of a few per cent all round. */
const FILL = 0.94;

/**
 * The pose that shows all of `box` for a perspective camera with vertical field of view `fovDeg`
 * and aspect ratio `aspect`. It looks across the box's thinner horizontal axis (a planar plant is
 * seen face-on, never edge-on), a little from the side and from above, from as near as keeps every
 * corner of the box in view (a wide, flat plant fills the width; a tall one the height). An empty
 * or degenerate box is treated as a unit box around its centre.
 */
export function framePose(box: Box3, fovDeg: number, aspect: number): CameraPose {
  const empty = box.isEmpty();
  const center = empty ? new Vector3() : box.getCenter(new Vector3());
  const size = empty ? new Vector3(1, 1, 1) : box.getSize(new Vector3());
  const across = (size.z <= size.x ? new Vector3(0.25, 0.18, 1) : new Vector3(1, 0.18, -0.25)).normalize();
  // The camera's own axes: `across` points from the target to the eye.
  const right = new Vector3(0, 1, 0).cross(across).normalize();
  const up = across.clone().cross(right);
  const tanV = Math.tan(MathUtils.degToRad(fovDeg) / 2) * FILL;
  const tanH = tanV * aspect;
  const half = size.clone().multiplyScalar(0.5).max(new Vector3(1e-6, 1e-6, 1e-6));
  if (half.length() < 1e-5) half.set(0.5, 0.5, 0.5);
  // Each corner in view: its sideways and upward offsets within the frustum at its depth.
  let distance = 0;
  const corner = new Vector3();
  for (let c = 0; c < 8; c++) {
    corner.set(c & 1 ? half.x : -half.x, c & 2 ? half.y : -half.y, c & 4 ? half.z : -half.z);
    const towards = corner.dot(across);
    distance = Math.max(distance, towards + Math.abs(corner.dot(right)) / tanH, towards + Math.abs(corner.dot(up)) / tanV);
  }
  const position = center.clone().addScaledVector(across, distance);
  return { position, target: center, near: distance / 100, far: (distance + half.length()) * 100 };
}

/** An orthographic camera placement looking down −Z at the XY plane (a flat plant, face-on). */
export interface FlatPose {
  /** Eye position: in front of the box on +Z. */
  position: Vector3;
  target: Vector3;
  /** Half the visible height in world units (the width follows from the aspect). */
  halfHeight: number;
  near: number;
  far: number;
}

/**
 * The orthographic pose that shows all of `box`'s XY extent, with a small margin, in a view of
 * aspect ratio `aspect` (width / height). An empty or degenerate box is treated as a unit square.
 */
export function flatPose(box: Box3, aspect: number): FlatPose {
  const empty = box.isEmpty();
  const center = empty ? new Vector3() : box.getCenter(new Vector3());
  const size = empty ? new Vector3(1, 1, 1) : box.getSize(new Vector3());
  const width = Math.max(size.x, 1e-6);
  const height = Math.max(size.y, 1e-6);
  const halfHeight = (Math.max(height, width / Math.max(aspect, 1e-6)) / 2) * 1.08;
  const depth = Math.max(size.z, width, height);
  return {
    position: new Vector3(center.x, center.y, center.z + depth * 2),
    target: center,
    halfHeight,
    near: depth * 0.01,
    far: depth * 4,
  };
}

/**
 * A perspective camera (40° vertical field of view) of aspect ratio `aspect` placed by
 * {@link framePose} to show all of `box`, its projection up to date.
 */
export function perspectiveCameraOn(box: Box3, aspect: number): PerspectiveCamera {
  const camera = new PerspectiveCamera(40, aspect);
  const pose = framePose(box, camera.fov, aspect);
  camera.position.copy(pose.position);
  camera.near = pose.near;
  camera.far = pose.far;
  camera.lookAt(pose.target);
  camera.updateProjectionMatrix();
  return camera;
}

/**
 * An orthographic camera of aspect ratio `aspect` placed by {@link flatPose} to show `box` face-on,
 * its projection up to date.
 */
export function orthographicCameraOn(box: Box3, aspect: number): OrthographicCamera {
  const pose = flatPose(box, aspect);
  const h = pose.halfHeight;
  const camera = new OrthographicCamera(-h * aspect, h * aspect, h, -h, pose.near, pose.far);
  camera.position.copy(pose.position);
  camera.lookAt(pose.target);
  camera.updateProjectionMatrix();
  return camera;
}
