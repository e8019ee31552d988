// The Lines mode: every segment of the plant drawn as a line of constant width in pixels (three.js
// fat lines: each segment a screen-facing quad), as the book draws its two-dimensional figures;
// an overlay of highlighted segments, and picking by the segment under the pointer.
import { Group, InstancedInterleavedBuffer, InterleavedBufferAttribute, type Raycaster } from 'three';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { LineSegments2 } from 'three/examples/jsm/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/examples/jsm/lines/LineSegmentsGeometry.js';
import type { MeshBuffers } from '../core';
import type { LineOverlay } from './highlight';
import { pointsBox, setBox } from './plant-geometry';

/** The width of the lines a studio opens with, in CSS pixels. */
export const DEFAULT_LINE_WIDTH = 2;
/** The narrowest and widest line offered, in pixels. */
export const LINE_WIDTH_MIN = 0.5;
export const LINE_WIDTH_MAX = 20;

/** A line width read from text: a number from {@link LINE_WIDTH_MIN} to {@link LINE_WIDTH_MAX}, or null. */
export function lineWidthOf(text: string): number | null {
  const value = Number(text.trim());
  return text.trim() !== '' && Number.isFinite(value) && value >= LINE_WIDTH_MIN && value <= LINE_WIDTH_MAX ? value : null;
}

/** How much wider than the plant's lines the highlighted ones are drawn, in pixels. */
const HIGHLIGHT_EXTRA = 1.5;

function lineSegments(width: number): LineSegments2 {
  const material = new LineMaterial({ vertexColors: true, linewidth: width, worldUnits: false });
  return new LineSegments2(new LineSegmentsGeometry(), material);
}

/** Sets `ends` and `colors` (two 3-float ends per segment) as the lines' geometry, replacing the old. */
function setLines(lines: LineSegments2, ends: Float32Array, colors: Float32Array): void {
  lines.geometry.dispose();
  const geometry = new LineSegmentsGeometry();
  if (ends.length >= 6) {
    setEnds(geometry, ends);
    geometry.setColors(colors);
  }
  lines.geometry = geometry;
  lines.visible = ends.length >= 6;
}

/**
 * `geometry.setPositions(ends)`, with the bounds from one pass over the ends (a box, and the sphere
 * around it) instead of its two (an exact box, then an exact sphere): 116,050 segments took 14 ms
 * of the page's thread that way. The sphere only has to hold every segment (culling, picking).
 */
function setEnds(geometry: LineSegmentsGeometry, ends: Float32Array): void {
  const instances = new InstancedInterleavedBuffer(ends, 6, 1); // start xyz, end xyz
  geometry.setAttribute('instanceStart', new InterleavedBufferAttribute(instances, 3, 0));
  geometry.setAttribute('instanceEnd', new InterleavedBufferAttribute(instances, 3, 3));
  geometry.instanceCount = ends.length / 6;
  setBox(geometry, pointsBox(ends));
}

/**
 * The plant's segments as lines, and the highlighted ones over them. Add {@link group} to the
 * scene; it shows nothing until {@link show} is given a mesh with segments.
 */
export class SegmentLines {
  readonly group = new Group();
  private readonly plant: LineSegments2;
  private readonly overlay: LineSegments2;
  private modules: Uint32Array = new Uint32Array(0);
  private width = DEFAULT_LINE_WIDTH;
  /**
   * Segments given to {@link show} while the lines were hidden: their geometry is made when the
   * lines are first shown (a big plant's takes tens of milliseconds, wasted in the Tubes mode).
   */
  private unmade: Pick<MeshBuffers, 'segmentEnds' | 'segmentColors'> | null = null;

  constructor() {
    this.plant = lineSegments(this.width);
    this.overlay = lineSegments(this.width + HIGHLIGHT_EXTRA);
    // Over the plant's lines whatever their depth: a highlight is never hidden behind them.
    this.overlay.material.depthTest = false;
    this.overlay.renderOrder = 1;
    this.group.add(this.plant, this.overlay);
    this.show(null);
  }

  /** Shows `mesh`'s segments (null: none), without highlight; while the lines are hidden, once they are shown. */
  show(mesh: Pick<MeshBuffers, 'segmentEnds' | 'segmentColors' | 'segmentModules'> | null): void {
    const empty = new Float32Array(0);
    this.unmade = { segmentEnds: mesh?.segmentEnds ?? empty, segmentColors: mesh?.segmentColors ?? empty };
    if (this.group.visible) this.make();
    else setLines(this.plant, empty, empty); // the old plant's lines go now
    this.modules = mesh?.segmentModules ?? new Uint32Array(0);
    this.highlight(null, 1);
  }

  /** Makes the geometry of the segments {@link show} was last given. */
  private make(): void {
    if (!this.unmade) return;
    setLines(this.plant, this.unmade.segmentEnds, this.unmade.segmentColors);
    this.unmade = null;
  }

  /** Draws `overlay`'s lines over the plant (null: none) and the plant's own at brightness `dim`. */
  highlight(overlay: LineOverlay | null, dim: number): void {
    const empty = new Float32Array(0);
    setLines(this.overlay, overlay?.ends ?? empty, overlay?.colors ?? empty);
    this.plant.material.color.setScalar(dim);
  }

  /** The lines' width in pixels (CSS pixels on screen; picture pixels in a snapshot). */
  get lineWidth(): number {
    return this.width;
  }

  set lineWidth(width: number) {
    this.width = width;
    this.plant.material.linewidth = width;
    this.overlay.material.linewidth = width + HIGHLIGHT_EXTRA;
  }

  /** Whether the lines are drawn. */
  set visible(on: boolean) {
    this.group.visible = on;
    if (on) this.make();
  }

  get visible(): boolean {
    return this.group.visible;
  }

  /**
   * The module of the segment `raycaster` (set from a camera) meets within the line's width, and
   * the hit's distance from the eye; null when it meets none or the lines are hidden.
   */
  pick(raycaster: Raycaster): { module: number; distance: number } | null {
    if (!this.group.visible || !this.plant.visible) return null;
    const hit = raycaster.intersectObject(this.plant, false)[0];
    if (!hit || hit.faceIndex == null || hit.faceIndex >= this.modules.length) return null;
    return { module: this.modules[hit.faceIndex], distance: hit.distance };
  }

  dispose(): void {
    for (const lines of [this.plant, this.overlay]) {
      lines.geometry.dispose();
      lines.material.dispose();
    }
  }
}
