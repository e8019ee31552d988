// The 3D view: one plant mesh, lights, an orbiting camera; renders on demand.
import {
  Box3,
  BufferAttribute,
  BufferGeometry,
  DirectionalLight,
  DoubleSide,
  GridHelper,
  HemisphereLight,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshStandardMaterial,
  PerspectiveCamera,
  Raycaster,
  Scene,
  Vector2,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { MeshBuffers } from '../core';
import { framePose } from './framing';
import { scenePalette } from './palette';
import { plantGeometry } from './plant-geometry';
import { highlightOverlay, moduleOfTriangle, type Rgb } from './highlight';

const DARK_SCHEME = '(prefers-color-scheme: dark)';

/**
 * Shows one plant at a time in a container element. The camera is framed on the first plant and
 * on {@link PlantView.frame}, and otherwise left where the user put it. Every new plant replaces
 * (and disposes) the previous geometry. The canvas keeps its drawing buffer so tests can read it.
 */
export class PlantView {
  private readonly renderer: WebGLRenderer;
  private readonly scene = new Scene();
  private readonly camera = new PerspectiveCamera(40, 1, 0.01, 1000);
  private readonly controls: OrbitControls;
  private readonly material = new MeshStandardMaterial({
    vertexColors: true,
    side: DoubleSide,
    roughness: 0.85,
    metalness: 0,
  });
  private readonly plant = new Mesh(new BufferGeometry(), this.material);
  /** The fallback for models too large to mesh: one coloured line per segment. */
  private readonly lines = new LineSegments(new BufferGeometry(), new LineBasicMaterial({ vertexColors: true }));
  private grid: GridHelper | undefined;
  /** The mesh on screen (its own colours and provenance ranges), for highlighting and picking. */
  private mesh: MeshBuffers | undefined;
  private readonly raycaster = new Raycaster();
  /** Highlighted modules, drawn over the plant (which is dimmed meanwhile). */
  private readonly overlay = new Mesh(
    new BufferGeometry(),
    new MeshStandardMaterial({
      vertexColors: true,
      side: DoubleSide,
      roughness: 0.7,
      metalness: 0,
      polygonOffset: true,
      polygonOffsetFactor: -1,
      polygonOffsetUnits: -1,
    }),
  );
  /** The camera has been framed on a plant with geometry; from then on it stays where the user puts it. */
  private framed = false;
  private renderQueued = false;
  private readonly darkScheme = window.matchMedia(DARK_SCHEME);
  private readonly resizeObserver: ResizeObserver;

  constructor(private readonly container: HTMLElement) {
    this.renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.domElement.setAttribute('aria-label', '3D view of the plant; drag to orbit, scroll to zoom');
    container.append(this.renderer.domElement);

    this.scene.add(new HemisphereLight(0xffffff, 0x6b5a48, 1.4));
    const headlight = new DirectionalLight(0xffffff, 1.9);
    headlight.position.set(0.6, 0.9, 0.4);
    this.camera.add(headlight, headlight.target); // a light that follows the camera
    headlight.target.position.set(0, 0, -1);
    this.scene.add(this.camera, this.plant, this.lines, this.overlay);

    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.requestRender());

    this.applyPalette();
    this.darkScheme.addEventListener('change', this.applyPalette);
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
    this.resize();
  }

  /** The bounding box of what is shown: the mesh, or the lines of the fallback. */
  private visibleBox(): Box3 {
    const geometry = this.plant.geometry.getAttribute('position') ? this.plant.geometry : this.lines.geometry;
    return geometry.boundingBox ?? new Box3();
  }

  /** Replaces the plant. The first plant with geometry is framed; later ones keep the camera. */
  showPlant(mesh: MeshBuffers): void {
    const asLines = mesh.indices.length === 0 && mesh.lines.length > 0;
    const oldMesh = this.plant.geometry;
    const oldLines = this.lines.geometry;
    this.plant.geometry = asLines ? new BufferGeometry() : plantGeometry(mesh);
    this.lines.geometry = asLines ? plantGeometry(mesh) : new BufferGeometry();
    oldMesh.dispose();
    oldLines.dispose();
    this.mesh = asLines ? undefined : mesh;
    this.colourModules(null);
    if (!this.framed && (mesh.indices.length > 0 || asLines)) {
      this.framed = true;
      this.frame();
    }
    this.requestRender();
  }

  /**
   * Paints the triangles of the modules `colourOf` names in its colour and dims the rest; `null`
   * restores the plant's own colours. (The line fallback of huge models is not highlighted.)
   */
  colourModules(colourOf: ((module: number) => Rgb | null) | null): void {
    const mesh = this.mesh;
    const old = this.overlay.geometry;
    this.overlay.geometry = new BufferGeometry();
    old.dispose();
    this.material.color.setScalar(1);
    if (mesh && colourOf) {
      const overlay = highlightOverlay(mesh, colourOf);
      const geometry = this.overlay.geometry;
      geometry.setAttribute('position', new BufferAttribute(overlay.positions, 3));
      geometry.setAttribute('normal', new BufferAttribute(overlay.normals, 3));
      geometry.setAttribute('color', new BufferAttribute(overlay.colors, 3));
      geometry.computeBoundingSphere();
      this.material.color.setScalar(0.55); // dim the rest
    }
    this.requestRender();
  }

  /** The module of the derived string drawn at a point of the page, or null (nothing there). */
  pickModule(clientX: number, clientY: number): number | null {
    const mesh = this.mesh;
    if (!mesh) return null;
    const rect = this.renderer.domElement.getBoundingClientRect();
    const ndc = new Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
    const hit = this.raycaster.intersectObject(this.plant, false)[0];
    if (!hit || hit.faceIndex == null) return null;
    return moduleOfTriangle(mesh.ranges, hit.faceIndex);
  }

  /** The canvas, for pointer events. */
  get canvas(): HTMLCanvasElement {
    return this.renderer.domElement;
  }

  /** Points the camera at the whole plant and fits the ground grid under it. */
  frame(): void {
    const box = this.visibleBox();
    const pose = framePose(box, this.camera.fov, this.camera.aspect);
    this.camera.position.copy(pose.position);
    this.camera.near = pose.near;
    this.camera.far = pose.far;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(pose.target);
    this.controls.update();
    this.placeGrid(box);
    this.requestRender();
  }

  /**
   * A PNG of the current view at `width` × `height` pixels: the same camera, lights and
   * background, the aspect ratio of the picture (the vertical field of view is kept). The canvas
   * is drawn at that size for one frame and restored before the page paints again.
   */
  async snapshot(width: number, height: number): Promise<Blob> {
    const canvas = this.renderer.domElement;
    const pixelRatio = this.renderer.getPixelRatio();
    let blob: Promise<Blob | null>;
    try {
      this.renderer.setPixelRatio(1);
      this.renderer.setSize(width, height, false);
      this.camera.aspect = width / height;
      this.camera.updateProjectionMatrix();
      this.renderer.render(this.scene, this.camera);
      // toBlob copies the bitmap now (preserveDrawingBuffer keeps it); encoding finishes later.
      blob = new Promise((resolve) => canvas.toBlob(resolve, 'image/png'));
    } finally {
      this.renderer.setPixelRatio(pixelRatio);
      this.resize();
      this.renderer.render(this.scene, this.camera);
    }
    const png = await blob;
    if (!png) throw new Error(`the browser could not encode a ${width} × ${height} PNG`);
    return png;
  }

  /** The largest picture side the GPU can draw (its renderbuffer and viewport limits). */
  maxPictureSide(): number {
    const gl = this.renderer.getContext();
    const viewport = gl.getParameter(gl.MAX_VIEWPORT_DIMS) as Int32Array;
    const renderbuffer = gl.getParameter(gl.MAX_RENDERBUFFER_SIZE) as number;
    return Math.min(viewport[0], viewport[1], renderbuffer);
  }

  /** Marks the plant as out of date (the grammar has errors) or current. */
  setStale(stale: boolean): void {
    this.container.toggleAttribute('data-stale', stale);
  }

  /** Releases the GPU resources and listeners. */
  dispose(): void {
    this.resizeObserver.disconnect();
    this.darkScheme.removeEventListener('change', this.applyPalette);
    this.controls.dispose();
    this.plant.geometry.dispose();
    this.overlay.geometry.dispose();
    this.overlay.material.dispose();
    this.lines.geometry.dispose();
    this.lines.material.dispose();
    this.material.dispose();
    this.removeGrid();
    this.renderer.dispose();
    this.renderer.domElement.remove();
  }

  private placeGrid(box: Box3): void {
    this.removeGrid();
    if (box.isEmpty()) return;
    const palette = scenePalette(this.darkScheme.matches);
    const span = Math.max(box.max.x - box.min.x, box.max.z - box.min.z, (box.max.y - box.min.y) * 0.6);
    const step = 10 ** Math.floor(Math.log10(span / 4 || 1));
    const size = Math.ceil((span * 1.6) / step) * step;
    this.grid = new GridHelper(size, Math.round(size / step), palette.gridCenter, palette.grid);
    this.grid.position.set((box.min.x + box.max.x) / 2, box.min.y, (box.min.z + box.max.z) / 2);
    this.scene.add(this.grid);
  }

  private removeGrid(): void {
    if (!this.grid) return;
    this.scene.remove(this.grid);
    this.grid.dispose();
    this.grid = undefined;
  }

  private readonly applyPalette = (): void => {
    const palette = scenePalette(this.darkScheme.matches);
    this.scene.background = palette.background;
    if (this.grid) {
      const box = this.visibleBox();
      this.placeGrid(box);
    }
    this.requestRender();
  };

  private resize(): void {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  private requestRender(): void {
    if (this.renderQueued) return;
    this.renderQueued = true;
    requestAnimationFrame(() => {
      this.renderQueued = false;
      this.renderer.render(this.scene, this.camera);
    });
  }
}
