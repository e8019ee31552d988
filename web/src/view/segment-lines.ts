// The Lines mode: every segment of the plant drawn as a line of constant width in pixels (three.js
// fat lines, `LineMaterial`: each segment a screen-facing quad with round ends, drawn without
// instancing by ./texel-lines.ts), as the book draws its two-dimensional figures; an overlay of
// highlighted segments, and picking by the segment under the pointer (./segment-pick.ts).
import { BufferAttribute, BufferGeometry, Group, LineBasicMaterial, LineSegments, type OrthographicCamera, type PerspectiveCamera, type Raycaster, type Vector2 } from 'three';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import type { MeshBuffers } from '../core';
import type { LineGrowth } from './line-growth';
import type { LineOverlay } from './highlight';
import { pointsBox, setBox } from './plant-geometry';
import { pickSegment } from './segment-pick';
import { TexelLines } from './texel-lines';

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
export const HIGHLIGHT_EXTRA = 1.5;

function lineMaterial(width: number): LineMaterial {
  return new LineMaterial({ vertexColors: true, linewidth: width, worldUnits: false });
}

/**
 * The plant's segments as lines, and the highlighted ones over them. Add {@link group} to the
 * scene; it shows nothing until {@link show} is given a mesh with segments. `maxTextureSize`: the
 * GPU's, which bounds the segments {@link TexelLines} can draw (two million or more); a plant of
 * more is drawn with lines one pixel wide.
 */
export class SegmentLines {
  readonly group = new Group();
  /** What WebGL draws of them (see {@link drawn}). */
  private readonly drawables = new Group();
  /** The plant's lines, and the highlighted ones (drawn over them); ./line-growth.ts makes them grow. */
  readonly plant: TexelLines;
  readonly overlay: TexelLines;
  /** The plant's segments when {@link plant} cannot hold them: one pixel wide. */
  private readonly thin = new LineSegments(new BufferGeometry(), new LineBasicMaterial({ vertexColors: true }));
  /** The segments drawn (start xyz, end xyz each), for picking. */
  private ends: Float32Array = new Float32Array(0);
  private modules: Uint32Array = new Uint32Array(0);
  /** The growth times of the segments drawn (two a segment), and of the highlighted ones. */
  times: Float32Array | undefined;
  overTimes: Float32Array | undefined;
  /** The growth in time, once the growth's chunk is there (./line-growth.ts `LineGrowth.attach`). */
  growth: LineGrowth | undefined;
  private width = DEFAULT_LINE_WIDTH;
  /**
   * Segments given to {@link show} while WebGL did not draw the lines (hidden, or not {@link drawn}):
   * their geometry is made when it first does (a big plant's takes tens of milliseconds, wasted in
   * the Tubes mode, or while the view draws the lines in 2D).
   */
  private unmade: Pick<MeshBuffers, 'segmentEnds' | 'segmentColors'> | null = null;
  /** The highlight given to {@link highlight} while WebGL did not draw the lines, drawn as {@link unmade} is. */
  private unmadeOverlay: { overlay: LineOverlay | null } | null = null;

  constructor(maxTextureSize?: number) {
    this.plant = new TexelLines(lineMaterial(this.width), maxTextureSize);
    this.overlay = new TexelLines(lineMaterial(this.width + HIGHLIGHT_EXTRA), maxTextureSize);
    // Over the plant's lines whatever their depth: a highlight is never hidden behind them.
    this.overlay.mesh.material.depthTest = false;
    this.overlay.mesh.renderOrder = 1;
    // The viewport's size (for picking) is taken when either is drawn.
    this.thin.onBeforeRender = this.plant.mesh.onBeforeRender;
    this.drawables.add(this.plant.mesh, this.thin, this.overlay.mesh);
    this.group.add(this.drawables);
    this.show(null);
  }

  /**
   * Whether WebGL draws the lines (false: the view draws them otherwise, ./sketch-canvas.ts, with
   * {@link setViewport} told the viewport's size; they are still picked).
   */
  set drawn(on: boolean) {
    this.drawables.visible = on;
    this.make();
  }

  /** Whether WebGL draws the lines now: they are shown and {@link drawn}. */
  private get drawnByWebGl(): boolean {
    return this.group.visible && this.drawables.visible;
  }

  /** The viewport's size in CSS pixels, for picking while the lines are not {@link drawn} (a frame that draws them sets it). */
  setViewport(width: number, height: number): void {
    this.plant.mesh.material.resolution.set(width, height);
  }

  /**
   * Shows `mesh`'s segments (null: none), without highlight, {@link drawn} by WebGL or not; while
   * the lines are hidden, once they are shown.
   */
  show(mesh: Pick<MeshBuffers, 'segmentEnds' | 'segmentColors' | 'segmentModules' | 'segmentGrowthTimes'> | null, drawn = this.drawables.visible): void {
    const empty = new Float32Array(0);
    this.drawables.visible = drawn;
    this.ends = mesh?.segmentEnds ?? empty; // picked, whoever draws them
    this.times = mesh?.segmentGrowthTimes;
    this.unmade = { segmentEnds: this.ends, segmentColors: mesh?.segmentColors ?? empty };
    if (this.drawnByWebGl) this.make();
    else this.setPlant(empty, empty); // the old plant's lines go now
    this.modules = mesh?.segmentModules ?? new Uint32Array(0);
    this.highlight(null, 1);
  }

  /** Makes the geometry of the segments and highlight last given, if WebGL draws them now. */
  private make(): void {
    if (!this.drawnByWebGl) return;
    if (this.unmade) this.setPlant(this.unmade.segmentEnds, this.unmade.segmentColors);
    if (this.unmadeOverlay) this.setOverlay(this.unmadeOverlay.overlay);
    this.unmade = this.unmadeOverlay = null;
  }

  /**
   * `ends` and `colors` (two 3-float ends per segment) as the plant's lines, with bounds from one
   * pass over the ends (a box, and the sphere around it; an exact box, then an exact sphere took
   * 14 ms of the page's thread for 116,050 segments): the sphere only has to hold every segment.
   */
  private setPlant(ends: Float32Array, colors: Float32Array): void {
    const box = pointsBox(ends);
    const fits = this.plant.fits(ends.length / 6);
    this.plant.setSegments(fits ? ends : new Float32Array(0), colors, box);
    // (The times are those of the segments last shown: of `ends`, or none are drawn.)
    this.growth?.times(this.plant, fits && ends.length ? this.times : undefined);
    if (!fits || this.thin.visible) {
      this.thin.geometry.dispose();
      this.thin.geometry = new BufferGeometry();
    }
    if (!fits) {
      this.thin.geometry.setAttribute('position', new BufferAttribute(ends, 3));
      this.thin.geometry.setAttribute('color', new BufferAttribute(colors, 3));
      setBox(this.thin.geometry, box);
    }
    this.thin.visible = !fits;
  }

  /**
   * Draws `overlay`'s lines over the plant (null: none; nor one of more segments than a texture
   * holds, see {@link TexelLines.fits}) and the plant's own at brightness `dim`.
   */
  highlight(overlay: LineOverlay | null, dim: number): void {
    this.unmadeOverlay = { overlay };
    if (this.drawnByWebGl) this.make();
    else this.setOverlay(null); // the old highlight goes now
    this.plant.mesh.material.color.setScalar(dim);
    this.thin.material.color.setScalar(dim);
  }

  private setOverlay(overlay: LineOverlay | null): void {
    const ends = overlay && this.overlay.fits(overlay.ends.length / 6) ? overlay.ends : new Float32Array(0);
    this.overlay.setSegments(ends, overlay?.colors ?? new Float32Array(0), pointsBox(ends));
    this.overTimes = ends.length > 0 ? overlay?.times : undefined;
    this.growth?.times(this.overlay, this.overTimes);
  }

  /** The lines' width in pixels (CSS pixels on screen; picture pixels in a snapshot). */
  get lineWidth(): number {
    return this.width;
  }

  set lineWidth(width: number) {
    this.width = width;
    this.plant.mesh.material.linewidth = width;
    this.overlay.mesh.material.linewidth = width + HIGHLIGHT_EXTRA;
  }

  /** Whether the lines are drawn. */
  set visible(on: boolean) {
    this.group.visible = on;
    this.make();
  }

  get visible(): boolean {
    return this.group.visible;
  }

  /**
   * The module of the segment `raycaster` (set from a camera) meets within the line's width (or a
   * few pixels beside it, ./segment-pick.ts), and the hit's distance from the eye; null when it
   * meets none or the lines are hidden. `tubes`: the segments are drawn as tubes (whose triangles
   * the pointer missed) in a viewport of that size in CSS pixels: the segment whose axis passes
   * within a few pixels, lines shown or not. (The group is never moved: the segments' coordinates
   * are the world's.)
   */
  pick(raycaster: Raycaster, tubes?: Vector2): { module: number; distance: number } | null {
    const camera = raycaster.camera as PerspectiveCamera | OrthographicCamera | null;
    if ((!tubes && !this.group.visible) || !camera || this.modules.length === 0) return null;
    // One pixel wide where WebGL draws them with `thin`; as wide as chosen otherwise (2D draws that width).
    const width = tubes ? 0 : this.thin.visible && this.drawables.visible ? 1 : this.width;
    // (At a growth time, the segments as grown then.)
    const resolution = tubes ?? this.plant.mesh.material.resolution;
    const hit = pickSegment(this.growth?.grown(this.ends, this.times) ?? this.ends, camera, raycaster.ray, width, resolution);
    if (!hit || hit.segment >= this.modules.length) return null;
    return { module: this.modules[hit.segment], distance: hit.distance };
  }

  dispose(): void {
    this.growth?.dispose(this.plant, this.overlay);
    this.plant.dispose();
    this.overlay.dispose();
    this.thin.geometry.dispose();
    for (const material of [this.plant.mesh.material, this.overlay.mesh.material, this.thin.material]) material.dispose();
  }
}
