// What the view draws in 2D over its WebGL canvas where a software rasterizer draws it
// (./sketch-canvas.ts): a plant drawn as one-pixel lines (a sketch, a model too large to mesh),
// and in the Lines mode a big plant's segments.
import { Vector2, type Camera } from 'three';
import type { MeshBuffers } from '../core';
import type { LineOverlay } from './highlight';
import type { RenderTarget } from './render-target';
import { HIGHLIGHT_EXTRA, type SegmentLines } from './segment-lines';
import { SketchCanvas } from './sketch-canvas';

/**
 * Segments from which, where a software rasterizer draws the view, the Lines mode draws a plant in
 * 2D over it (./sketch-canvas.ts): SwiftShader takes about 3 µs a segment every frame for the
 * WebGL lines (ABOP 1.24d at n = 10, 116,050 segments: about 0.3 s a frame, each time the camera
 * moves), the 2D canvas a fifth of that or less. Smaller plants are WebGL's, as on a GPU.
 */
const LINES_IN_2D_FROM = 50_000;

/** The 2D canvas over a view drawn by a software rasterizer, and what it shows. */
export class View2D {
  private readonly canvas: SketchCanvas;
  /** The Lines mode's segments are drawn here, not by WebGL ({@link placeLines}). */
  private segmentsHere = false;
  /** The plant drawn here as one-pixel lines (a sketch, a model too large to mesh). */
  private thin: MeshBuffers | undefined;
  /** The Lines mode's highlighted segments (drawn over the others) and the others' brightness. */
  private segmentHighlight: { over: LineOverlay | null; dim: number } = { over: null, dim: 1 };
  private readonly drawingBufferSize = new Vector2();

  constructor(
    container: HTMLElement,
    private readonly target: RenderTarget,
    private readonly segmentLines: SegmentLines,
  ) {
    this.canvas = new SketchCanvas(container);
  }

  /** Whether anything is drawn in 2D. */
  get active(): boolean {
    return this.canvas.active;
  }

  /** Whether the Lines mode's segments are drawn in 2D. */
  get linesIn2D(): boolean {
    return this.segmentsHere;
  }

  /** Whether the Lines mode's segments of `mesh` are to be drawn in 2D: it has enough of them. */
  wants(mesh: MeshBuffers | undefined): boolean {
    return (mesh?.segmentEnds.length ?? 0) >= 6 * LINES_IN_2D_FROM;
  }

  /**
   * A new plant: clears what was drawn, and shows `lines`'s one-pixel lines if it is a plant drawn
   * as lines (else undefined); true if it shows them.
   */
  showPlant(lines: MeshBuffers | undefined): boolean {
    this.canvas.clear();
    this.segmentsHere = false;
    this.thin = lines?.lines.length ? lines : undefined;
    return this.thinIn2D(true);
  }

  /**
   * Draws the one-pixel lines shown here (`on`), or leaves those with growth times to WebGL (while
   * a growth time is shown: the growth's shader grows them there). True if they are drawn here now.
   */
  thinIn2D(on: boolean): boolean {
    const thin = this.thin;
    if (!thin) return false;
    const here = on || !thin.segmentGrowthTimes;
    // (Shown again only when it changes: each frame of the growth played asks.)
    if (here && !this.canvas.active) this.canvas.show(thin.lines, thin.lineColors);
    if (!here) this.canvas.clear();
    return here;
  }

  /** The Lines mode's highlight, for {@link placeLines}. */
  highlight(highlight: { over: LineOverlay | null; dim: number }): void {
    this.segmentHighlight = highlight;
  }

  /**
   * Draws the Lines mode's segments of `mesh` in 2D, in their width, brightness and highlight; or,
   * with no mesh, takes them away. True if they are drawn (a frame is due).
   */
  placeLines(mesh: MeshBuffers | undefined): boolean {
    if (!mesh) {
      if (this.segmentsHere) this.canvas.clear();
      this.segmentsHere = false;
      return false;
    }
    // The canvas's pixels are the drawing buffer's; the widths are in CSS pixels.
    const ratio = this.target.pixelRatio();
    const width = this.segmentLines.lineWidth;
    const { over, dim } = this.segmentHighlight;
    // Round ends and corners as WebGL draws them, where they show: for lines of a few pixels
    // Skia's round joins cost more than the difference (1,048,576 segments 2 pixels wide: 733
    // against 511 ms a frame without a GPU).
    const style = { width: width * ratio, round: width * ratio > 4, dim };
    if (!this.segmentsHere) this.canvas.show(mesh.segmentEnds, mesh.segmentColors, style);
    this.canvas.restyle(style, over && { ends: over.ends, colors: over.colors, width: (width + HIGHLIGHT_EXTRA) * ratio });
    this.segmentsHere = true;
    return true;
  }

  /** What is drawn in 2D as `camera` sees it now. */
  draw(camera: Camera): void {
    if (!this.canvas.active) return;
    camera.updateMatrixWorld();
    const { x, y } = this.target.drawingBufferSize(this.drawingBufferSize);
    this.canvas.draw(camera, x, y);
    if (this.segmentsHere) this.segmentLines.setViewport(this.target.canvas.clientWidth, this.target.canvas.clientHeight);
  }

  /** Takes everything drawn away. */
  clear(): void {
    this.canvas.clear();
  }
}
