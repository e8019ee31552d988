// Where a picture's camera stands: looking the way the view's camera looks (as the user turned it),
// moved so that the whole plant fills the picture's own aspect ratio with a margin. The view's
// window may be wider than the picture: the A5 portrait PNG of the wide bush 1.25, framed as the
// window was, lost both its sides. Pure arithmetic on the camera and the plant's box.
import { Vector3, type Box3, type OrthographicCamera, type PerspectiveCamera } from 'three';

/** Share of the picture's width and height the plant may fill: a margin of 3.7 % all round, as the view frames a flat plant (framing.ts `flatPose`). */
export const PICTURE_FILL = 1 / 1.08;

/**
 * Places `camera` (its direction kept) so that all of `box` is in a picture of aspect ratio
 * `aspect` (width / height), with a margin; sets the perspective camera's aspect, or the
 * orthographic one's frustum (zoom 1). An empty box leaves the camera as it is.
 */
export function framePicture(camera: PerspectiveCamera | OrthographicCamera, box: Box3, aspect: number): void {
  if (box.isEmpty()) return;
  camera.updateMatrixWorld();
  const right = new Vector3().setFromMatrixColumn(camera.matrixWorld, 0).normalize();
  const up = new Vector3().setFromMatrixColumn(camera.matrixWorld, 1).normalize();
  const back = new Vector3().setFromMatrixColumn(camera.matrixWorld, 2).normalize(); // towards the eye
  const centre = box.getCenter(new Vector3());
  const half = box.getSize(new Vector3()).multiplyScalar(0.5).max(new Vector3(1e-6, 1e-6, 1e-6));
  const corners = Array.from({ length: 8 }, (_, c) => new Vector3(c & 1 ? half.x : -half.x, c & 2 ? half.y : -half.y, c & 4 ? half.z : -half.z));
  const radius = half.length();
  if ('isPerspectiveCamera' in camera) {
    const tanV = Math.tan((camera.fov * Math.PI) / 360) * PICTURE_FILL;
    const tanH = tanV * aspect;
    // Each corner within the frustum at its depth (as framing.ts's framePose, along this camera's axes).
    let distance = 0;
    for (const c of corners) distance = Math.max(distance, c.dot(back) + Math.abs(c.dot(right)) / tanH, c.dot(back) + Math.abs(c.dot(up)) / tanV);
    camera.position.copy(centre).addScaledVector(back, distance);
    camera.aspect = aspect;
    camera.near = distance / 100;
    camera.far = (distance + radius) * 100;
  } else {
    // The corners' extent across the view, centred in the picture.
    const across = { minX: Infinity, maxX: -Infinity, minY: Infinity, maxY: -Infinity };
    for (const c of corners) {
      const [x, y] = [c.dot(right), c.dot(up)];
      [across.minX, across.maxX, across.minY, across.maxY] = [Math.min(across.minX, x), Math.max(across.maxX, x), Math.min(across.minY, y), Math.max(across.maxY, y)];
    }
    const halfHeight = Math.max(across.maxY - across.minY, (across.maxX - across.minX) / aspect) / 2 / PICTURE_FILL;
    camera.position
      .copy(centre)
      .addScaledVector(right, (across.minX + across.maxX) / 2)
      .addScaledVector(up, (across.minY + across.maxY) / 2)
      .addScaledVector(back, radius * 2);
    [camera.top, camera.bottom, camera.left, camera.right, camera.zoom] = [halfHeight, -halfHeight, -halfHeight * aspect, halfHeight * aspect, 1];
    camera.near = radius / 100;
    camera.far = radius * 4;
  }
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld();
}

/** What {@link framePicture} changes of `camera`, kept: the returned function puts it back. */
export function keepCamera(camera: PerspectiveCamera | OrthographicCamera): () => void {
  const position = camera.position.clone();
  const { near, far, zoom } = camera;
  const frustum = 'isPerspectiveCamera' in camera ? { aspect: camera.aspect } : { top: camera.top, bottom: camera.bottom, left: camera.left, right: camera.right };
  return () => {
    camera.position.copy(position);
    Object.assign(camera, { near, far, zoom }, frustum);
    camera.updateProjectionMatrix();
    camera.updateMatrixWorld();
  };
}
