// Stages: several plants side by side in one picture (iterations a … b of a grammar, and rows of
// specimens grown with different seeds), each drawn by an orthographic camera looking the same way,
// at one scale (or each fitted to its tile), standing on a common baseline, with a caption under each (see
// stages-layout.ts). Flat plants are seen face-on; 3D plants a little from the side and above,
// like the studio's first view of them. Drawn on demand into its own canvas; a picture of any size
// comes out as a PNG with the captions. With `orbit` (the Variants view), dragging turns the one
// camera about the plants and the wheel zooms: every tile turns and zooms together.
import { Box3, Group, LineBasicMaterial, LineSegments, Mesh, OrthographicCamera, Scene, Vector2, Vector3, WebGLRenderer, type BufferGeometry, type Object3D } from 'three';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import type { Bounds, GpuArrays, MeshBuffers } from '../core';
import { scenePalette } from './palette';
import { lineGeometry, plantGeometry } from './plant-geometry';
import { addHeadlight, addSkyLight, litPlantMaterial, unlitPlantMaterial } from './scene-setup';
import type { PictureLook } from './snapshot';
import { captionHeight, stageTiles, type StageScale, type StageTile, type ViewExtent } from './stages-layout';
import { TexelLines } from './texel-lines';

const DARK_SCHEME = '(prefers-color-scheme: dark)';

/** One plant of the figure. */
export interface StagePlant {
  /** Its mesh; `null` when there is nothing to draw (the caption says why). */
  mesh: MeshBuffers | null;
  /** Its normals and colours packed for the GPU, when the mesh comes without them (from the build worker). */
  gpu?: GpuArrays;
  /**
   * Its segments as lines, drawn inside the tubes: a plant drawn small keeps its branches a pixel
   * wide where its tubes would be thinner than a pixel (and vanish).
   */
  lines: { lines: Float32Array; lineColors: Float32Array } | null;
  flat: boolean;
  bounds: Bounds;
  /** The caption under it, e.g. `n = 3`. */
  caption: string;
}

/**
 * A caption set in `room` pixels: on one line at `size` pixels where it fits; else broken after a
 * colon or before a parenthesis (`n = 0` over `(nothing drawn)`), at the largest size up to `size`
 * its widest line fits at (`width`: a text's width at a size).
 */
export function fittedCaption(caption: string, size: number, room: number, width: (text: string, size: number) => number): { lines: string[]; size: number } {
  const lines = width(caption, size) <= room ? [caption] : caption.split(/(?<=:) | (?=\()/);
  const widest = Math.max(...lines.map((line) => width(line, size)));
  return { lines, size: widest > room ? Math.max(1, (size * room) / widest) : size };
}

/** The height of a caption's line, in sizes of its font. */
const CAPTION_LEADING = 1.15;

/** Share of a tile's width a caption may take. */
const CAPTION_ROOM = 0.94;

/** The figure's layout: how many plants across and down (the plants are given row by row), and their scale. */
export interface StagesGrid {
  columns: number;
  rows: number;
  scale: StageScale;
}

export class StagesView {
  private readonly renderer: WebGLRenderer;
  private readonly scene = new Scene();
  private readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0.01, 1000);
  private readonly lit = litPlantMaterial();
  private readonly unlit = unlitPlantMaterial();
  private readonly lineMaterial = new LineBasicMaterial({ vertexColors: true });
  private plants: { object: Object3D | null; extent: ViewExtent | null; bounds: Bounds; caption: string; lines?: TexelLines }[] = [];
  /** The lines' width in CSS pixels when the plants are drawn as lines (as the view's Lines mode), else null: tubes. */
  private lineWidth: number | null = null;
  private readonly measure = document.createElement('canvas').getContext('2d');
  /** Where the camera looks from: the plants' centre, their radius, the unit direction to the eye. */
  private aim = { centre: new Vector3(), radius: 1, direction: new Vector3(0, 0, 1) };
  /** The zoom of every tile about its centre (1: the plants just fit). */
  private zoom = 1;
  private grid: StagesGrid = { columns: 1, rows: 1, scale: 'one' };
  private lighting = true;
  private renderQueued = false;
  private readonly captions: HTMLElement;
  private readonly darkScheme = window.matchMedia(DARK_SCHEME);
  private readonly resizeObserver: ResizeObserver;

  constructor(
    private readonly container: HTMLElement,
    options: { orbit?: boolean } = {},
  ) {
    this.renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true, alpha: true }); // (alpha: a transparent PNG)
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.domElement.setAttribute('aria-hidden', 'true');
    this.captions = document.createElement('div');
    this.captions.className = 'stage-captions';
    container.append(this.renderer.domElement, this.captions);
    addSkyLight(this.scene);
    addHeadlight(this.camera);
    this.scene.add(this.camera);
    this.darkScheme.addEventListener('change', this.requestRender);
    // A context the browser took away and gave back: three.js has made its state again; draw.
    this.renderer.domElement.addEventListener('webglcontextrestored', this.requestRender);
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
    this.resize();
    if (options.orbit) this.listenForOrbit();
  }

  /**
   * Shows `plants` (row by row) in a `grid`; replaces (and disposes) what was shown. With a
   * `lineWidth` (CSS pixels) their segments are drawn as lines that wide in every stage, however
   * each is scaled (as the view's Lines mode draws them); without, as tubes.
   */
  show(plants: readonly StagePlant[], grid: StagesGrid, lineWidth: number | null = null): void {
    this.clear();
    this.grid = grid;
    this.lineWidth = lineWidth;
    const flat = plants.every((p) => p.flat || !p.mesh);
    this.aimCamera(plants, flat);
    this.plants = plants.map((plant) => {
      if (!plant.mesh) return { object: null, extent: null, bounds: plant.bounds, caption: plant.caption };
      if (lineWidth !== null && plant.lines && plant.lines.lines.length > 0) return { ...this.asLines(plant.lines, plant.bounds, lineWidth), bounds: plant.bounds, caption: plant.caption };
      const geometry = plantGeometry(plant.mesh, plant.gpu, plant.bounds);
      const asLines = plant.mesh.indices.length === 0 && plant.mesh.lines.length > 0;
      const object = new Group();
      object.add(asLines ? new LineSegments(geometry, this.lineMaterial) : new Mesh(geometry, this.material()));
      if (!asLines && plant.lines && plant.lines.lines.length > 0) object.add(new LineSegments(lineGeometry(plant.lines), this.lineMaterial));
      object.visible = false;
      this.scene.add(object);
      return { object, extent: this.extent(plant.bounds), bounds: plant.bounds, caption: plant.caption };
    });
    this.showCaptions();
    this.requestRender();
  }

  /** `lines` drawn `width` CSS pixels wide, hidden until its tile is drawn. */
  private asLines(lines: NonNullable<StagePlant['lines']>, bounds: Bounds, width: number): { object: Object3D; extent: ViewExtent; lines: TexelLines } {
    const drawn = new TexelLines(new LineMaterial({ vertexColors: true, linewidth: width, worldUnits: false }), this.renderer.capabilities.maxTextureSize);
    drawn.setSegments(lines.lines, lines.lineColors, new Box3(new Vector3(...bounds[0]), new Vector3(...bounds[1])));
    drawn.mesh.visible = false;
    this.scene.add(drawn.mesh);
    return { object: drawn.mesh, extent: this.extent(bounds), lines: drawn };
  }

  /** Replaces the captions of the plants shown (row by row); the plants and the camera stay. */
  setCaptions(captions: readonly (string | undefined)[]): void {
    this.plants.forEach((plant, i) => (plant.caption = captions[i] ?? plant.caption));
    this.showCaptions();
  }

  /** Shades the plants (on) or shows the palette's colours as they are (off), like the 3D view. */
  setLighting(lit: boolean): void {
    this.lighting = lit;
    for (const { object, lines } of this.plants) if (!lines) object?.traverse((part) => part instanceof Mesh && (part.material = this.material()));
    this.requestRender();
  }

  /**
   * Turns the one camera about the plants' centre: `azimuth` radians about the vertical, `elevation`
   * radians up (kept short of straight up or down); every tile turns with it.
   */
  orbit(azimuth: number, elevation: number): void {
    const { direction } = this.aim;
    const up = Math.max(-1.45, Math.min(1.45, Math.asin(Math.max(-1, Math.min(1, direction.y))) + elevation));
    const around = Math.atan2(direction.x, direction.z) + azimuth;
    direction.set(Math.cos(up) * Math.sin(around), Math.sin(up), Math.cos(up) * Math.cos(around));
    this.placeCamera();
    for (const plant of this.plants) if (plant.object) plant.extent = this.extent(plant.bounds);
    this.placeCaptions();
    this.requestRender();
  }

  /** Zooms every tile by `factor` about its centre (more than 1: closer), from 1/20 to 50 times. */
  zoomBy(factor: number): void {
    this.zoom = Math.max(0.05, Math.min(50, this.zoom * factor));
    this.requestRender();
  }

  /**
   * The figure as a PNG of `width` × `height` pixels, captions included: the same tiles as on
   * screen, laid out for that size, on the `background` asked for; `scale` pixels of the picture
   * a CSS pixel of the screen (its lines' width and the captions' least size).
   */
  async picture(width: number, height: number, { background, scale }: { background: PictureLook['background']; scale: number }): Promise<Blob> {
    const pixelRatio = this.renderer.getPixelRatio();
    const canvas = document.createElement('canvas');
    canvas.width = width;
    canvas.height = height;
    const context = canvas.getContext('2d');
    if (!context) throw new Error('the browser has no 2D canvas to draw the picture on');
    try {
      this.renderer.setPixelRatio(1);
      this.renderer.setSize(width, height, false);
      this.setLineWidth(scale);
      const tiles = this.draw(width, height, background, scale);
      context.drawImage(this.renderer.domElement, 0, 0);
      const size = captionHeight(height, this.grid.rows, scale) * 0.55;
      context.textAlign = 'center';
      context.fillStyle = background === 'view' && this.darkScheme.matches ? '#e6edf3' : '#1f2328';
      const font = (px: number) => `${px}px system-ui, sans-serif`;
      tiles.forEach((tile, i) => {
        const fitted = fittedCaption(this.plants[i].caption, size, tile.viewport.width * CAPTION_ROOM, (text, px) => ((context.font = font(px)), context.measureText(text).width));
        context.font = font(fitted.size);
        // The last line on the caption's baseline, the others above it.
        fitted.lines.forEach((line, k) => context.fillText(line, tile.caption.x, tile.caption.y - (fitted.lines.length - 1 - k) * fitted.size * CAPTION_LEADING));
      });
    } finally {
      this.setLineWidth(1);
      this.renderer.setPixelRatio(pixelRatio);
      this.resize();
    }
    const png = await new Promise<Blob | null>((resolve) => canvas.toBlob(resolve, 'image/png'));
    if (!png) throw new Error(`the browser could not encode a ${width} × ${height} PNG`);
    return png;
  }

  /** The canvas on the page (its pixels are the figure, without the captions, which are HTML). */
  get canvas(): HTMLCanvasElement {
    return this.renderer.domElement;
  }

  /** Releases the GPU context and the plants. */
  dispose(): void {
    this.clear();
    this.resizeObserver.disconnect();
    this.darkScheme.removeEventListener('change', this.requestRender);
    this.lit.dispose();
    this.unlit.dispose();
    this.lineMaterial.dispose();
    this.renderer.dispose();
    this.renderer.forceContextLoss();
    this.renderer.domElement.remove();
    this.captions.remove();
  }

  private material() {
    return this.lighting ? this.lit : this.unlit;
  }

  private clear(): void {
    for (const { object, lines } of this.plants) {
      if (!object) continue;
      this.scene.remove(object);
      if (lines) (lines.dispose(), lines.mesh.material.dispose());
      else object.traverse((part) => (part instanceof Mesh || part instanceof LineSegments) && (part.geometry as BufferGeometry).dispose());
    }
    this.plants = [];
  }

  /**
   * Points the camera the way every tile is seen: face-on for flat plants; for 3D ones across
   * the thinner horizontal side of all the plants together, a little from the side and above.
   */
  private aimCamera(plants: readonly StagePlant[], flat: boolean): void {
    const all = new Box3();
    for (const p of plants) if (p.mesh) all.union(new Box3(new Vector3(...p.bounds[0]), new Vector3(...p.bounds[1])));
    const size = all.isEmpty() ? new Vector3(1, 1, 1) : all.getSize(new Vector3());
    const centre = all.isEmpty() ? new Vector3() : all.getCenter(new Vector3());
    const radius = Math.max(size.length() / 2, 1e-6);
    const across = flat ? new Vector3(0, 0, 1) : size.z <= size.x ? new Vector3(0.25, 0.18, 1) : new Vector3(1, 0.18, -0.25);
    this.aim = { centre, radius, direction: across.normalize() };
    this.zoom = 1;
    this.placeCamera();
  }

  /** The camera where {@link aim} puts it, looking at the plants' centre. */
  private placeCamera(): void {
    const { centre, radius, direction } = this.aim;
    this.camera.position.copy(centre).addScaledVector(direction, radius * 3);
    this.camera.up.set(0, 1, 0);
    this.camera.lookAt(centre);
    this.camera.near = radius * 0.5;
    this.camera.far = radius * 6;
    this.camera.updateMatrixWorld();
  }

  /**
   * Dragging on the figure turns the camera (half a turn across its width); the wheel zooms; with
   * the figure focused, the arrow keys turn it and + and − zoom.
   */
  private listenForOrbit(): void {
    const canvas = this.renderer.domElement;
    const step = Math.PI / 24;
    const keys: Record<string, () => void> = {
      ArrowLeft: () => this.orbit(step, 0),
      ArrowRight: () => this.orbit(-step, 0),
      ArrowUp: () => this.orbit(0, step),
      ArrowDown: () => this.orbit(0, -step),
      '+': () => this.zoomBy(1.25),
      '=': () => this.zoomBy(1.25),
      '-': () => this.zoomBy(0.8),
    };
    this.container.tabIndex = 0;
    this.container.addEventListener('keydown', (event) => {
      const key = keys[event.key];
      if (!key || event.altKey || event.ctrlKey || event.metaKey) return;
      event.preventDefault();
      key();
    });
    canvas.style.touchAction = 'none';
    let last: { x: number; y: number; id: number } | undefined;
    canvas.addEventListener('pointerdown', (event) => {
      last = { x: event.clientX, y: event.clientY, id: event.pointerId };
      canvas.setPointerCapture(event.pointerId);
    });
    canvas.addEventListener('pointermove', (event) => {
      if (!last || event.pointerId !== last.id) return;
      const turn = Math.PI / Math.max(1, this.container.clientWidth);
      this.orbit(-(event.clientX - last.x) * turn, (event.clientY - last.y) * turn);
      last = { ...last, x: event.clientX, y: event.clientY };
    });
    const release = () => (last = undefined);
    canvas.addEventListener('pointerup', release);
    canvas.addEventListener('pointercancel', release);
    canvas.addEventListener(
      'wheel',
      (event) => {
        event.preventDefault();
        this.zoomBy(Math.exp(-Math.max(-100, Math.min(100, event.deltaY)) * 0.002));
      },
      { passive: false },
    );
  }

  /** A box's extent in the camera's view plane. */
  private extent(bounds: Bounds): ViewExtent {
    const extent = { minX: Infinity, maxX: -Infinity, minY: Infinity, maxY: -Infinity };
    const corner = new Vector3();
    for (let c = 0; c < 8; c++) {
      corner.set(bounds[c & 1][0], bounds[(c >> 1) & 1][1], bounds[(c >> 2) & 1][2]).applyMatrix4(this.camera.matrixWorldInverse);
      extent.minX = Math.min(extent.minX, corner.x);
      extent.maxX = Math.max(extent.maxX, corner.x);
      extent.minY = Math.min(extent.minY, corner.y);
      extent.maxY = Math.max(extent.maxY, corner.y);
    }
    return extent;
  }

  /** The lines drawn `scale` times the width chosen (a picture's pixels a CSS pixel). */
  private setLineWidth(scale: number): void {
    for (const { lines } of this.plants) if (lines && this.lineWidth !== null) lines.mesh.material.linewidth = this.lineWidth * scale;
  }

  /**
   * Draws every tile into the renderer's canvas of `width` × `height` CSS pixels on `background`
   * (`scale`: the picture's pixels a CSS pixel, for the captions' band); returns the tiles.
   */
  private draw(width: number, height: number, background: PictureLook['background'] = 'view', pixels = 1): StageTile[] {
    const { columns, rows, scale } = this.grid;
    const tiles = stageTiles(this.plants.map((p) => p.extent), columns, rows, width, height, scale, pixels);
    const renderer = this.renderer;
    this.scene.background = null;
    renderer.setScissorTest(false);
    renderer.setClearColor(background === 'view' ? scenePalette(this.darkScheme.matches).background : 0xffffff, background === 'transparent' ? 0 : 1);
    renderer.clear();
    renderer.setScissorTest(true);
    tiles.forEach((tile, i) => {
      const { object } = this.plants[i];
      if (!object) return;
      // WebGL counts viewport rows from the bottom.
      const { x, y, width: w, height: h } = tile.viewport;
      const bottom = height - y - h;
      renderer.setViewport(x, bottom, w, h);
      renderer.setScissor(x, bottom, w, h);
      const { left, right, top, bottom: low } = tile.frustum;
      const [midX, midY, half] = [(left + right) / 2, (top + low) / 2, 0.5 / this.zoom];
      Object.assign(this.camera, { left: midX - (right - left) * half, right: midX + (right - left) * half, top: midY + (top - low) * half, bottom: midY - (top - low) * half });
      this.camera.updateProjectionMatrix();
      object.visible = true;
      renderer.autoClear = false;
      renderer.render(this.scene, this.camera);
      renderer.autoClear = true;
      object.visible = false;
    });
    renderer.setScissorTest(false);
    renderer.setViewport(0, 0, width, height);
    return tiles;
  }

  /** The captions as HTML over the canvas, where the tiles put them on screen. */
  private showCaptions(): void {
    this.captions.replaceChildren(
      ...this.plants.map(({ caption }) => {
        const label = document.createElement('span');
        label.className = 'stage-caption';
        label.textContent = caption;
        return label;
      }),
    );
    this.placeCaptions();
  }

  private placeCaptions(): void {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    const { columns, rows, scale } = this.grid;
    const tiles = stageTiles(this.plants.map((p) => p.extent), columns, rows, width, height, scale);
    const font = captionHeight(height, rows) * 0.55;
    const measure = this.measure;
    [...this.captions.children].forEach((label, i) => {
      const style = (label as HTMLElement).style;
      style.left = `${tiles[i].caption.x}px`;
      style.top = `${tiles[i].caption.y}px`;
      // As large as the band allows; broken in two, and smaller, where a long caption (`n = 0 (nothing drawn)`) would pass its tile.
      const caption = this.plants[i].caption;
      const fitted = measure
        ? fittedCaption(caption, font, tiles[i].viewport.width * CAPTION_ROOM, (text, px) => ((measure.font = `${px}px system-ui, sans-serif`), measure.measureText(text).width))
        : { lines: [caption], size: font };
      label.textContent = fitted.lines.join('\n');
      style.fontSize = `${fitted.size}px`;
      style.lineHeight = String(CAPTION_LEADING);
    });
  }

  private resize(): void {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height, false);
    this.placeCaptions();
    this.requestRender();
  }

  private readonly requestRender = (): void => {
    if (this.renderQueued) return;
    this.renderQueued = true;
    requestAnimationFrame(() => {
      this.renderQueued = false;
      // In CSS pixels, as the renderer's viewports are (it scales them by its pixel ratio).
      const size = this.renderer.getSize(new Vector2());
      this.draw(size.x, size.y);
    });
  };
}
