import { Box3, OrthographicCamera, PerspectiveCamera, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { framePicture, keepCamera, PICTURE_FILL } from './picture-frame';

/** The largest |x| and |y| of `box`'s corners in `camera`'s normalised device coordinates. */
function reach(camera: PerspectiveCamera | OrthographicCamera, box: Box3): { x: number; y: number } {
  let [x, y] = [0, 0];
  for (let c = 0; c < 8; c++) {
    const corner = new Vector3(c & 1 ? box.max.x : box.min.x, c & 2 ? box.max.y : box.min.y, c & 4 ? box.max.z : box.min.z).project(camera);
    [x, y] = [Math.max(x, Math.abs(corner.x)), Math.max(y, Math.abs(corner.y))];
  }
  return { x, y };
}

/** A bush twice as wide as tall, off the origin. */
const BUSH = new Box3(new Vector3(-3, 0, -2), new Vector3(5, 4, 3));

describe('framePicture', () => {
  it('fits a wide bush in a portrait picture, seen as the window saw it, with a margin', () => {
    // The window's camera: a landscape view close to the bush, turned a little.
    const camera = new PerspectiveCamera(40, 16 / 9, 0.1, 100);
    camera.position.set(2, 6, 6);
    camera.lookAt(1, 2, 0);
    const direction = camera.getWorldDirection(new Vector3());
    expect(reach(camera, BUSH).x, 'the window crops it').toBeGreaterThan(0.5);
    const putBack = keepCamera(camera);
    framePicture(camera, BUSH, 148 / 210); // A5 portrait
    const { x, y } = reach(camera, BUSH);
    expect(Math.max(x, y), 'every corner in, with a margin').toBeLessThanOrEqual(PICTURE_FILL + 1e-6);
    expect(Math.max(x, y), 'and the plant as large as the margin allows').toBeGreaterThan(PICTURE_FILL - 0.01);
    expect(camera.getWorldDirection(new Vector3()).angleTo(direction), 'looking the same way').toBeLessThan(1e-6);
    putBack();
    expect([camera.position.toArray(), camera.aspect]).toEqual([[2, 6, 6], 16 / 9]);
  });

  it('centres and fits a plant for an orthographic camera, zoomed or not', () => {
    const camera = new OrthographicCamera(-1, 1, 1, -1, 0.1, 100);
    camera.position.set(0, 0, 10);
    camera.zoom = 3;
    camera.lookAt(0, 0, 0);
    framePicture(camera, BUSH, 0.5);
    const { x, y } = reach(camera, BUSH);
    expect(Math.max(x, y)).toBeLessThanOrEqual(PICTURE_FILL + 1e-6);
    expect(Math.max(x, y)).toBeGreaterThan(PICTURE_FILL - 0.01);
    expect(camera.right / camera.top).toBeCloseTo(0.5);
  });
});
