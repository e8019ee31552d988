import { describe, expect, it } from 'vitest';
import { Matrix4, OrthographicCamera, PerspectiveCamera, Vector3, type Camera } from 'three';
import { Color, LinearSRGBColorSpace } from 'three';
import { HAIRLINE, projectSegments, strokeSegments, tracePolylines, type PathSink, type StrokeSink } from './sketch-canvas';

const [WIDTH, HEIGHT] = [200, 100];

/** A camera at z = 10 looking at the origin, its matrices up to date. */
function placed<C extends PerspectiveCamera | OrthographicCamera>(camera: C): C {
  camera.position.set(0, 0, 10);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  camera.updateProjectionMatrix();
  return camera;
}

function viewProjection(camera: Camera): number[] {
  return new Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse).elements;
}

/** Where three.js puts `point` on the 200 × 100 canvas (y down). */
function pixel(point: Vector3, camera: Camera): [number, number] {
  const ndc = point.clone().project(camera);
  return [((ndc.x + 1) / 2) * WIDTH, ((1 - ndc.y) / 2) * HEIGHT];
}

function projected(ends: number[], camera: Camera): { screen: Float32Array; shown: Uint8Array; count: number } {
  const segments = ends.length / 6;
  const [screen, shown] = [new Float32Array(4 * segments), new Uint8Array(segments)];
  const count = projectSegments(new Float32Array(ends), viewProjection(camera), WIDTH, HEIGHT, screen, shown);
  return { screen, shown, count };
}

describe('projectSegments', () => {
  for (const [name, make] of [
    ['perspective', () => new PerspectiveCamera(40, WIDTH / HEIGHT, 0.5, 100)],
    ['orthographic', () => new OrthographicCamera(-10, 10, 5, -5, 0.5, 100)],
  ] as const) {
    it(`puts segment ends where three.js projects them (${name})`, () => {
      const camera = placed(make());
      // Two segments of a branch (the second starts where the first ends) and one apart.
      const points = [new Vector3(-2, -1, 0), new Vector3(0, 1, 1), new Vector3(3, 2, -4), new Vector3(1, -3, 2), new Vector3(-1, 0.5, -2)];
      const ends = [points[0], points[1], points[1], points[2], points[3], points[4]].flatMap((p) => p.toArray());
      const { screen, shown, count } = projected(ends, camera);
      expect(count).toBe(3);
      expect([...shown]).toEqual([1, 1, 1]);
      const expected = [points[0], points[1], points[1], points[2], points[3], points[4]].flatMap((p) => pixel(p, camera));
      [...screen].forEach((v, i) => expect(v).toBeCloseTo(expected[i], 3));
    });
  }

  it('cuts a segment at the near plane and leaves out one wholly behind it', () => {
    const camera = placed(new PerspectiveCamera(40, WIDTH / HEIGHT, 0.5, 100));
    // The near plane is at z = 9.5. One segment crosses it, one lies behind the camera.
    const inFront = new Vector3(1, 1, 0);
    const behind = new Vector3(1, 1, 12);
    const { screen, shown, count } = projected([...inFront.toArray(), ...behind.toArray(), 0, 0, 11, 1, 0, 20], camera);
    expect(count).toBe(1);
    expect([...shown]).toEqual([1, 0]);
    const onPlane = inFront.clone().lerp(behind, (9.5 - 0) / (12 - 0));
    const expected = [...pixel(inFront, camera), ...pixel(onPlane, camera)];
    [...screen.subarray(0, 4)].forEach((v, i) => expect(v).toBeCloseTo(expected[i], 2));
  });

});

/** The distance from (x, y) to the segment from (ax, ay) to (bx, by). */
function distanceToSegment(x: number, y: number, ax: number, ay: number, bx: number, by: number): number {
  const [dx, dy] = [bx - ax, by - ay];
  const t = Math.max(0, Math.min(1, ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy || 1)));
  return Math.hypot(x - (ax + t * dx), y - (ay + t * dy));
}

/** The calls a path receives, as text. */
function traced(screen: number[], shown = screen.map(() => 1)): string[] {
  const calls: string[] = [];
  const path: PathSink = {
    moveTo: (x, y) => calls.push(`M ${x} ${y}`),
    lineTo: (x, y) => calls.push(`L ${x} ${y}`),
  };
  tracePolylines(path, new Float32Array(screen), new Uint8Array(shown), 0, screen.length / 4);
  return calls;
}

describe('tracePolylines', () => {
  it('draws a branch going straight on as one line, and turns at its corners', () => {
    // Three segments straight to the right, then one up.
    expect(traced([0, 0, 10, 0, 10, 0, 20, 0, 20, 0, 30, 0, 30, 0, 30, 10])).toEqual(['M 0 0', 'L 30 0', 'L 30 10']);
  });

  it('keeps a bend of more than half a pixel and leaves out one of less', () => {
    expect(traced([0, 0, 10, 0, 10, 0, 20, 0.375])).toEqual(['M 0 0', 'L 20 0.375']);
    expect(traced([0, 0, 10, 0, 10, 0, 20, 2])).toEqual(['M 0 0', 'L 10 0', 'L 20 2']);
  });

  it('follows a gentle curve: every point left out is within a pixel of a line drawn', () => {
    // 200 segments of 2 pixels turning 0.5° each: 100° in all, no turn alone over half a pixel.
    const points: [number, number][] = [[0, 0]];
    for (let k = 1; k <= 200; k++) {
      const angle = (0.5 * k * Math.PI) / 180;
      const [x, y] = points[k - 1];
      points.push([x + 2 * Math.cos(angle), y + 2 * Math.sin(angle)]);
    }
    const screen = new Float32Array(points.slice(1).flatMap(([x, y], k) => [...points[k], x, y]));
    const calls = traced([...screen]);
    expect(calls.length).toBeLessThan(100);
    const drawn = calls.map((c) => c.split(' ').slice(1).map(Number));
    for (const [x, y] of points) {
      const nearest = Math.min(...drawn.slice(1).map(([bx, by], k) => distanceToSegment(x, y, drawn[k][0], drawn[k][1], bx, by)));
      expect(nearest).toBeLessThanOrEqual(1);
    }
  });

  it('keeps a point where the line turns back on itself', () => {
    expect(traced([0, 0, 10, 0, 10, 0, 5, 0])).toEqual(['M 0 0', 'L 10 0', 'L 5 0']);
  });

  it('starts a new line where a segment does not start at the end of the one before, and skips segments not shown', () => {
    const screen = [0, 0, 10, 0, 50, 50, 60, 50, 60, 50, 70, 60];
    expect(traced(screen)).toEqual(['M 0 0', 'L 10 0', 'M 50 50', 'L 60 50', 'L 70 60']);
    expect(traced(screen, [1, 0, 1])).toEqual(['M 0 0', 'L 10 0', 'M 60 50', 'L 70 60']);
  });
});

/** The strokes a 2D context receives from {@link strokeSegments}: each path's style and points. */
function stroked(screen: number[], colors: number[], style = HAIRLINE): string[] {
  const strokes: string[] = [];
  let path: string[] = [];
  const sink: StrokeSink = {
    lineWidth: 0,
    lineCap: 'butt',
    lineJoin: 'miter',
    strokeStyle: '',
    beginPath: () => (path = []),
    moveTo: (x, y) => path.push(`M ${x} ${y}`),
    lineTo: (x, y) => path.push(`L ${x} ${y}`),
    stroke() {
      strokes.push(`${String(this.strokeStyle)} ${this.lineWidth} ${this.lineCap} ${this.lineJoin}: ${path.join(' ')}`);
    },
  };
  strokeSegments(sink, new Float32Array(screen), new Uint8Array(screen.length / 4).fill(1), new Float32Array(colors), style);
  return strokes;
}

/** The CSS colour of linear RGB (r, g, b). */
function css(r: number, g: number, b: number): string {
  return new Color().setRGB(r, g, b, LinearSRGBColorSpace).getStyle();
}

describe('strokeSegments', () => {
  const screen = [0, 0, 10, 0, 10, 0, 10, 10, 10, 10, 20, 10];
  const red = [0.8, 0.1, 0.1, 0.8, 0.1, 0.1];
  const green = [0.1, 0.6, 0.2, 0.1, 0.6, 0.2];

  it('strokes each run of one colour as one path, in sRGB, a pixel wide with plain ends for a sketch', () => {
    expect(stroked(screen, [...red, ...red, ...green])).toEqual([
      `${css(0.8, 0.1, 0.1)} 1 butt bevel: M 0 0 L 10 0 L 10 10`,
      `${css(0.1, 0.6, 0.2)} 1 butt bevel: M 10 10 L 20 10`,
    ]);
  });

  it('strokes the Lines mode in its width with round ends and corners, the colours dimmed', () => {
    expect(stroked(screen, [...red, ...red, ...red], { width: 3, round: true, dim: 0.5 })).toEqual([`${css(0.4, 0.05, 0.05)} 3 round round: M 0 0 L 10 0 L 10 10 L 20 10`]);
  });
});
