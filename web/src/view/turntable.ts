// A turntable: the camera turned about the vertical (the world's Y axis, the plant's up) through
// the point it looks at, keeping its distance, height and tilt, as a plant on a turning stand is
// filmed. Part of the pictures' chunk (./snapshot.ts), which the first plant does without.
import { Quaternion, Vector3, type Camera } from 'three';

/** A camera on a turntable (see {@link turntable}). */
export interface Turntable {
  /** Puts the camera `angle` radians about the vertical through its target, from where it stood. */
  turn(angle: number): void;
  /** Puts the camera back where it stood. */
  stop(): void;
}

/**
 * `camera` on a turntable about `target` (where it looks), from where it stands now. (A flat
 * plant's orthographic camera turns too: it then shows the plant edge on at a quarter turn.)
 */
export function turntable(camera: Camera, target: Vector3): Turntable {
  const position = camera.position.clone();
  const quaternion = camera.quaternion.clone();
  const centre = target.clone();
  const up = new Vector3(0, 1, 0);
  const turned = new Quaternion();
  return {
    turn: (angle) => {
      turned.setFromAxisAngle(up, angle);
      camera.position.copy(position).sub(centre).applyQuaternion(turned).add(centre);
      camera.quaternion.copy(quaternion).premultiply(turned);
      camera.updateMatrixWorld();
    },
    stop: () => {
      camera.position.copy(position);
      camera.quaternion.copy(quaternion);
      camera.updateMatrixWorld();
    },
  };
}
