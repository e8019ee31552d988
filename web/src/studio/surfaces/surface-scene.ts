// The surface editor's 3D view: one declared surface in the turtle's frame at scale 1 (x along L,
// y along H: up the screen, z along U: toward the viewer), tessellated as the plant draws it (the
// core's mesh), its 4 × 4 control nets as points and lines, the contact point with the turtle's
// heading and up, the end point if declared; an orbit camera. Drawn on demand. Each patch's front
// and back are in the colours the plant draws them with (the core's answer).
import {
  AmbientLight,
  ArrowHelper,
  BufferAttribute,
  BufferGeometry,
  Color,
  BackSide,
  DirectionalLight,
  FrontSide,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshStandardMaterial,
  PerspectiveCamera,
  Points,
  PointsMaterial,
  Ray,
  Scene,
  Vector2,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { Point3, SurfacePreview } from '../../core';

/** The colours of the view: the net, the selected point, the turtle's axes. */
const COLOURS = { net: 0xff7a00, selected: 0x1769d1, heading: 0x2e7d32, up: 0x1769d1, contact: 0x111111, end: 0x8e24aa } as const;

/** Moving a point: in the plane facing the camera, or along one axis of the written points (a direction in the view). */
export type DragAxis = null | Vector3;

/** The scene of one surface on `canvas`. */
export class SurfaceScene {
  private readonly renderer: WebGLRenderer;
  private readonly scene = new Scene();
  private readonly camera = new PerspectiveCamera(40, 1, 0.001, 1000);
  private readonly controls: OrbitControls;
  /** The surface's fronts and backs, each side in its own colours. */
  private readonly sides = [FrontSide, BackSide].map((side) => new Mesh(new BufferGeometry(), new MeshStandardMaterial({ vertexColors: true, side, roughness: 0.7 })));
  private readonly lines = new LineSegments(new BufferGeometry(), new LineBasicMaterial({ color: COLOURS.net, depthTest: false, transparent: true, opacity: 0.8 }));
  private readonly points = new Points(new BufferGeometry(), new PointsMaterial({ color: COLOURS.net, size: 9, sizeAttenuation: false, depthTest: false }));
  private readonly selection = new Points(new BufferGeometry(), new PointsMaterial({ color: COLOURS.selected, size: 15, sizeAttenuation: false, depthTest: false }));
  private readonly contact = new Points(new BufferGeometry(), new PointsMaterial({ color: COLOURS.contact, size: 11, sizeAttenuation: false, depthTest: false }));
  private readonly heading = new ArrowHelper(new Vector3(0, 1, 0), new Vector3(), 0.3, COLOURS.heading);
  private readonly up = new ArrowHelper(new Vector3(0, 0, 1), new Vector3(), 0.15, COLOURS.up);
  private readonly endPoint = new Points(new BufferGeometry(), new PointsMaterial({ color: COLOURS.end, size: 10, sizeAttenuation: false, depthTest: false }));
  private net: Point3[] = [];
  private framedFor = '';
  private frameRequested = false;
  private readonly resize: ResizeObserver;

  constructor(readonly canvas: HTMLCanvasElement) {
    this.renderer = new WebGLRenderer({ canvas, antialias: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.scene.background = new Color(0xf4f6f8);
    const light = new DirectionalLight(0xffffff, 2.2);
    light.position.set(0.6, 1, 1.4);
    this.camera.add(light); // a light that turns with the camera: the side looked at is always lit
    this.scene.add(this.camera, new AmbientLight(0xffffff, 0.9), ...this.sides, this.lines, this.points, this.selection, this.contact, this.heading, this.up, this.endPoint);
    this.lines.renderOrder = 10;
    this.points.renderOrder = 11;
    this.selection.renderOrder = 12;
    this.contact.geometry.setAttribute('position', new BufferAttribute(new Float32Array(3), 3));
    // The turtle's axes and the contact point are drawn over the surface, never hidden by it.
    for (const arrow of [this.heading, this.up]) {
      for (const part of [arrow.line, arrow.cone]) {
        part.renderOrder = 13;
        Object.assign(part.material, { depthTest: false, transparent: true });
      }
    }
    this.contact.renderOrder = 14;
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.addEventListener('change', () => this.requestFrame());
    this.resize = new ResizeObserver(() => this.fit());
    this.resize.observe(canvas);
  }

  /** Shows `surface` with its net and `selected` point; the camera frames it when its letter is new. */
  show(surface: SurfacePreview, selected: number | null): void {
    this.showMesh(surface);
    this.net = surface.net.map((p) => [...p]);
    this.drawNet();
    this.select(selected);
    const end = surface.end;
    this.endPoint.visible = !!end;
    if (end) this.endPoint.geometry.setAttribute('position', new BufferAttribute(Float32Array.from(end), 3));
    if (this.framedFor !== surface.letter) {
      this.framedFor = surface.letter;
      this.frame();
    }
  }

  /** Shows `surface`'s tessellation alone (while a drag moves the net itself). */
  showMesh(surface: SurfacePreview): void {
    const position = new BufferAttribute(surface.positions, 3);
    const normal = new BufferAttribute(surface.normals, 3);
    const index = new BufferAttribute(surface.indices, 1);
    this.sides.forEach((mesh, side) => {
      mesh.geometry.dispose();
      const geometry = new BufferGeometry();
      geometry.setAttribute('position', position);
      geometry.setAttribute('normal', normal);
      geometry.setAttribute('color', new BufferAttribute(vertexColours(surface, side), 3));
      geometry.setIndex(index);
      mesh.geometry = geometry;
    });
    this.requestFrame();
  }

  /** Moves net point `k` (and its copies `also`) to `point` at once, before the core's mesh follows. */
  movePoint(indices: readonly number[], point: Point3): void {
    for (const k of indices) if (this.net[k]) this.net[k] = [...point];
    this.drawNet();
    this.requestFrame();
  }

  /** Marks net point `k` (null: none). */
  select(k: number | null): void {
    const p = k === null ? undefined : this.net[k];
    this.selection.visible = !!p;
    if (p) this.selection.geometry.setAttribute('position', new BufferAttribute(Float32Array.from(p), 3));
    this.requestFrame();
  }

  /** The net point drawn nearest the page point, within `radius` CSS pixels, or null. */
  pointAt(clientX: number, clientY: number, radius: number): number | null {
    let best: number | null = null;
    let bestDistance = radius;
    this.net.forEach((p, k) => {
      const page = this.pageOf(p);
      const d = Math.hypot(page.x - clientX, page.y - clientY);
      if (d <= bestDistance) [best, bestDistance] = [k, d];
    });
    return best;
  }

  /** A point of the view's frame on the page (CSS pixels). */
  pageOf(point: Point3): { x: number; y: number } {
    const rect = this.canvas.getBoundingClientRect();
    const p = new Vector3(...point).project(this.camera);
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }

  /**
   * Where a drag from `through` goes under the page point: in the plane through it facing the
   * camera, or (`axis`, a direction) the point of that line nearest the pointer's ray.
   */
  dragTarget(clientX: number, clientY: number, through: Point3, axis: DragAxis): Point3 | null {
    const ray = this.rayAt(clientX, clientY);
    const origin = new Vector3(...through);
    if (axis) {
      const d = axis.clone().normalize();
      // The closest points of two lines: origin + s·d and ray.origin + t·ray.direction.
      const w = origin.clone().sub(ray.origin);
      const b = d.dot(ray.direction);
      const denominator = 1 - b * b;
      if (denominator < 1e-6) return null; // the axis points at the camera
      const s = (b * w.dot(ray.direction) - w.dot(d)) / denominator;
      const p = origin.addScaledVector(d, s);
      return [p.x, p.y, p.z];
    }
    const normal = this.camera.getWorldDirection(new Vector3());
    const denominator = ray.direction.dot(normal);
    if (Math.abs(denominator) < 1e-6) return null;
    const t = origin.clone().sub(ray.origin).dot(normal) / denominator;
    if (t < 0) return null;
    const p = ray.at(t, new Vector3());
    return [p.x, p.y, p.z];
  }

  /** Lets the pointer turn the camera, or not (while a point is dragged). */
  set orbiting(on: boolean) {
    this.controls.enabled = on;
  }

  /** Frames the surface and the turtle's axes. */
  frame(): void {
    const all = [...this.net, [0, 0.3, 0] as Point3];
    const centre = new Vector3();
    for (const p of all) centre.add(new Vector3(...p));
    centre.divideScalar(all.length);
    const radius = Math.max(0.05, ...all.map((p) => centre.distanceTo(new Vector3(...p))));
    const distance = (radius / Math.sin((this.camera.fov * Math.PI) / 360)) * 1.15;
    this.controls.target.copy(centre);
    this.camera.position.copy(centre).add(new Vector3(0.35, 0.25, 1).normalize().multiplyScalar(distance));
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.heading.setLength(radius * 0.6, radius * 0.12, radius * 0.06);
    this.up.setLength(radius * 0.3, radius * 0.08, radius * 0.04);
    this.controls.update();
    this.requestFrame();
  }

  /** Draws at the next frame (once however often it is asked). */
  requestFrame(): void {
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame(() => {
      this.frameRequested = false;
      this.renderer.render(this.scene, this.camera);
    });
  }

  dispose(): void {
    this.resize.disconnect();
    this.controls.dispose();
    for (const o of [...this.sides, this.lines, this.points, this.selection, this.contact, this.endPoint]) o.geometry.dispose();
    this.renderer.dispose();
  }

  private rayAt(clientX: number, clientY: number): Ray {
    const rect = this.canvas.getBoundingClientRect();
    const ndc = new Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    const origin = new Vector3().setFromMatrixPosition(this.camera.matrixWorld);
    const direction = new Vector3(ndc.x, ndc.y, 0.5).unproject(this.camera).sub(origin).normalize();
    return new Ray(origin, direction);
  }

  /** The net's points and its grid lines: each patch's rows and columns. */
  private drawNet(): void {
    const points = Float32Array.from(this.net.flat());
    this.points.geometry.setAttribute('position', new BufferAttribute(points, 3));
    const segments: number[] = [];
    for (let patch = 0; patch + 16 <= this.net.length; patch += 16) {
      for (let i = 0; i < 4; i++) {
        for (let j = 0; j < 3; j++) {
          segments.push(...this.net[patch + 4 * i + j], ...this.net[patch + 4 * i + j + 1]); // along a row
          segments.push(...this.net[patch + 4 * j + i], ...this.net[patch + 4 * (j + 1) + i]); // along a column
        }
      }
    }
    this.lines.geometry.setAttribute('position', new BufferAttribute(Float32Array.from(segments), 3));
    this.points.geometry.computeBoundingSphere();
    this.lines.geometry.computeBoundingSphere();
  }

  /** The canvas's drawing buffer follows its size on the page. */
  private fit(): void {
    const { clientWidth: w, clientHeight: h } = this.canvas;
    if (w === 0 || h === 0) return;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestFrame();
  }
}

/** Leaf green, the plant's colour for an organ before any colour is chosen: what shows until the core says. */
const LEAF: Point3 = [0.2, 0.58, 0.16];

/**
 * A colour per vertex of `surface`'s tessellation for its front (`side` 0) or back: each patch's
 * grid of (s + 1) × (t + 1) points in the patch's colour.
 */
function vertexColours(surface: SurfacePreview, side: number): Float32Array {
  const [s, t] = surface.precision;
  const perPatch = (s + 1) * (t + 1);
  const out = new Float32Array(surface.positions.length);
  for (let v = 0; v < out.length / 3; v++) out.set(surface.colors[Math.floor(v / perPatch)]?.[side] ?? LEAF, 3 * v);
  return out;
}
