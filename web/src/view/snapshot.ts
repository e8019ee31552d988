// Pictures of the view: a PNG of what the camera sees, at a size of the user's, drawn for one frame
// on the view's own canvas. A chunk of its own, which the first plant does without: the view loads
// it for the first picture. (It imports nothing at run time: what it needs of the view's modules
// comes in its `PictureSource`.)
import type { Color, OrthographicCamera, PerspectiveCamera, Scene, WebGLRenderer } from 'three';
import type { GroundGrid } from './ground-grid';
import type { SegmentLines } from './segment-lines';
import type { ShownPlant } from './shown-plant';
import type { View2D } from './view-2d';

/** A picture's look: its background (the view's, white or none), and the lines' width in its pixels. */
export interface PictureLook {
  background: 'view' | 'white' | 'transparent';
  /** The Lines mode's width in the picture's pixels (default: the view's, in CSS pixels). */
  lineWidth?: number;
}

/** What a picture is drawn from: the view's renderer, scene, camera and parts. */
export interface PictureSource {
  renderer: WebGLRenderer;
  scene: Scene;
  camera: PerspectiveCamera | OrthographicCamera;
  shown: ShownPlant;
  grid: GroundGrid;
  segmentLines: SegmentLines;
  view2D: View2D | undefined;
  /** White, the background of a picture on white. */
  white: Color;
  /** The largest picture side the GPU can draw. */
  maxSide: number;
  /** Draws the picture's frame into a target `scale` times its size (see `drawnSupersampled`). */
  draw(scale: number): void;
  /** Sizes the drawing buffer and the cameras to the view again. */
  resize(): void;
}

/**
 * Sets the view up for a picture of `look` drawn `scale` times its size: what is drawn in 2D (a
 * sketch, the Lines mode's segments of a big plant) drawn by WebGL into the picture, the
 * background, the lines' width. Returns what sets it back.
 */
function dress(view: PictureSource, look: PictureLook, scale: number): () => void {
  const { scene, shown, grid, segmentLines, view2D } = view;
  const background = scene.background;
  const lineWidth = segmentLines.lineWidth;
  const gridShown = grid.visible;
  shown.lines.visible = true;
  segmentLines.drawn = true;
  if (look.background !== 'view') {
    scene.background = look.background === 'white' ? view.white : null;
    grid.visible = false; // (set back before anything else runs)
  }
  segmentLines.lineWidth = (look.lineWidth ?? lineWidth) * scale;
  return () => {
    shown.lines.visible = !view2D?.active;
    segmentLines.drawn = !view2D?.linesIn2D;
    scene.background = background;
    grid.visible = gridShown;
    segmentLines.lineWidth = lineWidth;
  };
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
  const scale = multisampled || view.shown.asThinLines || 2 * Math.max(width, height) > view.maxSide ? 1 : 2;
  const pixelRatio = renderer.getPixelRatio();
  let blob: Promise<Blob | null>;
  const undress = dress(view, look, scale);
  try {
    renderer.setClearColor(0xffffff, look.background === 'transparent' ? 0 : 1);
    renderer.setPixelRatio(1);
    renderer.setSize(width * scale, height * scale, false);
    if ('isPerspectiveCamera' in camera) camera.aspect = width / height;
    else [camera.left, camera.right] = [-camera.top * (width / height), camera.top * (width / height)];
    camera.updateProjectionMatrix();
    view.draw(scale);
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
