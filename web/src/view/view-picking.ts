// Points of the page and the scene: what is drawn at a point (a module, a triangle, a handle),
// where a drag goes, and where a model point is on the page.
import { Plane, Raycaster, Vector2, Vector3, type Camera } from 'three';
import { MATERIAL_BARK, moduleOfTriangle } from './highlight';
import type { SegmentLines } from './segment-lines';
import type { ShownPlant } from './shown-plant';

/** Picks in the view drawn on `canvas` through the camera in use (`camera()`). */
export class ViewPicking {
  private readonly raycaster = new Raycaster();

  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly camera: () => Camera,
  ) {}

  /** The page point as normalised device coordinates of the canvas, set on the raycaster. */
  aim(clientX: number, clientY: number): Raycaster {
    const rect = this.canvas.getBoundingClientRect();
    const ndc = new Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera());
    return this.raycaster;
  }

  /**
   * The module of `plant`'s mesh drawn at a point of the page, or null; `lines`: its segments are
   * drawn as `segmentLines` (the Lines mode).
   */
  module(clientX: number, clientY: number, plant: ShownPlant, lines: boolean, segmentLines: SegmentLines): number | null {
    const mesh = plant.mesh;
    if (!mesh) return null;
    const raycaster = this.aim(clientX, clientY);
    // In the Lines mode the tubes' triangles are not drawn: only leaves, polygons and spheres count.
    const hit = raycaster
      .intersectObject(plant.pickable, false)
      .find((h) => h.faceIndex != null && (!lines || moduleOfTriangle(mesh.materialRanges, h.faceIndex) !== MATERIAL_BARK));
    // A thin tube is hard to hit: the pointer a few pixels beside its axis picks it too.
    const line = lines ? segmentLines.pick(raycaster) : hit ? null : segmentLines.pick(raycaster, this.viewport());
    if (line && (!hit || line.distance <= hit.distance)) return line.module;
    return hit?.faceIndex != null ? moduleOfTriangle(mesh.ranges, hit.faceIndex) : null;
  }

  /** The canvas's size in CSS pixels. */
  private viewport(): Vector2 {
    const rect = this.canvas.getBoundingClientRect();
    return new Vector2(rect.width, rect.height);
  }

  /** The triangle of `plant`'s mesh at a point of the page, or null. */
  triangle(clientX: number, clientY: number, plant: ShownPlant): number | null {
    if (!plant.mesh) return null;
    const hit = this.aim(clientX, clientY).intersectObject(plant.pickable, false)[0];
    return hit && hit.faceIndex != null ? hit.faceIndex : null;
  }

  /** Where a point of the page meets the plane through `through` facing the camera (a drag's target). */
  dragTarget(clientX: number, clientY: number, through: [number, number, number]): [number, number, number] | null {
    const raycaster = this.aim(clientX, clientY);
    const normal = this.camera().getWorldDirection(new Vector3());
    const plane = new Plane().setFromNormalAndCoplanarPoint(normal, new Vector3(...through));
    const point = raycaster.ray.intersectPlane(plane, new Vector3());
    return point ? [point.x, point.y, point.z] : null;
  }

  /** A model point's place on the page (CSS pixels). */
  pageOf(point: [number, number, number]): { x: number; y: number } {
    const rect = this.canvas.getBoundingClientRect();
    const p = new Vector3(...point).project(this.camera());
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }
}
