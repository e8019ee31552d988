// Pictures of the view: a PNG of what the camera sees, at a size of the user's, drawn for one frame
// on the view's own canvas; and a movie's frames, drawn one after another the same way. A chunk of its own, which the first plant does without: the view loads
// it for the first picture. (It imports nothing of the view's modules at run time but the
// turntable, which is its own: what it needs of them comes in its `PictureSource`.)
import { Vector3, type Color, type OrthographicCamera, type PerspectiveCamera, type Scene, type WebGLRenderer } from 'three';
import type { GroundGrid } from './ground-grid';
import type { SegmentLines } from './segment-lines';
import type { ShownPlant } from './shown-plant';
import { framePicture, keepCamera } from './picture-frame';
import { turntable } from './turntable';
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
  /** The point the camera looks at (the orbit's centre). */
  target: [number, number, number];
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

/** `source` drawn into `canvas` (a new one by default) of `width` × `height` (smoothed: a 2:1 scale averages each 2 × 2 pixels). */
function scaledDown(source: HTMLCanvasElement, width: number, height: number, canvas = document.createElement('canvas')): HTMLCanvasElement {
  if (canvas.width !== width || canvas.height !== height) [canvas.width, canvas.height] = [width, height];
  const context = canvas.getContext('2d');
  if (!context) throw new Error(`the browser could not make a ${width} × ${height} canvas for the picture`);
  context.imageSmoothingQuality = 'high';
  context.drawImage(source, 0, 0, width, height);
  return canvas;
}

/**
 * The scale a picture of `width` × `height` is drawn at: twice its size where the view does not
 * multisample (a software rasterizer's, see `viewRenderer`) and the GPU can, then scaled down: as
 * smooth as a multisampled one.
 */
function pictureScale(view: PictureSource, width: number, height: number): number {
  const multisampled = view.renderer.getContext().getContextAttributes()?.antialias === true;
  return multisampled || view.shown.asThinLines || 2 * Math.max(width, height) > view.maxSide ? 1 : 2;
}

/**
 * Draws the (dressed) view at `width` × `height` pixels, `scale` times that in its drawing buffer,
 * with the camera taking the picture's aspect ratio (the vertical field of view, or the
 * orthographic height, is kept). Returns the canvas holding the picture: the view's own, or
 * `scaled` (a new canvas by default) when drawn at twice the size. The view is to be restored after.
 */
function drawSized(view: PictureSource, width: number, height: number, scale: number, look: PictureLook, scaled?: HTMLCanvasElement): HTMLCanvasElement {
  const { renderer, camera } = view;
  renderer.setClearColor(0xffffff, look.background === 'transparent' ? 0 : 1);
  // (Setting a canvas's size, even to the one it has, makes its drawing buffer again: a movie's
  // frames after the first keep it.)
  if (renderer.getPixelRatio() !== 1) renderer.setPixelRatio(1);
  const canvas = renderer.domElement;
  if (canvas.width !== width * scale || canvas.height !== height * scale) renderer.setSize(width * scale, height * scale, false);
  if ('isPerspectiveCamera' in camera) camera.aspect = width / height;
  else [camera.left, camera.right] = [-camera.top * (width / height), camera.top * (width / height)];
  camera.updateProjectionMatrix();
  view.draw(scale);
  return scale === 1 ? canvas : scaledDown(canvas, width, height, scaled);
}

/** Puts the view back as it was before pictures were drawn (its size, its camera's aspect) and draws it. */
function restore(view: PictureSource, pixelRatio: number): void {
  view.renderer.setPixelRatio(pixelRatio);
  view.resize();
  view.renderer.render(view.scene, view.camera);
}

/**
 * A PNG of the view at `width` × `height` pixels: the camera looking the same way, moved so that the
 * whole plant fills the picture's aspect ratio with a margin (./picture-frame.ts), the same lights,
 * the look `look` (see {@link drawSized}). The canvas is drawn at that size for one frame and
 * restored, with the camera, before the page paints again.
 */
export async function snapshot(view: PictureSource, width: number, height: number, look: PictureLook): Promise<Blob> {
  const scale = pictureScale(view, width, height);
  const pixelRatio = view.renderer.getPixelRatio();
  let blob: Promise<Blob | null>;
  const undress = dress(view, look, scale);
  const putBack = keepCamera(view.camera);
  try {
    framePicture(view.camera, view.shown.box(true), width / height);
    const picture = drawSized(view, width, height, scale, look);
    // toBlob copies the bitmap now (preserveDrawingBuffer keeps it); encoding finishes later.
    blob = new Promise((resolve) => picture.toBlob(resolve, 'image/png'));
  } finally {
    undress();
    putBack();
    restore(view, pixelRatio);
  }
  const png = await blob;
  if (!png) throw new Error(`the browser could not encode a ${width} × ${height} PNG`);
  return png;
}

/** Frames of a movie drawn by the view, one after another, its camera turned (see {@link filmFrames}). */
export interface FilmFrames {
  /** Turns the camera `angle` radians about the vertical through its target, from where it stood when filming began. */
  turn(angle: number): void;
  /**
   * Draws the view as it is posed now at `width` × `height` pixels; returns the canvas holding
   * the frame, valid until the next call.
   */
  draw(width: number, height: number): HTMLCanvasElement;
  /** Puts the view back as it was (its size, look and camera) and draws it. */
  close(): void;
}

/**
 * The most pixels a movie's frame is drawn with when it is drawn at twice its size and scaled down
 * (see {@link pictureScale}): reading the drawing back to scale it waits for a software GPU, 160 ms
 * a 1280 × 720 frame against 1 ms drawn at its size, where the encoder takes the frame without
 * waiting (`npm run bench:studio`, scripts/bench-studio-movie.mjs). Small frames (a GIF for
 * slides, 640 × 360) are smoothed; bigger ones are as the view draws them.
 */
const FILM_SUPERSAMPLED_PIXELS = 1280 * 720;

/**
 * Frames of `look` for a movie: as {@link snapshot}'s picture (at twice the size only up to
 * {@link FILM_SUPERSAMPLED_PIXELS}), each frame drawn on the view's canvas, which keeps the
 * frames' size until {@link FilmFrames.close} (the view is not to draw meanwhile: it would draw
 * into a frame-sized canvas); `closed` is called once the view is back.
 */
export function filmFrames(view: PictureSource, look: PictureLook, closed: () => void): FilmFrames {
  const pixelRatio = view.renderer.getPixelRatio();
  const scaled = document.createElement('canvas');
  let undress: (() => void) | undefined;
  let dressedAt = 0;
  let open = true;
  const stand = turntable(view.camera, new Vector3(...view.target));
  return {
    turn: (angle) => stand.turn(angle),
    draw: (width, height) => {
      const scale = 4 * width * height <= FILM_SUPERSAMPLED_PIXELS ? pictureScale(view, width, height) : 1;
      if (scale !== dressedAt) {
        undress?.();
        undress = dress(view, look, scale);
        dressedAt = scale;
      }
      return drawSized(view, width, height, scale, look, scaled);
    },
    close: () => {
      if (open) {
        open = false;
        stand.stop();
        undress?.();
        restore(view, pixelRatio);
        closed();
      }
    },
  };
}
