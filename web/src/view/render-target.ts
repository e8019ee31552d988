// Where a view draws: its own WebGL canvas (the studio), or a 2D canvas of its own filled by the
// page's one shared WebGL renderer (the <meristem-plant> elements: ./shared-renderer.ts).
import type { Camera, Scene, Vector2, WebGLRenderer } from 'three';
import { viewRenderer } from './view-renderer';

/** What a {@link PlantView} draws with and into. */
export interface RenderTarget {
  /** The renderer that draws (its context's fences, uploads and programs serve the view). */
  readonly renderer: WebGLRenderer;
  /** A software rasterizer draws (see `viewRenderer`). */
  readonly software: boolean;
  /** The canvas on the page: what the reader sees, and where pointer and keys come. */
  readonly canvas: HTMLCanvasElement;
  /** The canvas whose WebGL context draws (the one to hear `webglcontextlost` from). */
  readonly contextCanvas: HTMLCanvasElement;
  /** The canvas is `width` × `height` CSS pixels. */
  setSize(width: number, height: number): void;
  /** Device pixels per CSS pixel of the canvas. */
  pixelRatio(): number;
  /** The canvas's size in device pixels, into `target`. */
  drawingBufferSize(target: Vector2): Vector2;
  /** Draws `scene` as `camera` sees it into the canvas. */
  render(scene: Scene, camera: Camera): void;
  /** Gives back what is the view's own (not a shared renderer). */
  dispose(): void;
}

/** A view's own WebGL canvas and renderer: the studio's. */
export function ownTarget(): RenderTarget {
  const { renderer, software } = viewRenderer();
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  const canvas = renderer.domElement;
  return {
    renderer,
    software,
    canvas,
    contextCanvas: canvas,
    setSize: (width, height) => renderer.setSize(width, height, false),
    pixelRatio: () => renderer.getPixelRatio(),
    drawingBufferSize: (target) => renderer.getDrawingBufferSize(target),
    render: (scene, camera) => renderer.render(scene, camera),
    dispose: () => {
      renderer.dispose();
      canvas.remove();
    },
  };
}
