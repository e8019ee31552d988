// A plant's segments drawn with the 2D canvas, over the WebGL view, where a software rasterizer
// draws that view (./rasterizer.ts): one-pixel lines (a big plant's sketch, on screen while the
// build worker meshes its tubes; a plant too large to mesh), and in the Lines mode a big plant's
// lines themselves.
// SwiftShader spent 50 to 80 ms rasterizing the 116,050 lines of ABOP 1.24d at n = 10 as a WebGL
// frame, and the page's thread waited for it (Chromium reads each WebGL frame back without a GPU)
// or the tubes' upload did (with GPU compositing): the tubes came on screen 30 to 70 ms later than
// with no sketch at all (`npm run bench:studio`, 2026-11-27). The CPU draws the same hairlines
// into a 2D canvas in 5 to 15 ms, the projection included. The Lines mode's wide lines with round
// ends cost SwiftShader about 3 µs a segment every frame (a 1,048,576-segment dragon curve: 3 s a
// frame); the 2D canvas draws them in a fifth of that or less. The WebGL view meanwhile draws its
// frame without them.
import type { Camera } from 'three';
import { Color, LinearSRGBColorSpace, Matrix4 } from 'three';

/**
 * The segments `ends` (x, y, z for each end, two ends a segment) as seen through `viewProjection`
 * (a camera's projection matrix times its inverse world matrix, column-major) on a canvas of
 * `width` × `height` pixels: x, y for each end written to `out` (four numbers a segment, y down),
 * and for each segment in `shown` whether any of it is in front of the camera's near plane (the
 * part behind it is cut off, as WebGL clips). Returns the number of segments shown.
 */
export function projectSegments(ends: Float32Array, viewProjection: ArrayLike<number>, width: number, height: number, out: Float32Array, shown: Uint8Array): number {
  const m = Float64Array.from(viewProjection);
  const halfWidth = width / 2;
  const halfHeight = height / 2;
  let count = 0;
  // Each end in clip space (x, y, z, w); the first carried over from the last segment's second
  // where a segment starts where the one before ended (a branch goes on).
  let x0 = 0;
  let y0 = 0;
  let z0 = 0;
  let w0 = 0;
  let x1 = 0;
  let y1 = 0;
  let z1 = 0;
  let w1 = 0;
  // The sixteen products are written out, with the ends in locals: through a helper and an array
  // of clip coordinates the projection took twice as long (4.5 against 2.1 ms for the big tree in
  // Node). Each end projected goes to the second end's locals, the one there before moving to the
  // first's: a segment that goes on from the one before projects only its second end.
  for (let s = 0, o = 0; o < ends.length; s++, o += 6) {
    const goesOn = s > 0 && ends[o] === ends[o - 3] && ends[o + 1] === ends[o - 2] && ends[o + 2] === ends[o - 1];
    for (let e = goesOn ? o + 3 : o; e <= o + 3; e += 3) {
      x0 = x1;
      y0 = y1;
      z0 = z1;
      w0 = w1;
      const x = ends[e];
      const y = ends[e + 1];
      const z = ends[e + 2];
      x1 = m[0] * x + m[4] * y + m[8] * z + m[12];
      y1 = m[1] * x + m[5] * y + m[9] * z + m[13];
      z1 = m[2] * x + m[6] * y + m[10] * z + m[14];
      w1 = m[3] * x + m[7] * y + m[11] * z + m[15];
    }
    // Signed distance from the near plane (z = -w in clip space): positive in front of it.
    const near0 = z0 + w0;
    const near1 = z1 + w1;
    if (near0 < 0 && near1 < 0) {
      shown[s] = 0;
      continue;
    }
    shown[s] = 1;
    count++;
    const k = 4 * s;
    if (near0 >= 0 && near1 >= 0) {
      out[k] = (x0 / w0 + 1) * halfWidth;
      out[k + 1] = (1 - y0 / w0) * halfHeight;
      out[k + 2] = (x1 / w1 + 1) * halfWidth;
      out[k + 3] = (1 - y1 / w1) * halfHeight;
      continue;
    }
    // One end behind the plane: that end moved onto it.
    const t = near0 / (near0 - near1);
    const px = x0 + t * (x1 - x0);
    const py = y0 + t * (y1 - y0);
    const pw = w0 + t * (w1 - w0);
    const front = near0 >= 0;
    out[k] = ((front ? x0 / w0 : px / pw) + 1) * halfWidth;
    out[k + 1] = (1 - (front ? y0 / w0 : py / pw)) * halfHeight;
    out[k + 2] = ((front ? px / pw : x1 / w1) + 1) * halfWidth;
    out[k + 3] = (1 - (front ? py / pw : y1 / w1)) * halfHeight;
  }
  return count;
}

/** How {@link SketchCanvas} strokes segments: widths in pixels of the canvas. */
export interface LineStyle {
  /** The lines' width. */
  width: number;
  /** Round ends and corners (the Lines mode's), or plain ends and bevelled corners (a sketch's hairlines, thin lines). */
  round: boolean;
  /** The brightness of the segments' colours (1: as they are; less while some are highlighted). */
  dim: number;
}

/** A sketch's lines: a pixel wide, plain ends. */
export const HAIRLINE: LineStyle = { width: 1, round: false, dim: 1 };

/** Segments drawn over the others, `width` pixels of the canvas wide (highlighted ones). */
export interface OverSegments {
  ends: Float32Array;
  colors: Float32Array;
  width: number;
}

/** What {@link strokeSegments} draws on: a 2D canvas context, or a recorder in tests. */
export interface StrokeSink extends PathSink {
  lineWidth: number;
  lineCap: CanvasLineCap;
  lineJoin: CanvasLineJoin;
  strokeStyle: string | CanvasGradient | CanvasPattern;
  beginPath(): void;
  stroke(): void;
}

/**
 * Strokes the segments `shown` of `screen` (as {@link projectSegments} writes them) onto `sink`
 * in `style`, each in its colour of `colors` (linear RGB, three numbers an end, as the core's line
 * colours; the first end's is the segment's) times `style.dim`: one path for each run of segments
 * of one colour (a plant has few colours, in long runs).
 */
export function strokeSegments(sink: StrokeSink, screen: Float32Array, shown: Uint8Array, colors: Float32Array, style: LineStyle): void {
  const segments = shown.length;
  const color = new Color();
  sink.lineWidth = style.width;
  sink.lineCap = style.round ? 'round' : 'butt';
  sink.lineJoin = style.round ? 'round' : 'bevel'; // no miter's spike where a line turns back
  for (let start = 0; start < segments; ) {
    let end = start + 1;
    while (end < segments && sameColor(colors, start, end)) end++;
    sink.beginPath();
    tracePolylines(sink, screen, shown, start, end);
    const [r, g, b] = [colors[6 * start], colors[6 * start + 1], colors[6 * start + 2]];
    sink.strokeStyle = color.setRGB(r * style.dim, g * style.dim, b * style.dim, LinearSRGBColorSpace).getStyle();
    sink.stroke();
    start = end;
  }
}

/** Segments and where they are on the canvas (reused from one drawing to the next). */
class Projected {
  screen = new Float32Array(0);
  shown = new Uint8Array(0);

  /** `ends` as `viewProjection` puts them on a canvas of `width` × `height`. */
  project(ends: Float32Array, viewProjection: ArrayLike<number>, width: number, height: number): void {
    const segments = ends.length / 6;
    if (this.screen.length < 4 * segments) [this.screen, this.shown] = [new Float32Array(4 * segments), new Uint8Array(segments)];
    projectSegments(ends, viewProjection, width, height, this.screen, this.shown);
  }
}

/**
 * The 2D canvas over the view that shows segments (a sketch, or the Lines mode's lines): in the
 * page only while it shows some.
 */
export class SketchCanvas {
  readonly canvas = document.createElement('canvas');
  private ends: Float32Array | undefined;
  private colors: Float32Array | undefined;
  private style = HAIRLINE;
  private over: OverSegments | null = null;
  private readonly segments = new Projected();
  private readonly overSegments = new Projected();
  private readonly matrix = new Matrix4();
  /** What the canvas shows, when `drawn`: the segments through this matrix. */
  private readonly drawnWith = new Matrix4();
  private drawn = false;

  /** `container`: the view's, where the canvas goes after the view's own (over it). */
  constructor(private readonly container: HTMLElement) {
    this.canvas.className = 'sketch-canvas';
    this.canvas.setAttribute('aria-hidden', 'true');
    // The view's canvas below takes the pointer (orbit, picking), in the studio and in an embed.
    this.canvas.style.pointerEvents = 'none';
  }

  /** Whether segments are shown. */
  get active(): boolean {
    return this.ends !== undefined;
  }

  /**
   * Shows the segments `ends` in the linear RGB `colors` (both as the core's `lines`, `lineColors`)
   * in `style`, from the next {@link draw}, with nothing over them.
   */
  show(ends: Float32Array, colors: Float32Array, style: LineStyle = HAIRLINE): void {
    this.ends = ends;
    this.colors = colors;
    this.style = style;
    this.over = null;
    this.drawn = false;
  }

  /**
   * Draws the segments shown in `style` from the next {@link draw}, with `over` over them (null:
   * none); nothing to draw again when they are as drawn already (the view restyles after each
   * build, mostly to the same).
   */
  restyle(style: LineStyle, over: OverSegments | null): void {
    const same = (a: OverSegments | null, b: OverSegments | null) => a === b || (a !== null && b !== null && a.ends === b.ends && a.colors === b.colors && a.width === b.width);
    if (style.width === this.style.width && style.round === this.style.round && style.dim === this.style.dim && same(over, this.over)) return;
    this.style = style;
    this.over = over;
    this.drawn = false;
  }

  /** Takes the segments away. */
  clear(): void {
    this.ends = this.colors = undefined;
    this.over = null;
    this.drawn = false;
    this.canvas.remove();
  }

  /**
   * Draws the segments as `camera` (its matrices up to date) sees them on a drawing buffer of
   * `width` × `height` pixels, unless the canvas shows just that already.
   */
  draw(camera: Camera, width: number, height: number): void {
    const { ends, colors, canvas } = this;
    if (!ends || !colors) return;
    this.matrix.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
    if (this.drawn && this.matrix.equals(this.drawnWith) && canvas.width === width && canvas.height === height) return;
    this.drawnWith.copy(this.matrix);
    this.drawn = true;
    if (canvas.width !== width || canvas.height !== height) [canvas.width, canvas.height] = [width, height];
    // Drawn by the CPU (`willReadFrequently`): a 2D canvas drawn by the GPU is drawn by the same
    // software rasterizer (with GPU compositing the tubes then came 1.7 s after the keystroke).
    const context = canvas.getContext('2d', { willReadFrequently: true });
    if (!context) return;
    context.clearRect(0, 0, width, height);
    this.segments.project(ends, this.matrix.elements, width, height);
    strokeSegments(context, this.segments.screen, this.segments.shown.subarray(0, ends.length / 6), colors, this.style);
    const over = this.over;
    if (over && over.ends.length > 0) {
      this.overSegments.project(over.ends, this.matrix.elements, width, height);
      strokeSegments(context, this.overSegments.screen, this.overSegments.shown.subarray(0, over.ends.length / 6), over.colors, { width: over.width, round: true, dim: 1 });
    }
    if (!canvas.isConnected) this.container.append(canvas);
  }
}

/** What {@link tracePolylines} draws on: a 2D canvas context, or a `Path2D`. */
export interface PathSink {
  moveTo(x: number, y: number): void;
  lineTo(x: number, y: number): void;
}

/**
 * Segments `from` to `to` (those `shown`) of `screen` (x, y for each end, as {@link projectSegments}
 * writes them) traced into `path` as polylines: one goes on where a segment starts at the end of
 * the one before (a branch's segments), and leaves out the points where it goes straight on: each
 * line drawn runs from a corner along the direction of the segment that left it, and ends before
 * the first point more than half a pixel off that line (or going back), so every point left out is
 * within a pixel of it. Fewer calls to the canvas, the same pixels give or take one at an edge.
 */
export function tracePolylines(path: PathSink, screen: Float32Array, shown: Uint8Array, from: number, to: number): void {
  // The polyline's end (NaN: no polyline yet), its last corner and the unit direction it left it in.
  let lastX = NaN;
  let lastY = NaN;
  let cornerX = 0;
  let cornerY = 0;
  let dirX = 0;
  let dirY = 0;
  for (let s = from; s < to; s++) {
    if (!shown[s]) continue;
    const o = 4 * s;
    const ax = screen[o];
    const ay = screen[o + 1];
    const bx = screen[o + 2];
    const by = screen[o + 3];
    const goesOn = ax === lastX && ay === lastY;
    if (!goesOn) {
      if (lastX === lastX) path.lineTo(lastX, lastY);
      path.moveTo(ax, ay);
    }
    if (!goesOn || !alongLine(cornerX, cornerY, dirX, dirY, ax, ay, bx, by)) {
      if (goesOn) path.lineTo(ax, ay);
      const length = Math.hypot(bx - ax, by - ay);
      cornerX = ax;
      cornerY = ay;
      dirX = length > 0 ? (bx - ax) / length : 0;
      dirY = length > 0 ? (by - ay) / length : 0;
    }
    lastX = bx;
    lastY = by;
  }
  if (lastX === lastX) path.lineTo(lastX, lastY);
}

/**
 * Whether (bx, by) is within half a pixel of the line from the corner (cx, cy) in the unit
 * direction (dx, dy) (none: zero), and no nearer the corner along it than (ax, ay).
 */
function alongLine(cx: number, cy: number, dx: number, dy: number, ax: number, ay: number, bx: number, by: number): boolean {
  if (dx === 0 && dy === 0) return false;
  const across = dx * (by - cy) - dy * (bx - cx);
  const along = dx * (bx - cx) + dy * (by - cy);
  return Math.abs(across) <= 0.5 && along >= dx * (ax - cx) + dy * (ay - cy);
}

/** Segments `a` and `b` start in the same colour. */
function sameColor(colors: Float32Array, a: number, b: number): boolean {
  return colors[6 * a] === colors[6 * b] && colors[6 * a + 1] === colors[6 * b + 1] && colors[6 * a + 2] === colors[6 * b + 2];
}
