import { describe, expect, it } from 'vitest';
import { OrthographicCamera, PerspectiveCamera, Raycaster, Vector2 } from 'three';
import { pickSegment } from './segment-pick';

/** A camera on the z axis at `z`, looking at the origin, and a raycaster through the pixel (x, y) of a 200 × 100 viewport. */
function aimed(camera: PerspectiveCamera | OrthographicCamera, x: number, y: number): Raycaster {
  camera.position.set(0, 0, 10);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  camera.updateProjectionMatrix();
  const raycaster = new Raycaster();
  raycaster.setFromCamera(new Vector2((x / 200) * 2 - 1, 1 - (y / 100) * 2), camera);
  return raycaster;
}

const VIEWPORT = new Vector2(200, 100);

describe('pickSegment', () => {
  // Orthographic: 20 × 10 world units on 200 × 100 pixels, 10 pixels a unit.
  const ortho = () => new OrthographicCamera(-10, 10, 5, -5, 0.1, 100);

  it('finds the segment under the pointer within half the line width, in pixels', () => {
    // Segment 0: along x at y = 0; segment 1: along y at x = 5 (pixel column 150).
    const ends = new Float32Array([-8, 0, 0, 8, 0, 0, 5, -4, 0, 5, 4, 0]);
    const on = (x: number, y: number, width = 4) => {
      const camera = ortho();
      return pickSegment(ends, camera, aimed(camera, x, y).ray, width, VIEWPORT, 0)?.segment ?? null;
    };
    expect(on(60, 50)).toBe(0);
    expect(on(60, 51.5)).toBe(0); // 1.5 px off a 4 px line
    expect(on(60, 52.5)).toBeNull(); // 2.5 px off
    expect(on(60, 52.5, 6)).toBe(0); // within a 6 px line
    expect(on(151, 30)).toBe(1);
    expect(on(195, 50)).toBeNull(); // beyond the segment's end (x = 8: pixel 180)
  });

  it('picks a thin line from a few pixels beside it, and the nearer of two lines on screen (issue 48)', () => {
    // Segment 0 along x at y = 0 (pixel row 50); segment 1 along x at y = -0.8 (row 58).
    const ends = new Float32Array([-8, 0, 0, 8, 0, 0, -8, -0.8, 0, 8, -0.8, 0]);
    const at = (x: number, y: number, width: number) => {
      const camera = ortho();
      return pickSegment(ends, camera, aimed(camera, x, y).ray, width, VIEWPORT)?.segment ?? null;
    };
    expect(at(60, 47, 1)).toBe(0); // 3 px above a 1 px line
    expect(at(60, 53, 1)).toBe(0); // 3 px below it, nearer it than the other
    expect(at(60, 55, 1)).toBe(1); // 3 px above the other
    expect(at(60, 61, 2)).toBe(1); // 3 px below a 2 px line
    expect(at(60, 40, 1)).toBeNull(); // 10 px away: nothing
    expect(at(60, 44.4, 2)).toBeNull(); // 4.6 px beyond a 2 px line's edge
    expect(at(60, 45.2, 2)).toBe(0); // 3.8 px beyond it
  });

  it('prefers a line that covers the pointer, then the nearest to the eye, over one beside it', () => {
    const camera = ortho();
    // Segment 0 at z = 5 (near the eye), 3 px above the pointer; segment 1 at z = -5 under it.
    const ends = new Float32Array([-8, 0.3, 5, 8, 0.3, 5, -8, 0, -5, 8, 0, -5]);
    expect(pickSegment(ends, camera, aimed(camera, 60, 50).ray, 2, VIEWPORT)?.segment).toBe(1);
  });

  it('never picks a segment with NaN ends (not grown yet at the growth time shown)', () => {
    const ends = new Float32Array([NaN, NaN, NaN, NaN, NaN, NaN, -8, 0, 0, 8, 0, 0]);
    for (const camera of [ortho(), new PerspectiveCamera(60, 2, 0.1, 100)]) {
      expect(pickSegment(ends, camera, aimed(camera, 100, 50).ray, 4, VIEWPORT)?.segment).toBe(1);
      expect(pickSegment(ends.slice(0, 6), camera, aimed(camera, 100, 50).ray, 4, VIEWPORT)).toBeNull();
    }
  });

  it('takes the nearest to the eye where lines cross, and gives its distance', () => {
    const camera = ortho();
    const raycaster = aimed(camera, 100, 50);
    // Both through the screen's centre: segment 0 at z = -2, segment 1 at z = 3 (nearer the eye at z = 10).
    const ends = new Float32Array([-5, 0, -2, 5, 0, -2, 0, -3, 3, 0, 3, 3]);
    const hit = pickSegment(ends, camera, raycaster.ray, 2, VIEWPORT);
    expect(hit?.segment).toBe(1);
    expect(hit?.distance).toBeCloseTo(7, 5);
  });

  it('cuts off what lies behind the camera, and sees nothing before a frame gave it a viewport', () => {
    const camera = new PerspectiveCamera(60, 2, 0.1, 100);
    const raycaster = aimed(camera, 100, 50);
    // A segment from behind the camera (z = 20) to in front of it, through the origin.
    const through = new Float32Array([-1, 0, 20, 1, 0, -20]);
    const hit = pickSegment(through, camera, raycaster.ray, 4, VIEWPORT);
    expect(hit?.segment).toBe(0);
    expect(hit?.distance).toBeCloseTo(10, 3);
    const behind = new Float32Array([-1, 0, 15, 1, 0, 15]);
    expect(pickSegment(behind, camera, raycaster.ray, 4, VIEWPORT)).toBeNull();
    const inFront = new Float32Array([-1, 0, 0, 1, 0, 0]);
    expect(pickSegment(inFront, camera, raycaster.ray, 4, VIEWPORT)?.distance).toBeCloseTo(10, 5);
    expect(pickSegment(inFront, camera, raycaster.ray, 4, new Vector2(0, 0))).toBeNull();
  });
});
