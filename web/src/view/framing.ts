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
