// The plant on screen: the mesh drawn from the GPU's buffers, its plain twin that raycasting reads,
// and the coloured lines of a plant drawn as lines (a sketch, a model too large to mesh).
import { Box3, BufferGeometry, LineBasicMaterial, LineSegments, Mesh, type Material } from 'three';
import type { MeshBuffers } from '../core';
import type { BufferPool, GpuGeometry } from './gpu-geometry';
import { growthSpanOf } from './growth-arrays';
import { plantGeometry, pointsBox, setBox } from './plant-geometry';
import type { IncomingPlant, PlantUpload } from './plant-upload';

/** The plant shown by the view, replaced whole by each new one. */
export class ShownPlant {
  /** The plant drawn: its geometry is a {@link GpuGeometry}'s (or empty). */
  readonly drawn: Mesh<BufferGeometry, Material | Material[]>;
  /** The buffers {@link drawn} draws from. */
  private onGpu: GpuGeometry | undefined;
  /**
   * The plant drawn, as plain arrays: what raycasting reads (three.js cannot read the GPU's
   * buffers back). Never drawn, not in the scene; its material is the plant's (for the groups).
   */
  readonly pickable: Mesh<BufferGeometry, Material | Material[]>;
  /** The fallback for models too large to mesh, and sketches: one coloured line per segment. */
  readonly lines: LineSegments<BufferGeometry, LineBasicMaterial>;
  /** The mesh on screen (its own colours and provenance ranges), for highlighting and picking; none for lines. */
  mesh: MeshBuffers | undefined;
  /** The plant on screen lies in the plane z = 0. */
  flat = false;
  /** The box of the plant's segments (drawn as lines in the Lines mode), once asked for. */
  private segmentsBox: Box3 | undefined;
  /** N when the plant carries growth arrays (./growth-arrays.ts), else null. */
  growthSpan: number | null = null;

  /** `material`: the plant's until {@link material} is set. */
  constructor(material: Material) {
    this.drawn = new Mesh<BufferGeometry, Material | Material[]>(new BufferGeometry(), material);
    this.pickable = new Mesh<BufferGeometry, Material | Material[]>(new BufferGeometry(), material);
    this.lines = new LineSegments(new BufferGeometry(), new LineBasicMaterial({ vertexColors: true }));
  }

  /** Draws the plant (and picks in it) with `material` (one, or one per material group). */
  set material(material: Material | Material[]) {
    this.drawn.material = material;
    this.pickable.material = material;
  }

  /** Puts a plant (its geometry on the GPU, or its lines) in place of the old one, and disposes the old one's. */
  replace({ mesh, flat, source, onGpu }: IncomingPlant): void {
    const asLines = onGpu === undefined;
    this.mesh = asLines ? undefined : mesh;
    const oldMesh = this.drawn.geometry;
    const oldOnGpu = this.onGpu;
    const oldPickable = this.pickable.geometry;
    const oldLines = this.lines.geometry;
    this.drawn.geometry = onGpu?.geometry ?? new BufferGeometry();
    this.onGpu = onGpu;
    this.pickable.geometry = source ?? new BufferGeometry();
    this.lines.geometry = asLines ? plantGeometry(mesh) : new BufferGeometry();
    if (oldOnGpu) oldOnGpu.dispose();
    else oldMesh.dispose();
    oldPickable.dispose();
    oldLines.dispose();
    this.flat = flat;
    this.segmentsBox = undefined;
    // With the segments' times: the Lines mode's lines grow by them (the mesh may hold no vertex).
    this.growthSpan = growthSpanOf(mesh.growthTimes, mesh.segmentGrowthTimes);
  }

  /** Whether a plant drawn as lines, one pixel wide, is on screen (a plant too large to mesh, a sketch). */
  get asThinLines(): boolean {
    return this.lines.geometry.getAttribute('position') !== undefined;
  }

  /** The normals on the GPU: the mesh's floats, or the worker's packed ones (its floats are then empty). */
  get normalsOnGpu(): Float32Array | Int16Array | undefined {
    return this.pickable.geometry.getAttribute('normal')?.array as Float32Array | Int16Array | undefined;
  }

  /**
   * The bounding box of what is shown: the mesh, or the lines of the fallback; with the segments
   * when they are drawn as lines (`usesLines`: the mesh then has no tubes, maybe nothing).
   */
  box(usesLines: boolean): Box3 {
    const geometry = this.drawn.geometry.getAttribute('position') ? this.drawn.geometry : this.lines.geometry;
    const box = geometry.boundingBox ?? new Box3();
    if (!usesLines || !this.mesh) return box;
    this.segmentsBox ??= pointsBox(this.mesh.segmentEnds);
    return box.clone().union(this.segmentsBox);
  }

  /**
   * After vertices of the mesh last given (the one on its way to the GPU, `incoming`, if any, else
   * the one on screen) were changed in place (its arrays are the geometry's): uploads only `ranges`
   * ((first vertex, count) pairs) and updates the bounds.
   */
  patchVertices(ranges: Uint32Array, incoming: IncomingPlant | undefined): void {
    const { mesh, source, onGpu } = incoming ?? { mesh: this.mesh, source: this.pickable.geometry, onGpu: this.onGpu };
    if (!mesh || !source || !onGpu) return;
    for (const [name, array, size] of [
      ['position', mesh.positions, 3],
      ['normal', mesh.normals, 3],
      ['uv', mesh.uvs, 2],
      ['growthOrigin', mesh.growthOrigins, 3],
    ] as const) {
      // (Packed normals are not the mesh's: a mesh with them is not edited.)
      if (!array || source.getAttribute(name)?.array !== array) continue;
      for (let k = 0; k + 1 < ranges.length; k += 2) onGpu.patch(name, size * ranges[k], size * ranges[k + 1]);
    }
    setBox(source, pointsBox(mesh.positions));
    setBox(onGpu.geometry, source.boundingBox!);
  }

  /** The context is back: the plant goes to the GPU again from its arrays. */
  restored(upload: PlantUpload): void {
    if (!this.onGpu) return;
    this.onGpu = upload.again(this.onGpu, this.pickable.geometry);
    this.drawn.geometry = this.onGpu.geometry;
  }

  /** Gives the GPU's buffers back to `buffers` and clears it (the view is disposed), and disposes the rest. */
  dispose(buffers: BufferPool): void {
    this.onGpu?.dispose();
    buffers.clear();
    this.drawn.geometry.dispose();
    this.pickable.geometry.dispose();
    this.lines.geometry.dispose();
    this.lines.material.dispose();
  }
}

