// The view's WebGL renderer (multisampled where a GPU draws) and its frames: drawn on demand, at an
// animation frame, once the GPU has finished the frame before.
import { BufferAttribute, BufferGeometry, Group, LineSegments, Mesh, WebGLRenderer, type Camera, type Material, type Scene } from 'three';
import { drawnBySoftware } from './rasterizer';

/**
 * The view's renderer: multisampled (4× MSAA) where a GPU draws, not on a software rasterizer (a
 * machine without a usable GPU: {@link drawnBySoftware}), where multisampling costs more than the
 * rest of each frame. On SwiftShader, 1.24d at n = 10 in the Tubes mode: the GPU done with the
 * edited tree 1.9–2.3 s after a keystroke with it, 0.7–0.8 s without, and the tubes drawn
 * 276–368 ms → 212–235 ms (the upload waits for the sketch's frame; `npm run bench:studio`).
 * Its tubes still draw at least a pixel wide (`atLeastAPixelWide`), and pictures are drawn at
 * twice their size and scaled down (./snapshot.ts). On such a machine the context is made twice:
 * the first tells the rasterizer. The Stages view and the gallery's thumbnails keep multisampling
 * everywhere: they draw few, small plants, mostly as lines one pixel wide, which a picture scaled
 * down would fade. `software` says which it is (the view draws its sketches in 2D there:
 * `PlantView.showSketch`).
 */
export function viewRenderer(): { renderer: WebGLRenderer; software: boolean } {
  const options = { preserveDrawingBuffer: true, alpha: true };
  const renderer = new WebGLRenderer({ ...options, antialias: true });
  if (!drawnBySoftware(renderer.getContext())) return { renderer, software: false };
  renderer.dispose();
  renderer.forceContextLoss();
  return { renderer: new WebGLRenderer({ ...options, antialias: false }), software: true };
}

/**
 * Compiles without drawing the programs of the materials `meshes` for a plant's triangles and
 * `lines` for its lines, and those of `scene` as it is now, with `renderer`, as `camera` sees
 * them. Settles when they are ready to draw with.
 */
export function compileAhead(renderer: WebGLRenderer, scene: Scene, camera: Camera, meshes: Material[], lines: Material[]): Promise<unknown> {
  // Stand-ins with the attributes a plant's geometries have: three.js keys a program by them too.
  const triangle = (...names: string[]) => {
    const geometry = new BufferGeometry();
    for (const name of names) geometry.setAttribute(name, new BufferAttribute(new Float32Array(9), 3));
    return geometry;
  };
  const standIns = new Group();
  const mesh = triangle('position', 'normal', 'color');
  for (const material of meshes) standIns.add(new Mesh(mesh, material));
  const line = triangle('position', 'color');
  for (const material of lines) standIns.add(new LineSegments(line, material));
  // And the scene's own objects as they are now: the first plant's frame still draws some of them
  // without attributes (the sketch's lines when there is no sketch), which takes other programs.
  return Promise.all([renderer.compileAsync(standIns, camera, scene), renderer.compileAsync(scene, camera)]);
}

/** The largest picture side the GPU can draw (its renderbuffer and viewport limits). */
export function maxPictureSide(renderer: WebGLRenderer): number {
  const gl = renderer.getContext();
  const viewport = gl.getParameter(gl.MAX_VIEWPORT_DIMS) as Int32Array;
  const renderbuffer = gl.getParameter(gl.MAX_RENDERBUFFER_SIZE) as number;
  return Math.min(viewport[0], viewport[1], renderbuffer);
}

/** What a frame of the view does, in order. */
export interface FrameSteps {
  /** Before the frame, while it is still queued (a frame asked for meanwhile is this one). */
  prepare(): void;
  /** The WebGL frame. */
  render(): void;
  /** After the WebGL frame and its fence (what is drawn in 2D over it). */
  after(): void;
}

/**
 * Frames drawn on demand ({@link request}): one at the next animation frame, however often asked
 * for, and only once the GPU has passed the fence after the frame before the last (one frame at
 * most is still being drawn). Listeners hear of each frame drawn.
 */
export class FrameLoop {
  private queued = false;
  /** The fence after the last frame drawn, until the GPU has passed it ({@link gpuIdle}). */
  private drawn: WebGLSync | null = null;
  /** The fence after the frame before, until the GPU has passed it ({@link renderWhenDrawn}). */
  private before: WebGLSync | null = null;
  private readonly listeners = new Set<() => void>();

  constructor(
    private readonly renderer: WebGLRenderer,
    private readonly steps: FrameSteps,
  ) {}

  /** Asks for a frame. */
  request(): void {
    if (this.queued) return;
    this.queued = true;
    requestAnimationFrame(() => this.renderWhenDrawn());
  }

  /**
   * Renders at an animation frame once the GPU has finished the frame before the last (a fence
   * after each): a frame of a million-vertex plant can keep a software GPU busy for up to a second,
   * and a new plant's upload made meanwhile held the page's thread until then (long tasks of 0.3 to
   * 3 s while typing into that tree, `tests/browser/responsiveness.test.ts`). One frame may still
   * be on its way: with GPU compositing on SwiftShader the fence of the last frame is seen passed
   * only after the compositor's frame that follows it, and waiting for it drew one animation
   * frame in two or three (the growth of 1.24d at n = 7 played at 4-9 frames a second, 6-13 with
   * a frame in flight, on a machine at load 12-16). Where the page's frame reads the canvas back
   * (software compositing), the last frame is done by the next animation frame, and nothing
   * changes. A GPU is done long before the next frame, and nothing waits.
   */
  private renderWhenDrawn(): void {
    if (!this.passed(this.before)) {
      requestAnimationFrame(() => this.renderWhenDrawn());
      return;
    }
    const gl = this.renderer.getContext();
    this.steps.prepare();
    this.queued = false;
    this.steps.render();
    if (gl instanceof WebGL2RenderingContext) {
      if (this.before) gl.deleteSync(this.before);
      this.before = this.drawn;
      this.drawn = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    }
    this.steps.after();
    for (const listener of this.listeners) listener();
  }

  /** Whether there is no fence `sync` or the GPU has passed it. */
  private passed(sync: WebGLSync | null): boolean {
    const gl = this.renderer.getContext();
    return !sync || !(gl instanceof WebGL2RenderingContext) || gl.clientWaitSync(sync, 0, 0) !== gl.TIMEOUT_EXPIRED;
  }

  /** The GPU has finished the last frame drawn (its fence, and the one before, have passed). */
  gpuIdle(): boolean {
    if (!this.passed(this.drawn)) return false;
    const gl = this.renderer.getContext() as WebGL2RenderingContext;
    for (const sync of [this.drawn, this.before]) if (sync) gl.deleteSync(sync);
    this.drawn = this.before = null;
    return true;
  }

  /** The context was lost, and the fences with it. */
  forgetFence(): void {
    this.drawn = this.before = null;
  }

  /** Calls `listener` after every frame drawn; returns the function that stops it. */
  onRender(listener: () => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }
}
