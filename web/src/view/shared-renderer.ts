// One WebGL renderer for every view of a page that shows many (the <meristem-plant> elements:
// issue 50, finding 9b). A browser keeps few WebGL contexts (Chromium 16 a page) and drops the
// oldest past them: with a context per plant, a page of 20 plants in sight lost 4, of 50 lost 34.
// Here each view has a plain 2D canvas: its frame is drawn by the shared renderer into the
// bottom-left corner of the shared (off-page) canvas, at the view's size, and copied from there
// into the view's canvas at once (`drawImage`, in the same task, so no other view's frame comes
// between). The copy, not one page-sized WebGL overlay drawn with scissors: an overlay must follow
// every scroll, resize, transform, clip and stacking order of the page around each element, while
// a canvas in each element is laid out, scrolled, clipped and hit by pointers as any element is,
// and draws only when its own plant or camera changes (and only while near sight: the element
// releases its view when it scrolls away). One context is lost only if the page makes many
// others; then the views say so, and a view made again makes a new shared renderer.
import type { Camera, Scene, Vector2, WebGLRenderer } from 'three';
import type { RenderTarget } from './render-target';
import { viewRenderer } from './view-renderer';

class SharedRenderer {
  readonly renderer: WebGLRenderer;
  readonly software: boolean;
  /** The drawing buffer's size in CSS pixels: the largest view's so far (it only grows). */
  private width = 1;
  private height = 1;

  constructor() {
    ({ renderer: this.renderer, software: this.software } = viewRenderer());
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.setSize(this.width, this.height, false);
  }

  get lost(): boolean {
    return this.renderer.getContext().isContextLost();
  }

  /** Draws `scene` at `width` × `height` CSS pixels and copies the frame into `into` (sized to it). */
  draw(scene: Scene, camera: Camera, width: number, height: number, into: CanvasRenderingContext2D): void {
    const { renderer } = this;
    if (width > this.width || height > this.height) {
      // (A pixel more: three rounds the viewport's device pixels where the canvas's are floored.)
      this.width = Math.max(this.width, Math.ceil(width) + 1);
      this.height = Math.max(this.height, Math.ceil(height) + 1);
      renderer.setSize(this.width, this.height, false);
    }
    renderer.setViewport(0, 0, width, height);
    renderer.setScissor(0, 0, width, height);
    renderer.setScissorTest(true);
    renderer.render(scene, camera);
    renderer.setScissorTest(false);
    const { width: w, height: h } = into.canvas;
    const source = renderer.domElement;
    into.globalCompositeOperation = 'copy';
    // GL's rows start at the bottom: the corner drawn is the canvas's last rows.
    into.drawImage(source, 0, source.height - h, w, h, 0, 0, w, h);
  }
}

let shared: SharedRenderer | undefined;

/** The page's shared renderer: made on first use, and again after its context was lost. */
function sharedRenderer(): SharedRenderer {
  if (!shared || shared.lost) {
    shared?.renderer.dispose();
    shared = new SharedRenderer();
  }
  return shared;
}

/** A view's 2D canvas, drawn by the page's shared renderer. */
export function sharedTarget(): RenderTarget {
  const { renderer, software } = sharedRenderer();
  const owner = shared!;
  const canvas = document.createElement('canvas');
  const context = canvas.getContext('2d');
  if (!context) throw new Error('no 2D canvas');
  let size = { width: 1, height: 1 };
  const ratio = () => renderer.getPixelRatio();
  return {
    renderer,
    software,
    canvas,
    contextCanvas: renderer.domElement,
    setSize: (width, height) => {
      size = { width, height };
      canvas.width = Math.max(1, Math.round(width * ratio())); // (as three rounds the viewport)
      canvas.height = Math.max(1, Math.round(height * ratio()));
    },
    pixelRatio: ratio,
    drawingBufferSize: (target: Vector2) => target.set(canvas.width, canvas.height),
    render: (scene, camera) => owner.draw(scene, camera, size.width, size.height, context),
    dispose: () => canvas.remove(),
  };
}
