import { describe, expect, it } from 'vitest';
import type { OrthographicCamera, PerspectiveCamera} from 'three';
import { Box3, Vector3 } from 'three';
import { flatPose, framePose, orthographicCameraOn, perspectiveCameraOn } from './framing';

/** True when every corner of `box` projects inside the camera's view. */
function cornersVisible(box: Box3, camera: PerspectiveCamera): boolean {
  for (const x of [box.min.x, box.max.x])
    for (const y of [box.min.y, box.max.y])
      for (const z of [box.min.z, box.max.z]) {
        const p = new Vector3(x, y, z).project(camera);
        if (Math.abs(p.x) > 1 || Math.abs(p.y) > 1 || p.z < -1 || p.z > 1) return false;
      }
  return true;
}

function cameraAt(box: Box3, aspect: number): PerspectiveCamera {
  const camera = perspectiveCameraOn(box, aspect);
  camera.updateMatrixWorld();
  return camera;
}

describe('framePose', () => {
  it('keeps a tall planar plant entirely in view, wide or narrow', () => {
    const box = new Box3(new Vector3(-20, 0, -0.5), new Vector3(25, 90, 0.5));
    for (const aspect of [0.5, 1, 2]) expect(cornersVisible(box, cameraAt(box, aspect))).toBe(true);
  });

  it('fills a good part of the view (not a speck)', () => {
    const box = new Box3(new Vector3(-1, 0, -1), new Vector3(1, 2, 1));
    const camera = cameraAt(box, 1);
    const top = new Vector3(0, 2, 0).project(camera).y;
    const bottom = new Vector3(0, 0, 0).project(camera).y;
    expect(top - bottom).toBeGreaterThan(0.6);
  });

  it('fills the width with a wide, low plant (the box, not its bounding sphere, is fitted)', () => {
    const box = new Box3(new Vector3(-10, 0, -3), new Vector3(10, 4, 3));
    const camera = cameraAt(box, 1.6);
    expect(cornersVisible(box, camera)).toBe(true);
    let [left, right] = [Infinity, -Infinity];
    for (const x of [box.min.x, box.max.x])
      for (const y of [box.min.y, box.max.y])
        for (const z of [box.min.z, box.max.z]) {
          const p = new Vector3(x, y, z).project(camera);
          [left, right] = [Math.min(left, p.x), Math.max(right, p.x)];
        }
    expect((right - left) / 2, 'the box spans most of the view').toBeGreaterThan(0.85);
  });

  it('looks at a plant in the YZ plane face-on, not edge-on', () => {
    const box = new Box3(new Vector3(-0.1, 0, -5), new Vector3(0.1, 10, 5));
    const pose = framePose(box, 40, 1);
    const view = pose.position.clone().sub(pose.target).normalize();
    expect(Math.abs(view.x)).toBeGreaterThan(0.9);
  });

  it('survives an empty box', () => {
    const pose = framePose(new Box3(), 40, 1);
    expect(Number.isFinite(pose.position.length())).toBe(true);
    expect(pose.near).toBeGreaterThan(0);
  });
});

describe('flatPose', () => {
  function orthoAt(box: Box3, aspect: number): OrthographicCamera {
    const camera = orthographicCameraOn(box, aspect);
    camera.updateMatrixWorld();
    return camera;
  }

  it('shows a flat plant face-on and whole, tall or wide, in any view', () => {
    const tall = new Box3(new Vector3(-70, 0, -0.4), new Vector3(70, 249, 0.4));
    const wide = new Box3(new Vector3(-20, -2, -0.2), new Vector3(85, 10, 0.2));
    for (const box of [tall, wide])
      for (const aspect of [0.5, 1, 2]) {
        const camera = orthoAt(box, aspect);
        for (const x of [box.min.x, box.max.x])
          for (const y of [box.min.y, box.max.y])
            for (const z of [box.min.z, box.max.z]) {
              const p = new Vector3(x, y, z).project(camera);
              expect(Math.max(Math.abs(p.x), Math.abs(p.y), Math.abs(p.z))).toBeLessThanOrEqual(1);
            }
        const pose = flatPose(box, aspect);
        expect(pose.position.clone().sub(pose.target).normalize().z).toBeCloseTo(1);
      }
  });

  it('fills the view along the limiting side', () => {
    const box = new Box3(new Vector3(0, 0, 0), new Vector3(1, 2, 0));
    const top = new Vector3(0.5, 2, 0).project(orthoAt(box, 1)).y;
    expect(top).toBeGreaterThan(0.9);
  });
});
