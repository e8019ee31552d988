// Pictures of the view: a PNG of what the camera sees, at a size of the user's, drawn for one frame
// on the view's own canvas.
import { PerspectiveCamera, type OrthographicCamera, type Scene, type WebGLRenderer } from 'three';
import { drawnSupersampled } from './scene-setup';

/** A picture's look: its background (the view's, white or none), and the lines' width in its pixels. */
export interface PictureLook {
  background: 'view' | 'white' | 'transparent';
  /** The Lines mode's width in the picture's pixels (default: the view's, in CSS pixels). */
  lineWidth?: number;
}

/** What a picture is drawn from: the view's renderer, scene and camera, and its own settings. */
export interface PictureSource {
  renderer: WebGLRenderer;
  scene: Scene;
  camera: PerspectiveCamera | OrthographicCamera;
  /** A plant drawn as lines one pixel wide is on screen (too large to mesh): scaled down, they would fade. */
  thinLines: boolean;
  /**
   * Sets the view up for a picture of `look` drawn `scale` times its size (what is drawn in 2D
   * drawn by WebGL, the background, the lines' width); returns what sets it back.
   */
  dress(look: PictureLook, scale: number): () => void;
  /** Sizes the drawing buffer and the cameras to the view again. */
  resize(): void;
}

/** The largest picture side the GPU can draw (its renderbuffer and viewport limits). */
export function maxPictureSide(renderer: WebGLRenderer): number {
  const gl = renderer.getContext();
  const viewport = gl.getParameter(gl.MAX_VIEWPORT_DIMS) as Int32Array;
  const renderbuffer = gl.getParameter(gl.MAX_RENDERBUFFER_SIZE) as number;
  return Math.min(viewport[0], viewport[1], renderbuffer);
}

/** `source` drawn into a new canvas of `width` × `height` (smoothed: a 2:1 scale averages each 2 × 2 pixels). */
function scaledDown(source: HTMLCanvasElement, width: number, height: number): HTMLCanvasElement {
  const canvas = document.createElement('canvas');
  [canvas.width, canvas.height] = [width, height];
  const context = canvas.getContext('2d');
  if (!context) throw new Error(`the browser could not make a ${width} × ${height} canvas for the picture`);
  context.imageSmoothingQuality = 'high';
  context.drawImage(source, 0, 0, width, height);
  return canvas;
}

/**
 * A PNG of the view at `width` × `height` pixels: the same camera and lights, the aspect ratio of
 * the picture (the vertical field of view, or the orthographic height, is kept), the look
 * `look`. The canvas is drawn at that size for one frame and restored before the page paints
 * again. A view without multisampling (a software rasterizer's, see `viewRenderer`) draws it at
 * twice the size, where the GPU can, and scales it down: as smooth as a multisampled one.
 */
export async function snapshot(view: PictureSource, width: number, height: number, look: PictureLook): Promise<Blob> {
  const { renderer, scene, camera } = view;
  const canvas = renderer.domElement;
  const multisampled = renderer.getContext().getContextAttributes()?.antialias === true;
  const scale = multisampled || view.thinLines || 2 * Math.max(width, height) > maxPictureSide(renderer) ? 1 : 2;
  const pixelRatio = renderer.getPixelRatio();
  let blob: Promise<Blob | null>;
  const undress = view.dress(look, scale);
  try {
    renderer.setClearColor(0xffffff, look.background === 'transparent' ? 0 : 1);
    renderer.setPixelRatio(1);
    renderer.setSize(width * scale, height * scale, false);
    if (camera instanceof PerspectiveCamera) camera.aspect = width / height;
    else [camera.left, camera.right] = [-camera.top * (width / height), camera.top * (width / height)];
    camera.updateProjectionMatrix();
    drawnSupersampled(scale, () => renderer.render(scene, camera));
    // toBlob copies the bitmap now (preserveDrawingBuffer keeps it); encoding finishes later.
    const picture = scale === 1 ? canvas : scaledDown(canvas, width, height);
    blob = new Promise((resolve) => picture.toBlob(resolve, 'image/png'));
  } finally {
    undress();
    renderer.setPixelRatio(pixelRatio);
    view.resize();
    renderer.render(scene, camera);
  }
  const png = await blob;
  if (!png) throw new Error(`the browser could not encode a ${width} × ${height} PNG`);
  return png;
}
