// The ground grid: squares of a round size under the plant in 3D, behind it in 2D.
import { GridHelper, LineBasicMaterial, type Box3, type Material, type Scene } from 'three';
import type { ScenePalette } from './palette';

/** The view's grid, made again for each plant (its size follows the plant's), shown or hidden. */
export class GroundGrid {
  private grid: GridHelper | undefined;
  /**
   * The material of every grid (GridHelper's own, kept): a new plant gets a new grid, and a new
   * material would make WebGL link its program again, 5-10 ms of the first frame of each edit.
   */
  readonly material = new LineBasicMaterial({ vertexColors: true, toneMapped: false });
  private shown = true;

  constructor(private readonly scene: Scene) {}

  /** Whether a grid is placed (there is a plant). */
  get placed(): boolean {
    return this.grid !== undefined;
  }

  /**
   * A grid of round-numbered squares: on the ground under the plant in 3D; in 2D (`flat`) behind
   * it, in the plane of the drawing, its centre line at the plant's base.
   */
  place(box: Box3, flat: boolean, palette: ScenePalette): void {
    this.remove();
    if (box.isEmpty()) return;
    // In 2D the grid's centre line is the ground: it must reach the plant's top above it.
    const span = flat
      ? Math.max(box.max.x - box.min.x, 2 * (box.max.y - box.min.y))
      : Math.max(box.max.x - box.min.x, box.max.z - box.min.z, (box.max.y - box.min.y) * 0.6);
    const step = 10 ** Math.floor(Math.log10(span / 4 || 1));
    const size = Math.ceil((span * 1.6) / step) * step;
    this.grid = new GridHelper(size, Math.round(size / step), palette.gridCenter, palette.grid);
    (this.grid.material as Material).dispose(); // never drawn: no program to release
    this.grid.material = this.material;
    if (flat) {
      this.grid.rotation.x = Math.PI / 2;
      const depth = Math.max(box.max.z - box.min.z, span * 1e-3);
      this.grid.position.set((box.min.x + box.max.x) / 2, box.min.y, box.min.z - depth);
    } else {
      this.grid.position.set((box.min.x + box.max.x) / 2, box.min.y, (box.min.z + box.max.z) / 2);
    }
    this.grid.visible = this.shown;
    this.scene.add(this.grid);
  }

  private remove(): void {
    if (!this.grid) return;
    this.scene.remove(this.grid);
    this.grid.geometry.dispose(); // its material is kept for the next grid
    this.grid = undefined;
  }

  /** Whether the grid is shown (now and for the next plants). */
  get visible(): boolean {
    return this.shown;
  }

  set visible(visible: boolean) {
    this.shown = visible;
    if (this.grid) this.grid.visible = visible;
  }

  dispose(): void {
    this.remove();
    this.material.dispose();
  }
}
