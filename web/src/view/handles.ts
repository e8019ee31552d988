// The Bézier handles of a selected branch, drawn over the plant: its control polygon P0–P1–P2–P3,
// the attachment point P0 (small, fixed) and the draggable P1, P2 and P3, always visible (no depth
// test), sized by the plant's size.
import {
  BufferAttribute,
  BufferGeometry,
  Group,
  Line,
  LineBasicMaterial,
  Mesh,
  MeshBasicMaterial,
  SphereGeometry,
  type Raycaster,
} from 'three';

/** The handles' colours (linear RGB hex): the polygon, the attachment point, the draggable ones. */
export const HANDLE_COLOURS = { polygon: 0xff7a00, anchor: 0x2a6fdb, handle: 0xff7a00 } as const;

export class BezierHandles {
  readonly group = new Group();
  private readonly polygon = new Line(
    new BufferGeometry(),
    new LineBasicMaterial({ color: HANDLE_COLOURS.polygon, depthTest: false, transparent: true }),
  );
  private readonly spheres: Mesh[];

  constructor() {
    const sphere = new SphereGeometry(1, 16, 12);
    const anchor = new MeshBasicMaterial({ color: HANDLE_COLOURS.anchor, depthTest: false, transparent: true });
    const handle = new MeshBasicMaterial({ color: HANDLE_COLOURS.handle, depthTest: false, transparent: true });
    this.spheres = [0, 1, 2, 3].map((i) => {
      const mesh = new Mesh(sphere, i === 0 ? anchor : handle);
      mesh.renderOrder = 11;
      mesh.userData.handle = i;
      return mesh;
    });
    this.polygon.renderOrder = 10;
    this.group.add(this.polygon, ...this.spheres);
    this.group.visible = false;
  }

  /** Shows the handles at `points` (P0..P3, 12 floats), spheres of radius `radius`; null hides them. */
  show(points: Float32Array | null, radius: number): void {
    if (!points || points.length < 12) {
      this.group.visible = false;
      return;
    }
    this.polygon.geometry.setAttribute('position', new BufferAttribute(points.slice(0, 12), 3));
    this.polygon.geometry.computeBoundingSphere();
    this.spheres.forEach((s, i) => {
      s.position.set(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
      s.scale.setScalar(i === 0 ? radius * 0.7 : radius);
    });
    this.group.visible = true;
  }

  /** The draggable handle (1, 2, 3) the ray meets first, or null. */
  hit(raycaster: Raycaster): 1 | 2 | 3 | null {
    if (!this.group.visible) return null;
    const hits = raycaster.intersectObjects(this.spheres.slice(1), false);
    return hits.length > 0 ? (hits[0].object.userData.handle as 1 | 2 | 3) : null;
  }

  dispose(): void {
    this.polygon.geometry.dispose();
    this.spheres[0].geometry.dispose();
  }
}
