// Where to put the camera so a box fills the view.
import { Box3, MathUtils, Sphere, Vector3 } from 'three';

/** A camera placement: eye position, point looked at, and clip planes that suit the distance. */
export interface CameraPose {
  position: Vector3;
  target: Vector3;
  near: number;
  far: number;
}

/**
 * The pose that shows all of `box` for a perspective camera with vertical field of view `fovDeg`
 * and aspect ratio `aspect`. It looks across the box's thinner horizontal axis (a planar plant is
 * seen face-on, never edge-on), a little from the side and from above. An empty or degenerate box
 * is treated as a unit box around its centre.
 */
export function framePose(box: Box3, fovDeg: number, aspect: number): CameraPose {
  const sphere = box.isEmpty() ? new Sphere(new Vector3(), 1) : box.getBoundingSphere(new Sphere());
  const radius = sphere.radius > 1e-6 ? sphere.radius : 1;
  const vertical = MathUtils.degToRad(fovDeg);
  const horizontal = 2 * Math.atan(Math.tan(vertical / 2) * aspect);
  // The bounding sphere just fits: a tall thin plant touches the top and bottom, never leaves them.
  const distance = radius / Math.sin(Math.min(vertical, horizontal) / 2);

  const size = box.isEmpty() ? new Vector3(1, 1, 1) : box.getSize(new Vector3());
  const across = size.z <= size.x ? new Vector3(0.25, 0.18, 1) : new Vector3(1, 0.18, -0.25);
  const position = sphere.center.clone().addScaledVector(across.normalize(), distance);
  return {
    position,
    target: sphere.center.clone(),
    near: distance / 100,
    far: distance * 100,
  };
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
