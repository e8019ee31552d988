// The 3D view: one plant mesh, lights, an orbiting perspective camera or a face-on orthographic
// one for flat plants, an optional ground grid; renders on demand.
import {
  Box3,
  BufferAttribute,
  BufferGeometry,
  Color,
  DoubleSide,
  GridHelper,
  Group,
  LineBasicMaterial,
  LineSegments,
  Material,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  OrthographicCamera,
  PerspectiveCamera,
  Plane,
  Raycaster,
  Scene,
  Spherical,
  MathUtils,
  Vector3,
  Vector2,
  WebGLRenderer,
  type Camera,
} from 'three';
import type { Bounds, GpuArrays, MeshBuffers } from '../core';
import { CameraControls, loadOrbitControls } from './camera-controls';
import { drawnBySoftware } from './rasterizer';
import { flatPose, framePose } from './framing';
import { scenePalette } from './palette';
import { plantGeometry, pointsBox, setBox } from './plant-geometry';
import { BufferPool, GpuGeometry } from './gpu-geometry';
import { loadTexture, texturedMaterials, type TexturedMaterials } from './textures';
import { addHeadlight, addSkyLight, atLeastAPixelWide, drawnSupersampled, litPlantMaterial, unlitPlantMaterial } from './scene-setup';
import { MATERIAL_BARK, highlightOverlay, highlightSegments, moduleOfTriangle, type LineOverlay, type Rgb } from './highlight';
import { DEFAULT_LINE_WIDTH, HIGHLIGHT_EXTRA, SegmentLines } from './segment-lines';
import { BezierHandles } from './handles';
import { SketchCanvas } from './sketch-canvas';

const DARK_SCHEME = '(prefers-color-scheme: dark)';


/** `perspective`: orbit in 3D; `orthographic`: the XY plane face-on (2D), pan and zoom only. */
export type Projection = 'perspective' | 'orthographic';

/** How the projection is chosen: from the plant (`auto`: flat plants in 2D), or fixed by the user. */
export type ProjectionMode = 'auto' | Projection;

/**
 * How branches are drawn: `lines` of constant width in pixels (as the book's 2D figures), `tubes`
 * of the grammar's widths, or `auto`: lines for plants drawn in one plane, tubes for 3D ones.
 */
export type RenderMode = 'auto' | 'lines' | 'tubes';

/** A picture's look: its background (the view's, white or none), and the lines' width in its pixels. */
export interface PictureLook {
  background: 'view' | 'white' | 'transparent';
  /** The Lines mode's width in the picture's pixels (default: the view's, in CSS pixels). */
  lineWidth?: number;
}

/** A camera's place: eye, the point it looks at (the orbit's centre), and the orthographic zoom. */
export interface ViewPose {
  position: [number, number, number];
  target: [number, number, number];
  zoom: number;
}

/**
 * A new plant goes to the GPU (see {@link GpuGeometry}) in slices of this many bytes, as many per
 * task as fit in {@link UPLOAD_TASK_MS}. A slice takes under 1 ms of the page's thread when the GPU
 * keeps up, and tens of ms when it does not (software GPU on a loaded machine, traced): small
 * slices keep such a wait short. A plant of at most {@link UPLOAD_AT_ONCE_BYTES} goes up whole and
 * is shown at once.
 */
const UPLOAD_SLICE_BYTES = 2 << 20;
const UPLOAD_TASK_MS = 8;
const UPLOAD_AT_ONCE_BYTES = 8 << 20;

/**
 * Segments from which, where a software rasterizer draws the view, the Lines mode draws a plant in
 * 2D over it (./sketch-canvas.ts): SwiftShader takes about 3 µs a segment every frame for the
 * WebGL lines (ABOP 1.24d at n = 10, 116,050 segments: about 0.3 s a frame, each time the camera
 * moves), the 2D canvas a fifth of that or less. Smaller plants are WebGL's, as on a GPU.
 */
const LINES_IN_2D_FROM = 50_000;

/** A plant for the screen: its mesh and, unless drawn as lines, its geometry (plain and on the GPU). */
interface IncomingPlant {
  mesh: MeshBuffers;
  flat: boolean;
  source?: BufferGeometry;
  onGpu?: GpuGeometry;
}

/**
 * Runs `task` in a task of its own, at once: ahead of other tasks where `scheduler.postTask` exists
 * (the user is waiting for the plant), else by a message (a `setTimeout` chain waits 4 ms a call
 * after five).
 */
function nextTask(task: () => void): void {
  const scheduler = (globalThis as { scheduler?: { postTask?: (task: () => void, options: { priority: string }) => Promise<unknown> } }).scheduler;
  if (scheduler?.postTask) {
    void scheduler.postTask(task, { priority: 'user-blocking' });
    return;
  }
  const channel = new MessageChannel();
  channel.port1.onmessage = () => {
    channel.port1.close();
    task();
  };
  channel.port2.postMessage(null);
}

/**
 * The view's renderer: multisampled (4× MSAA) where a GPU draws, not on a software rasterizer (a
 * machine without a usable GPU: {@link drawnBySoftware}), where multisampling costs more than the
 * rest of each frame. On SwiftShader, 1.24d at n = 10 in the Tubes mode: the GPU done with the
 * edited tree 1.9–2.3 s after a keystroke with it, 0.7–0.8 s without, and the tubes drawn
 * 276–368 ms → 212–235 ms (the upload waits for the sketch's frame; `npm run bench:studio`).
 * Its tubes still draw at least a pixel wide (`atLeastAPixelWide`), and pictures are drawn at
 * twice their size and scaled down ({@link PlantView.snapshot}). On such a machine the context is
 * made twice: the first tells the rasterizer. The Stages view and the gallery's thumbnails keep
 * multisampling everywhere: they draw few, small plants, mostly as lines one pixel wide, which a
 * picture scaled down would fade. `software` says which it is (the view draws its sketches in 2D
 * there: {@link PlantView.showSketch}).
 */
function viewRenderer(): { renderer: WebGLRenderer; software: boolean } {
  const options = { preserveDrawingBuffer: true, alpha: true };
  const renderer = new WebGLRenderer({ ...options, antialias: true });
  if (!drawnBySoftware(renderer.getContext())) return { renderer, software: false };
  renderer.dispose();
  renderer.forceContextLoss();
  return { renderer: new WebGLRenderer({ ...options, antialias: false }), software: true };
}

/** `source` drawn into a new canvas of `width` × `height` (smoothed: a 2:1 scale averages each 2 × 2 pixels). */
function scaledDown(source: HTMLCanvasElement, width: number, height: number): HTMLCanvasElement {
  const canvas = document.createElement('canvas');
  [canvas.width, canvas.height] = [width, height];
  const context = canvas.getContext('2d');
  if (!context) throw new Error(`the browser could not make a ${width} × ${height} canvas for the picture`);
  context.imageSmoothingQuality = 'high';
  context.drawImage(source, 0, 0, width, height);
  return canvas;
}

/** One of the two cameras with its controls and whether it has been framed on a plant yet. */
interface CameraRig<C extends PerspectiveCamera | OrthographicCamera> {
  camera: C;
  controls: CameraControls;
  framed: boolean;
}

/**
 * Shows one plant at a time in a container element. The view follows the plant: each new plant is
 * framed, unless the user has moved the camera since the last fit (then {@link onRefitHint}'s
 * listeners hear that the plant may have left the frame) or the frame is held
 * ({@link holdFrame}: while branches are edited, while Play shows the growth in one frame).
 * {@link frame} fits the plant on screen and follows again. Every new plant replaces (and
 * disposes) the previous geometry. The canvas keeps its drawing buffer so tests can read it.
 *
 * The container gets `data-projection` (`perspective` | `orthographic`) for styling and tests.
 */
export class PlantView {
  private readonly renderer: WebGLRenderer;
  /** The box of the plant's segments (drawn as lines in the Lines mode), once asked for. */
  private segmentsBox: Box3 | undefined;
  private readonly scene = new Scene();
  private readonly perspective: CameraRig<PerspectiveCamera>;
  private readonly orthographic: CameraRig<OrthographicCamera>;
  private active: CameraRig<PerspectiveCamera> | CameraRig<OrthographicCamera>;
  private readonly lit = litPlantMaterial();
  private readonly unlit = unlitPlantMaterial();
  /** Bark and leaf textured materials ([bark, leaf, plain], by the mesh's material groups). */
  private readonly textured: TexturedMaterials;
  private lighting = true;
  private texturing = true;
  /** Images loaded so far (of 2): the plant shows untextured until both are there. */
  private texturesLoaded = 0;
  /** The plant drawn: its geometry is a {@link GpuGeometry}'s (or empty). */
  private readonly plant = new Mesh<BufferGeometry, Material | Material[]>(new BufferGeometry(), this.lit);
  /** The buffers {@link plant} draws from. */
  private plantOnGpu: GpuGeometry | undefined;
  /** WebGL buffers of plants replaced, for the next plants' arrays. */
  private readonly gpuBuffers: BufferPool;
  /**
   * The plant drawn, as plain arrays: what raycasting reads (three.js cannot read the GPU's
   * buffers back). Never drawn, not in the scene; its material is the plant's (for the groups).
   */
  private readonly pickable = new Mesh<BufferGeometry, Material | Material[]>(new BufferGeometry(), this.lit);
  /** A plant on its way to the GPU; the one on screen stays until its last slice is there. */
  private incoming: IncomingPlant | undefined;
  /** The fallback for models too large to mesh, and sketches: one coloured line per segment. */
  private readonly lines = new LineSegments(new BufferGeometry(), new LineBasicMaterial({ vertexColors: true }));
  /**
   * Where a software rasterizer draws the view: what is drawn in 2D over it, a sketch
   * ({@link showSketch}) or a big plant's lines in the Lines mode ({@link placeLines}).
   */
  private readonly canvas2D: SketchCanvas | undefined;
  /** The Lines mode's segments are drawn on {@link canvas2D}, not by WebGL ({@link placeLines}). */
  private linesIn2D = false;
  /** The Lines mode's highlighted segments (drawn over the others) and the others' brightness. */
  private segmentHighlight: { over: LineOverlay | null; dim: number } = { over: null, dim: 1 };
  private readonly drawingBufferSize = new Vector2();
  private grid: GridHelper | undefined;
  /**
   * The material of every grid (GridHelper's own, kept): a new plant gets a new grid, and a new
   * material would make WebGL link its program again, 5-10 ms of the first frame of each edit.
   */
  private readonly gridMaterial = new LineBasicMaterial({ vertexColors: true, toneMapped: false });
  private gridVisible = true;
  /** The mesh on screen (its own colours and provenance ranges), for highlighting and picking. */
  private mesh: MeshBuffers | undefined;
  private readonly raycaster = new Raycaster();
  /** Highlighted modules, drawn over the plant (which is dimmed meanwhile). */
  private readonly overlay = new Mesh(
    new BufferGeometry(),
    atLeastAPixelWide(
      new MeshStandardMaterial({
        vertexColors: true,
        side: DoubleSide,
        roughness: 0.7,
        metalness: 0,
        polygonOffset: true,
        polygonOffsetFactor: -1,
        polygonOffsetUnits: -1,
      }),
    ),
  );
  /** The Lines mode's segments (hidden while tubes are drawn). */
  private readonly segmentLines: SegmentLines;
  private lineWidthChosen = DEFAULT_LINE_WIDTH;
  private lineScale = 1;
  /** Stands in for the tubes' material in the Lines mode: their triangles are not drawn. */
  private readonly hiddenTubes = new MeshBasicMaterial({ visible: false });
  private renderMode: RenderMode = 'auto';
  /** Who needs tubes now whatever the mode (branch editing reshapes tubes). */
  private readonly tubeHolders = new Set<string>();
  /**
   * The last highlight asked for (of the plant last given: a new plant clears it), redrawn when
   * the render mode changes and when a plant that was uploading comes on screen.
   */
  private colourOf: ((module: number) => Rgb | null) | null = null;
  /** The selected branch's Bézier handles (branch editing). */
  private readonly handles = new BezierHandles();
  private mode: ProjectionMode = 'auto';
  /** The plant on screen lies in the plane z = 0. */
  private flat = false;
  /** Frame the next plant shown, even if the camera was moved (a new grammar was opened). */
  private frameNext = false;
  /** The user orbited, panned or zoomed since the last fit: new plants keep the camera. */
  private moved = false;
  /** Who holds the frame now (e.g. `editing`, `play`): while anyone does, new plants keep it. */
  private readonly holders = new Set<string>();
  private refitHinted = false;
  private readonly refitListeners = new Set<(shown: boolean) => void>();
  private renderQueued = false;
  /** The container's size changed since the drawing buffer was sized ({@link resize} is due). */
  private sizeStale = false;
  /** The fence after the last frame drawn, until the GPU has passed it ({@link renderWhenDrawn}). */
  private drawn: WebGLSync | null = null;
  private readonly darkScheme = window.matchMedia(DARK_SCHEME);
  private readonly resizeObserver: ResizeObserver;
  private readonly renderListeners = new Set<() => void>();
  /** A plant was given to {@link showPlant} (the textures load after its first frame). */
  private plantShown = false;
  /** Settles when the OrbitControls are attached (see {@link controlsReady}). */
  private readonly controlsLoaded: Promise<void>;

  /** `assetBase`: the site's root, where the textures are (default: the page's address). */
  constructor(
    private readonly container: HTMLElement,
    { assetBase }: { assetBase?: string } = {},
  ) {
    // The images (150 KB, not part of any plant's first frame: it shows untextured until they are
    // there) load after the first frame that drew a plant, not beside the core and the script.
    const plantDrawn = new Promise<void>((resolve) => {
      const stop = this.onRender(() => {
        if (!this.plantShown) return;
        stop();
        resolve();
      });
    });
    const texture = (name: 'bark' | 'leaf') => loadTexture(name, () => this.textureLoaded(), (message) => this.texturesFailed(message), assetBase, plantDrawn);
    this.textured = texturedMaterials(texture('bark'), texture('leaf'), this.lit, this.unlit);
    const { renderer, software } = viewRenderer();
    this.renderer = renderer;
    this.gpuBuffers = new BufferPool(renderer.getContext() as WebGL2RenderingContext);
    this.segmentLines = new SegmentLines(this.renderer.capabilities.maxTextureSize);
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    const canvas = this.renderer.domElement;
    canvas.setAttribute('aria-label', '3D view of the plant; drag or the arrow keys to orbit, scroll or + and − to zoom, Home to fit');
    canvas.tabIndex = 0;
    canvas.addEventListener('keydown', (event) => this.onKey(event));
    canvas.addEventListener('webglcontextlost', () => this.contextLost());
    canvas.addEventListener('webglcontextrestored', () => this.contextRestored());
    container.append(canvas);
    if (software) this.canvas2D = new SketchCanvas(container);

    addSkyLight(this.scene);
    this.perspective = this.rig(new PerspectiveCamera(40, 1, 0.01, 1000));
    this.orthographic = this.rig(new OrthographicCamera(-1, 1, 1, -1, 0.01, 1000));
    this.orthographic.controls.enableRotate = false; // a 2D view pans and zooms
    this.active = this.perspective;
    this.perspective.controls.enabled = true;
    this.controlsLoaded = plantDrawn.then(loadOrbitControls).then(
      (Controls) => {
        this.perspective.controls.attach(Controls);
        this.orthographic.controls.attach(Controls);
      },
      (error: unknown) => console.error('The camera controls could not load:', error),
    );
    this.scene.add(this.perspective.camera, this.plant, this.lines, this.segmentLines.group, this.overlay, this.handles.group);
    this.container.dataset.projection = 'perspective';

    this.applyPalette();
    this.darkScheme.addEventListener('change', this.applyPalette);
    // The drawing buffer is resized with the next frame, once the GPU is idle: resizing it while a
    // software GPU still draws the frame before waits for that frame (290 ms of the page's thread
    // for the big tree, when the status line's wrapping moved the view while typing).
    this.resizeObserver = new ResizeObserver(() => {
      this.sizeStale = true;
      this.requestRender();
    });
    this.resizeObserver.observe(container);
    this.resize();
  }

  private rig<C extends PerspectiveCamera | OrthographicCamera>(camera: C): CameraRig<C> {
    addHeadlight(camera);
    const controls = new CameraControls(camera, this.renderer.domElement, {
      change: () => this.requestRender(),
      start: () => (this.moved = true),
    });
    return { camera, controls, framed: false };
  }

  /**
   * Settles when the mouse and touch can move the camera: three's OrbitControls load after the
   * first frame that drew a plant (issue 22, the first load); the keys work before.
   */
  get controlsReady(): Promise<void> {
    return this.controlsLoaded;
  }

  /**
   * Compiles the shader programs of the view's materials without drawing: the plant's (lit, unlit,
   * textured), its lines, the Lines mode's and the grid's. Called while the core downloads, so that
   * the first plant's frame does not wait for the GPU's compiler (70-90 ms of the first load's
   * last frame on SwiftShader, traced). Settles when they are ready to draw with.
   */
  compileShaders(): Promise<unknown> {
    // Stand-ins with the attributes a plant's geometries have: three.js keys a program by them too.
    const triangle = (...names: string[]) => {
      const geometry = new BufferGeometry();
      for (const name of names) geometry.setAttribute(name, new BufferAttribute(new Float32Array(9), 3));
      return geometry;
    };
    const standIns = new Group();
    const mesh = triangle('position', 'normal', 'color');
    for (const material of [this.lit, this.unlit, ...this.textured.lit, ...this.textured.unlit]) standIns.add(new Mesh(mesh, material));
    const lines = triangle('position', 'color');
    standIns.add(new LineSegments(lines, this.lines.material), new LineSegments(lines, this.gridMaterial));
    // And the scene's own objects as they are now: the first plant's frame still draws some of them
    // without attributes (the sketch's lines when there is no sketch), which takes other programs.
    const camera = this.active.camera;
    return Promise.all([this.renderer.compileAsync(standIns, camera, this.scene), this.renderer.compileAsync(this.scene, camera)]);
  }

  /** The projection in use. */
  get projection(): Projection {
    return this.active === this.orthographic ? 'orthographic' : 'perspective';
  }

  /** The camera in use (for tests and the future picking of segments). */
  get camera(): Camera {
    return this.active.camera;
  }

  /** The bounding box of what is shown: the mesh, or the lines of the fallback. */
  private visibleBox(): Box3 {
    const geometry = this.plant.geometry.getAttribute('position') ? this.plant.geometry : this.lines.geometry;
    const box = geometry.boundingBox ?? new Box3();
    // In the Lines mode the segments are drawn as lines, and the mesh has no tubes (maybe nothing).
    if (!this.usesLines || !this.mesh) return box;
    this.segmentsBox ??= pointsBox(this.mesh.segmentEnds);
    return box.clone().union(this.segmentsBox);
  }

  /**
   * Replaces the plant; `flat` says it lies in the plane z = 0 (in `auto` mode it is then shown
   * face-on in 2D). The plant is framed (see the class comment) unless the user moved the camera
   * or the frame is held; a camera's first plant, and the one after {@link frameNextPlant}, always.
   * `gpu`, when given, holds the normals and colours packed smaller for the GPU (by the core, for
   * the build worker): a big plant reaches the GPU in less time. `bounds`: the build's
   * `stats.bounds`, which spare a pass over the mesh (see {@link plantGeometry}). A plant of more
   * than {@link UPLOAD_AT_ONCE_BYTES} goes to the GPU over several tasks while the one before stays
   * on screen ({@link uploading}).
   */
  showPlant(mesh: MeshBuffers, flat = false, gpu?: GpuArrays, bounds?: Bounds): void {
    this.incoming?.onGpu?.dispose();
    this.incoming = undefined;
    this.colourOf = null; // a highlight names modules of the plant it was asked for
    if (mesh.indices.length === 0 && mesh.lines.length > 0) {
      this.swapIn({ mesh, flat });
      return;
    }
    const source = plantGeometry(mesh, gpu, bounds);
    const onGpu = new GpuGeometry(this.gpuBuffers, source);
    const incoming: IncomingPlant = { mesh, flat, source, onGpu };
    this.incoming = incoming;
    if (onGpu.remaining <= UPLOAD_AT_ONCE_BYTES) {
      this.finishUpload();
      return;
    }
    // A big plant: slices for a few milliseconds per task, once the GPU has drawn the frame before
    // (a frame of the sketch on a software GPU takes up to 300 ms, and an upload meanwhile waits).
    const next = () => {
      if (this.incoming !== incoming) return; // replaced by a newer plant, and disposed
      if (!this.gpuIdle()) {
        setTimeout(next, 2);
        return;
      }
      const start = performance.now();
      let done = onGpu.upload(UPLOAD_SLICE_BYTES);
      while (!done && performance.now() - start < UPLOAD_TASK_MS) done = onGpu.upload(UPLOAD_SLICE_BYTES);
      if (!done) nextTask(next);
      else this.finishUpload();
    };
    next();
  }

  /**
   * A big plant's sketch (its segments as `lines` in the linear RGB `lineColors`, as the core's
   * sketch gives them), shown as a plant drawn as lines until the next plant replaces it (in 2D
   * where a software rasterizer draws the view, see {@link swapIn}).
   */
  showSketch(lines: Float32Array, lineColors: Float32Array, flat: boolean): void {
    const empty = new Float32Array(0);
    const none = new Uint32Array(0);
    this.showPlant(
      { positions: empty, normals: empty, colors: empty, indices: none, ranges: none, uvs: empty, materialRanges: none, lines, lineColors, segmentEnds: empty, segmentColors: empty, segmentModules: none },
      flat,
    );
  }

  /** What is drawn in 2D (a sketch, or the Lines mode's segments) as the camera sees it now. */
  private draw2D(): void {
    if (!this.canvas2D?.active) return;
    const camera = this.active.camera;
    camera.updateMatrixWorld();
    const { x, y } = this.renderer.getDrawingBufferSize(this.drawingBufferSize);
    this.canvas2D.draw(camera, x, y);
    if (this.linesIn2D) this.segmentLines.setViewport(this.renderer.domElement.clientWidth, this.renderer.domElement.clientHeight);
  }

  /**
   * Draws the Lines mode's segments of the plant on screen in 2D ({@link canvas2D}), in their
   * width, brightness and highlight, where a software rasterizer draws the view and the plant has
   * {@link LINES_IN_2D_FROM} segments or more; else leaves them to WebGL. Called when the plant,
   * the mode, the width or the highlight changes.
   */
  private placeLines(): void {
    const canvas = this.canvas2D;
    const mesh = this.mesh;
    const in2D = this.segmentsIn2D;
    this.segmentLines.drawn = !in2D;
    if (!canvas || !mesh || !in2D) {
      if (this.linesIn2D) canvas?.clear();
      this.linesIn2D = false;
      return;
    }
    // The canvas's pixels are the drawing buffer's; the widths are in CSS pixels.
    const ratio = this.renderer.getPixelRatio();
    const width = this.segmentLines.lineWidth;
    const { over, dim } = this.segmentHighlight;
    // Round ends and corners as WebGL draws them, where they show: for lines of a few pixels
    // Skia's round joins cost more than the difference (1,048,576 segments 2 pixels wide: 733
    // against 511 ms a frame without a GPU).
    const style = { width: width * ratio, round: width * ratio > 4, dim };
    if (!this.linesIn2D) canvas.show(mesh.segmentEnds, mesh.segmentColors, style);
    canvas.restyle(style, over && { ends: over.ends, colors: over.colors, width: (width + HIGHLIGHT_EXTRA) * ratio });
    this.linesIn2D = true;
    this.requestRender();
  }

  /** Whether the Lines mode's segments of the plant on screen are to be drawn in 2D ({@link placeLines}). */
  private get segmentsIn2D(): boolean {
    return this.canvas2D !== undefined && this.usesLines && (this.mesh?.segmentEnds.length ?? 0) >= 6 * LINES_IN_2D_FROM;
  }

  /** Uploads what is left of the incoming plant at once, and puts it on screen. */
  private finishUpload(): void {
    const incoming = this.incoming;
    if (!incoming) return;
    incoming.onGpu?.upload(Infinity);
    this.incoming = undefined;
    this.swapIn(incoming);
  }

  /**
   * A plant given to {@link showPlant} is still on its way to the GPU (the one before is on
   * screen meanwhile, and picking finds nothing).
   */
  get uploading(): boolean {
    return this.incoming !== undefined;
  }

  /** Puts a plant (its geometry on the GPU, or its lines) on screen in place of the old one. */
  private swapIn({ mesh, flat, source, onGpu }: IncomingPlant): void {
    this.plantShown = true;
    this.canvas2D?.clear();
    this.linesIn2D = false; // drawn again by colourModules below, if they are to be
    const asLines = onGpu === undefined;
    // One-pixel lines (a sketch, a plant too large to mesh) where a software rasterizer draws the
    // view: in 2D over it (./sketch-canvas.ts); the WebGL frame, drawn without them, costs that
    // rasterizer next to nothing.
    const lines2D = asLines && mesh.lines.length > 0 && this.canvas2D !== undefined;
    if (lines2D) this.canvas2D?.show(mesh.lines, mesh.lineColors);
    this.lines.visible = !lines2D;
    this.mesh = asLines ? undefined : mesh;
    const oldMesh = this.plant.geometry;
    const oldOnGpu = this.plantOnGpu;
    const oldPickable = this.pickable.geometry;
    const oldLines = this.lines.geometry;
    this.plant.geometry = onGpu?.geometry ?? new BufferGeometry();
    this.plantOnGpu = onGpu;
    this.pickable.geometry = source ?? new BufferGeometry();
    this.lines.geometry = asLines ? plantGeometry(mesh) : new BufferGeometry();
    if (oldOnGpu) oldOnGpu.dispose();
    else oldMesh.dispose();
    oldPickable.dispose();
    oldLines.dispose();
    this.flat = flat;
    // Whether WebGL draws them, said with them: its geometry of segments drawn in 2D is not made.
    this.segmentLines.show(asLines ? null : mesh, !this.segmentsIn2D);
    this.segmentsBox = undefined;
    this.applyMaterial();
    this.colourModules(this.colourOf); // what was asked for while it uploaded, if anything
    // A mesh without tubes (the Lines mode's) may hold no triangle: its segments are drawn.
    const hasGeometry = mesh.indices.length > 0 || asLines || (mesh.segmentEnds.length > 0 && this.usesLines);
    if (hasGeometry && this.frameNext) {
      this.frameNext = false;
      this.perspective.framed = false;
      this.orthographic.framed = false;
    }
    this.useProjection(this.wantedProjection(), hasGeometry);
    if (hasGeometry) this.follow();
    this.requestRender();
    // What is drawn in 2D, drawn now with the camera framed on it, not in the frame: the WebGL
    // frame comes on screen no later for it (the frame redraws it only if the camera or size changed).
    this.draw2D();
  }

  /** Frames the new plant on screen, or keeps the camera (and hints at a refit if the user moved it). */
  private follow(): void {
    if (!this.active.framed) this.frame();
    else if (this.holders.size > 0) return;
    else if (!this.moved) this.frame();
    else this.hintRefit(true);
  }

  /**
   * Holds the frame for `holder` (`on`) or lets it go: while anyone holds it, new plants keep the
   * camera where it is and no refit is hinted.
   */
  holdFrame(holder: string, on: boolean): void {
    if (on) this.holders.add(holder);
    else this.holders.delete(holder);
  }

  /** Follows the plant again from the next one, as if the user had not moved the camera. */
  followAgain(): void {
    this.moved = false;
  }

  /**
   * Calls `listener` with `true` when a new plant was not framed because the user had moved the
   * camera (a "Refit" hint is due), and with `false` once the view is framed again.
   */
  onRefitHint(listener: (shown: boolean) => void): () => void {
    this.refitListeners.add(listener);
    return () => this.refitListeners.delete(listener);
  }

  private hintRefit(shown: boolean): void {
    if (shown === this.refitHinted) return;
    this.refitHinted = shown;
    for (const listener of this.refitListeners) listener(shown);
  }

  /**
   * Paints the triangles of the modules `colourOf` names in its colour and dims the rest; `null`
   * restores the plant's own colours. (The line fallback of huge models is not highlighted.)
   */
  colourModules(colourOf: ((module: number) => Rgb | null) | null): void {
    this.colourOf = colourOf;
    // The modules are then the incoming plant's: they are painted when it is on screen.
    if (this.incoming) return;
    const mesh = this.mesh;
    const old = this.overlay.geometry;
    this.overlay.geometry = new BufferGeometry();
    old.dispose();
    let dim = 1;
    const lines = this.usesLines;
    this.segmentHighlight = { over: mesh && colourOf && lines ? highlightSegments(mesh, colourOf) : null, dim: mesh && colourOf ? 0.55 : 1 };
    this.segmentLines.highlight(this.segmentHighlight.over, this.segmentHighlight.dim);
    this.placeLines();
    if (mesh && colourOf) {
      // The normals on the GPU: the mesh's floats, or the worker's packed ones (its floats are then empty).
      const normals = this.pickable.geometry.getAttribute('normal')?.array as Float32Array | Int16Array | undefined;
      const overlay = highlightOverlay(mesh, colourOf, !lines, normals ?? mesh.normals);
      const geometry = this.overlay.geometry;
      geometry.setAttribute('position', new BufferAttribute(overlay.positions, 3));
      geometry.setAttribute('normal', new BufferAttribute(overlay.normals, 3));
      geometry.setAttribute('color', new BufferAttribute(overlay.colors, 3));
      geometry.computeBoundingSphere();
      dim = 0.55; // dim the rest
    }
    this.lit.color.setScalar(dim);
    this.unlit.color.setScalar(dim);
    for (const m of [...this.textured.lit, ...this.textured.unlit]) (m as MeshBasicMaterial).color.setScalar(dim);
    this.requestRender();
  }

  /** The module of the derived string drawn at a point of the page, or null (nothing there). */
  pickModule(clientX: number, clientY: number): number | null {
    const mesh = this.mesh;
    if (!mesh || this.incoming) return null;
    this.aim(clientX, clientY);
    const lines = this.usesLines;
    // In the Lines mode the tubes' triangles are not drawn: only leaves, polygons and spheres count.
    const hit = this.raycaster
      .intersectObject(this.pickable, false)
      .find((h) => h.faceIndex != null && (!lines || moduleOfTriangle(mesh.materialRanges, h.faceIndex) !== MATERIAL_BARK));
    const line = lines ? this.segmentLines.pick(this.raycaster) : null;
    if (line && (!hit || line.distance <= hit.distance)) return line.module;
    return hit?.faceIndex != null ? moduleOfTriangle(mesh.ranges, hit.faceIndex) : null;
  }

  /** The page point as normalised device coordinates of the canvas, set on the raycaster. */
  private aim(clientX: number, clientY: number): void {
    const rect = this.renderer.domElement.getBoundingClientRect();
    const ndc = new Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.active.camera);
  }

  /** The triangle of the mesh on screen at a point of the page, or null. */
  pickTriangle(clientX: number, clientY: number): number | null {
    if (!this.mesh || this.incoming) return null;
    this.aim(clientX, clientY);
    const hit = this.raycaster.intersectObject(this.pickable, false)[0];
    return hit && hit.faceIndex != null ? hit.faceIndex : null;
  }

  /**
   * After vertices of the mesh on screen were changed in place (its arrays are the geometry's),
   * uploads only `ranges` ((first vertex, count) pairs) and updates the bounds.
   */
  patchVertices(ranges: Uint32Array): void {
    // The mesh last given: the one on its way to the GPU, if any, else the one on screen.
    const { mesh, source, onGpu } = this.incoming ?? { mesh: this.mesh, source: this.pickable.geometry, onGpu: this.plantOnGpu };
    if (!mesh || !source || !onGpu) return;
    for (const [name, array, size] of [
      ['position', mesh.positions, 3],
      ['normal', mesh.normals, 3],
      ['uv', mesh.uvs, 2],
    ] as const) {
      // (Packed normals are not the mesh's: a mesh with them is not edited.)
      if (source.getAttribute(name)?.array !== array) continue;
      for (let k = 0; k + 1 < ranges.length; k += 2) onGpu.patch(name, size * ranges[k], size * ranges[k + 1]);
    }
    setBox(source, pointsBox(mesh.positions));
    setBox(onGpu.geometry, source.boundingBox!);
    this.requestRender();
  }

  /** Shows a branch's handles at `points` (P0..P3, 12 floats), or hides them (null). */
  showHandles(points: Float32Array | null): void {
    // Hidden already (each new plant hides them): no frame. A frame of a big plant keeps a software
    // GPU busy for 200 ms, and a plant on its way to the GPU waits for it.
    if (!points && !this.handles.group.visible) return;
    const box = this.visibleBox();
    const size = box.isEmpty() ? 1 : box.getSize(new Vector3()).length();
    this.handles.show(points, size * 0.012);
    this.requestRender();
  }

  /** The draggable handle (1, 2, 3) at a point of the page, or null. */
  handleAt(clientX: number, clientY: number): 1 | 2 | 3 | null {
    this.aim(clientX, clientY);
    return this.handles.hit(this.raycaster);
  }

  /** Where a point of the page meets the plane through `through` facing the camera (a drag's target). */
  dragTarget(clientX: number, clientY: number, through: [number, number, number]): [number, number, number] | null {
    this.aim(clientX, clientY);
    const normal = this.active.camera.getWorldDirection(new Vector3());
    const plane = new Plane().setFromNormalAndCoplanarPoint(normal, new Vector3(...through));
    const point = this.raycaster.ray.intersectPlane(plane, new Vector3());
    return point ? [point.x, point.y, point.z] : null;
  }

  /** A model point's place on the page (CSS pixels), for tests and tooltips. */
  pageOf(point: [number, number, number]): { x: number; y: number } {
    const rect = this.renderer.domElement.getBoundingClientRect();
    const p = new Vector3(...point).project(this.active.camera);
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }

  /** Lets the mouse orbit the camera, or not (while a handle is dragged). */
  setOrbitEnabled(enabled: boolean): void {
    this.active.controls.enabled = enabled;
  }

  /** The canvas, for pointer events. */
  get canvas(): HTMLCanvasElement {
    return this.renderer.domElement;
  }

  /**
   * Where the camera in use stands: what a share link keeps. `zoom` is the orthographic camera's
   * (1 for the perspective one).
   */
  cameraPose(): ViewPose {
    const { camera, controls } = this.active;
    return {
      position: camera.position.toArray() as [number, number, number],
      target: controls.target.toArray() as [number, number, number],
      zoom: this.active === this.orthographic ? this.orthographic.camera.zoom : 1,
    };
  }

  /**
   * Puts the camera in use where `pose` says (after framing it on the plant on screen, for its
   * clipping planes and the grid), and keeps it there across later plants.
   */
  setCameraPose(pose: ViewPose): void {
    this.frame();
    const { camera, controls } = this.active;
    camera.position.fromArray(pose.position);
    controls.target.fromArray(pose.target);
    if (camera instanceof OrthographicCamera) camera.zoom = pose.zoom;
    else {
      // Keep the plant inside the clipping range wherever the camera stands.
      const distance = camera.position.distanceTo(controls.target);
      camera.near = Math.min(camera.near, distance / 1000);
      camera.far = Math.max(camera.far, distance * 10);
    }
    camera.updateProjectionMatrix();
    controls.update();
    this.active.framed = true;
    this.moved = true; // the link's camera stays, as if the user had put it there
    this.requestRender();
  }

  /**
   * Keys on the focused view: the arrows orbit (in 2D they pan), + and − zoom, Home fits the plant;
   * Shift makes the steps finer. Other keys (Ctrl+Z for branch edits) pass.
   */
  private onKey(event: KeyboardEvent): void {
    if (event.altKey || event.ctrlKey || event.metaKey) return;
    const step = event.shiftKey ? 1 : 5;
    const moves: Record<string, () => void> = {
      ArrowLeft: () => this.orbit(-step, 0),
      ArrowRight: () => this.orbit(step, 0),
      ArrowUp: () => this.orbit(0, -step),
      ArrowDown: () => this.orbit(0, step),
      '+': () => this.zoomBy(1 / (1 + step / 40)),
      '=': () => this.zoomBy(1 / (1 + step / 40)),
      '-': () => this.zoomBy(1 + step / 40),
      Home: () => this.frame(),
    };
    const move = moves[event.key];
    if (!move) return;
    event.preventDefault();
    move();
    if (event.key !== 'Home') this.moved = true;
  }

  /** Turns the camera about its target by `right` and `down` degrees (in 2D: pans by that share of the view, in tenths). */
  private orbit(right: number, down: number): void {
    const { camera, controls } = this.active;
    if (camera instanceof OrthographicCamera) {
      const height = (camera.top - camera.bottom) / camera.zoom;
      const shift = new Vector3(right, -down, 0).multiplyScalar(height / 50);
      camera.position.add(shift);
      controls.target.add(shift);
    } else {
      const offset = camera.position.clone().sub(controls.target);
      const spherical = new Spherical().setFromVector3(offset);
      spherical.theta -= MathUtils.degToRad(right);
      spherical.phi = MathUtils.clamp(spherical.phi + MathUtils.degToRad(down), 0.01, Math.PI - 0.01);
      camera.position.copy(controls.target).add(offset.setFromSpherical(spherical));
    }
    controls.update();
    this.requestRender();
  }

  /** Moves the camera `factor` times as far from its target (below 1: nearer). */
  private zoomBy(factor: number): void {
    const { camera, controls } = this.active;
    if (camera instanceof OrthographicCamera) {
      camera.zoom /= factor;
      camera.updateProjectionMatrix();
    } else {
      camera.position.sub(controls.target).multiplyScalar(factor).add(controls.target);
    }
    controls.update();
    this.requestRender();
  }

  /** Frames the camera on the next plant shown (e.g. after another example was opened). */
  frameNextPlant(): void {
    this.frameNext = true;
  }

  /** Chooses the projection: `auto` (2D for flat plants) or a fixed one. */
  setProjectionMode(mode: ProjectionMode): void {
    this.mode = mode;
    this.useProjection(this.wantedProjection(), true);
  }

  /** The projection mode last set. */
  get projectionMode(): ProjectionMode {
    return this.mode;
  }

  private wantedProjection(): Projection {
    if (this.mode !== 'auto') return this.mode;
    return this.flat ? 'orthographic' : 'perspective';
  }

  private useProjection(projection: Projection, frameIfNew: boolean): void {
    const next = projection === 'orthographic' ? this.orthographic : this.perspective;
    if (next === this.active) return;
    this.active.controls.enabled = false;
    this.scene.remove(this.active.camera); // its headlight goes with it
    this.active = next;
    this.active.controls.enabled = true;
    this.scene.add(this.active.camera);
    this.container.dataset.projection = projection;
    this.resize();
    if (frameIfNew && !this.active.framed && !this.visibleBox().isEmpty()) this.frame();
    else this.placeGrid(this.visibleBox());
    this.requestRender();
  }

  /**
   * Points the camera at the whole plant, or at `bounds` (e.g. the last step's plant, so Play
   * shows the growth in one frame), fits the ground grid under (or behind) it, and follows the
   * plant again.
   */
  frame(bounds?: Bounds): void {
    const box = bounds ? new Box3(new Vector3(...bounds[0]), new Vector3(...bounds[1])) : this.visibleBox();
    if (this.active === this.orthographic) {
      const { camera, controls } = this.orthographic;
      const pose = flatPose(box, this.aspect());
      camera.position.copy(pose.position);
      camera.up.set(0, 1, 0);
      camera.zoom = 1;
      camera.top = pose.halfHeight;
      camera.bottom = -pose.halfHeight;
      camera.near = pose.near;
      camera.far = pose.far;
      this.fitOrthographic();
      controls.target.copy(pose.target);
      controls.update();
    } else {
      const { camera, controls } = this.perspective;
      const pose = framePose(box, camera.fov, camera.aspect);
      camera.position.copy(pose.position);
      camera.near = pose.near;
      camera.far = pose.far;
      camera.updateProjectionMatrix();
      controls.target.copy(pose.target);
      controls.update();
    }
    if (!box.isEmpty()) this.active.framed = true;
    this.moved = false;
    this.hintRefit(false);
    this.placeGrid(box);
    this.requestRender();
  }

  /**
   * A PNG of the current view at `width` × `height` pixels: the same camera and lights, the
   * aspect ratio of the picture (the vertical field of view, or the orthographic height, is kept).
   * With `look.background` white or transparent the picture has that background and no grid; the
   * lines are `look.lineWidth` of its pixels wide. The canvas is drawn at that size for one frame
   * and restored before the page paints again. A view without multisampling (a software
   * rasterizer's, see {@link viewRenderer}) draws it at twice the size, where the GPU can, and
   * scales it down: as smooth as a multisampled one.
   */
  async snapshot(width: number, height: number, look: PictureLook = { background: 'view' }): Promise<Blob> {
    this.finishUpload(); // the picture is of the plant last given
    const canvas = this.renderer.domElement;
    const multisampled = this.renderer.getContext().getContextAttributes()?.antialias === true;
    // Not a plant drawn as lines one pixel wide (too large to mesh): scaled down, they would fade.
    const thinLines = this.lines.geometry.getAttribute('position') !== undefined;
    const scale = multisampled || thinLines || 2 * Math.max(width, height) > this.maxPictureSide() ? 1 : 2;
    const pixelRatio = this.renderer.getPixelRatio();
    const camera = this.active.camera;
    const background = this.scene.background;
    const lineWidth = this.segmentLines.lineWidth;
    let blob: Promise<Blob | null>;
    // What is drawn in 2D (a sketch, the Lines mode's segments of a big plant) is drawn into the picture.
    this.lines.visible = true;
    this.segmentLines.drawn = true;
    try {
      if (look.background !== 'view') {
        this.scene.background = look.background === 'white' ? new Color('#ffffff') : null;
        if (this.grid) this.grid.visible = false;
      }
      this.renderer.setClearColor(0xffffff, look.background === 'transparent' ? 0 : 1);
      this.segmentLines.lineWidth = (look.lineWidth ?? lineWidth) * scale;
      this.renderer.setPixelRatio(1);
      this.renderer.setSize(width * scale, height * scale, false);
      if (camera instanceof PerspectiveCamera) camera.aspect = width / height;
      else [camera.left, camera.right] = [-camera.top * (width / height), camera.top * (width / height)];
      camera.updateProjectionMatrix();
      drawnSupersampled(scale, () => this.renderer.render(this.scene, camera));
      // toBlob copies the bitmap now (preserveDrawingBuffer keeps it); encoding finishes later.
      const picture = scale === 1 ? canvas : scaledDown(canvas, width, height);
      blob = new Promise((resolve) => picture.toBlob(resolve, 'image/png'));
    } finally {
      this.lines.visible = !this.canvas2D?.active;
      this.segmentLines.drawn = !this.linesIn2D;
      this.scene.background = background;
      if (this.grid) this.grid.visible = this.gridVisible;
      this.segmentLines.lineWidth = lineWidth;
      this.renderer.setPixelRatio(pixelRatio);
      this.resize();
      this.renderer.render(this.scene, camera);
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

  /** Shows or hides the ground grid. */
  setGridVisible(visible: boolean): void {
    this.gridVisible = visible;
    if (this.grid) this.grid.visible = visible;
    this.requestRender();
  }

  /** Lit and shaded (true), or the palette's colours unshaded (false). */
  setLighting(lit: boolean): void {
    this.lighting = lit;
    this.applyMaterial();
  }

  /** Bark and leaf textures on (true, the default) or off (the palette's colours alone). */
  setTextures(on: boolean): void {
    this.texturing = on;
    this.applyMaterial();
  }

  private applyMaterial(): void {
    const textured = this.lighting ? this.textured.lit : this.textured.unlit;
    const on = this.texturing && this.texturesLoaded === 2;
    const material = on ? textured : this.lighting ? this.lit : this.unlit;
    const lines = this.usesLines;
    // By material kind (bark, leaf, plain): in the Lines mode the tubes give way to the lines.
    const kinds = Array.isArray(material) ? material : [material, material, material];
    this.plant.material = lines ? [this.hiddenTubes, kinds[1], kinds[2]] : material;
    this.pickable.material = this.plant.material;
    this.segmentLines.visible = lines;
    this.container.dataset.render = lines ? 'lines' : 'tubes';
    this.container.dataset.textures = String(on);
    this.requestRender();
  }

  /** Chooses how branches are drawn: lines, tubes, or `auto` (lines for flat plants). */
  setRenderMode(mode: RenderMode): void {
    this.renderMode = mode;
    this.applyMaterial();
    this.colourModules(this.colourOf);
  }

  /** The render mode last set. */
  get renderModeChosen(): RenderMode {
    return this.renderMode;
  }

  /** The width of the Lines mode's lines, in CSS pixels (times the line scale). */
  setLineWidth(pixels: number): void {
    this.lineWidthChosen = pixels;
    this.segmentLines.lineWidth = pixels * this.lineScale;
    this.placeLines();
    this.requestRender();
  }

  /** Draws the lines `scale` times the width chosen (2 in Large mode: a projector's lines). */
  setLineScale(scale: number): void {
    this.lineScale = scale;
    this.setLineWidth(this.lineWidthChosen);
  }

  /**
   * Draws tubes for `holder` whatever the mode (`on`), or lets go (branch editing reshapes the
   * tubes and their handles).
   */
  holdTubes(holder: string, on: boolean): void {
    if (on) this.tubeHolders.add(holder);
    else this.tubeHolders.delete(holder);
    this.applyMaterial();
    this.colourModules(this.colourOf);
  }

  /** The view's background as `#rrggbb` (a drawing "as the view" has it, without the grid). */
  backgroundHex(): string {
    return `#${scenePalette(this.darkScheme.matches).background.getHexString()}`;
  }

  /** True while the plant's segments are drawn as lines (the mode chosen, or `auto` and flat). */
  get usesLines(): boolean {
    if (!this.mesh || this.mesh.segmentModules.length === 0 || this.tubeHolders.size > 0) return false;
    return this.renderMode === 'lines' || (this.renderMode === 'auto' && this.flat);
  }

  /** An image arrived; with both, the plant is drawn textured (if the toggle is on). */
  private textureLoaded(): void {
    this.texturesLoaded++;
    this.applyMaterial();
  }

  /** A texture did not load: show the plant untextured, and say so on the container (for tests). */
  private texturesFailed(message: string): void {
    this.container.dataset.texturesError = message;
    this.setTextures(false);
  }

  /** Marks the plant as out of date (the grammar has errors) or current. */
  setStale(stale: boolean): void {
    this.container.toggleAttribute('data-stale', stale);
  }

  /** Calls `listener` after every frame drawn; returns the function that stops it. */
  onRender(listener: () => void): () => void {
    this.renderListeners.add(listener);
    return () => this.renderListeners.delete(listener);
  }

  /** Releases the GPU resources and listeners. */
  dispose(): void {
    this.resizeObserver.disconnect();
    this.darkScheme.removeEventListener('change', this.applyPalette);
    this.perspective.controls.dispose();
    this.orthographic.controls.dispose();
    this.incoming?.onGpu?.dispose();
    this.incoming = undefined;
    this.plantOnGpu?.dispose();
    this.gpuBuffers.clear();
    this.plant.geometry.dispose();
    this.pickable.geometry.dispose();
    this.overlay.geometry.dispose();
    this.overlay.material.dispose();
    this.lines.geometry.dispose();
    this.lines.material.dispose();
    this.segmentLines.dispose();
    this.hiddenTubes.dispose();
    this.lit.dispose();
    this.unlit.dispose();
    this.textured.dispose();
    this.removeGrid();
    this.gridMaterial.dispose();
    this.renderer.dispose();
    this.renderer.domElement.remove();
    this.canvas2D?.clear();
  }

  /**
   * A grid of round-numbered squares: on the ground under the plant in 3D; in 2D behind it, in the
   * plane of the drawing, its centre line at the plant's base.
   */
  private placeGrid(box: Box3): void {
    this.removeGrid();
    if (box.isEmpty()) return;
    const palette = scenePalette(this.darkScheme.matches);
    const flat = this.active === this.orthographic;
    // In 2D the grid's centre line is the ground: it must reach the plant's top above it.
    const span = flat
      ? Math.max(box.max.x - box.min.x, 2 * (box.max.y - box.min.y))
      : Math.max(box.max.x - box.min.x, box.max.z - box.min.z, (box.max.y - box.min.y) * 0.6);
    const step = 10 ** Math.floor(Math.log10(span / 4 || 1));
    const size = Math.ceil((span * 1.6) / step) * step;
    this.grid = new GridHelper(size, Math.round(size / step), palette.gridCenter, palette.grid);
    (this.grid.material as Material).dispose(); // never drawn: no program to release
    this.grid.material = this.gridMaterial;
    if (flat) {
      this.grid.rotation.x = Math.PI / 2;
      const depth = Math.max(box.max.z - box.min.z, span * 1e-3);
      this.grid.position.set((box.min.x + box.max.x) / 2, box.min.y, box.min.z - depth);
    } else {
      this.grid.position.set((box.min.x + box.max.x) / 2, box.min.y, (box.min.z + box.max.z) / 2);
    }
    this.grid.visible = this.gridVisible;
    this.scene.add(this.grid);
  }

  private removeGrid(): void {
    if (!this.grid) return;
    this.scene.remove(this.grid);
    this.grid.geometry.dispose(); // its material is kept for the next grid
    this.grid = undefined;
  }

  private readonly applyPalette = (): void => {
    const palette = scenePalette(this.darkScheme.matches);
    this.scene.background = palette.background;
    if (this.grid) this.placeGrid(this.visibleBox());
    this.requestRender();
  };

  private aspect(): number {
    return Math.max(1, this.container.clientWidth) / Math.max(1, this.container.clientHeight);
  }

  /** The orthographic camera's width follows the view's aspect; its height is the framed one. */
  private fitOrthographic(): void {
    const camera = this.orthographic.camera;
    const halfWidth = camera.top * this.aspect();
    camera.left = -halfWidth;
    camera.right = halfWidth;
    camera.updateProjectionMatrix();
  }

  private resize(): void {
    this.sizeStale = false;
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height, false);
    this.perspective.camera.aspect = width / height;
    this.perspective.camera.updateProjectionMatrix();
    this.fitOrthographic();
    this.requestRender();
  }

  /**
   * The browser took the view's WebGL context away (a phone's browser sent to the background, a
   * GPU reset): every buffer and fence of it went too. three.js makes its own again when the
   * context comes back; the plant's are the view's own ({@link GpuGeometry}): see
   * {@link contextRestored}.
   */
  private contextLost(): void {
    this.drawn = null;
    this.gpuBuffers.clear(true);
  }

  /**
   * The context is back (three.js has made its state again, its listener being first): the plant
   * on screen, and one on its way, go to the GPU again from their arrays, and the view draws.
   */
  private contextRestored(): void {
    this.contextLost(); // and any buffers given back while it was
    const again = (onGpu: GpuGeometry, source: BufferGeometry) => {
      onGpu.dispose(true);
      const fresh = new GpuGeometry(this.gpuBuffers, source);
      fresh.upload(Infinity);
      return fresh;
    };
    if (this.plantOnGpu) {
      this.plantOnGpu = again(this.plantOnGpu, this.pickable.geometry);
      this.plant.geometry = this.plantOnGpu.geometry;
    }
    const incoming = this.incoming;
    if (incoming?.onGpu && incoming.source) {
      incoming.onGpu = again(incoming.onGpu, incoming.source);
      this.finishUpload();
    }
    this.requestRender();
  }

  private requestRender(): void {
    if (this.renderQueued) return;
    this.renderQueued = true;
    requestAnimationFrame(() => this.renderWhenDrawn());
  }

  /**
   * Renders at an animation frame once the GPU has finished the frame before (a fence after each):
   * a frame of a million-vertex plant can keep a software GPU busy for up to a second, and a new
   * plant's upload made meanwhile held the page's thread until then (long tasks of 0.3 to 3 s while
   * typing into that tree, `tests/browser/responsiveness.test.ts`). A GPU is done long before the
   * next frame, and nothing waits.
   */
  private renderWhenDrawn(): void {
    if (!this.gpuIdle()) {
      requestAnimationFrame(() => this.renderWhenDrawn());
      return;
    }
    const gl = this.renderer.getContext();
    if (this.sizeStale) this.resize(); // (while this frame is still queued: no other is asked for)
    this.renderQueued = false;
    this.renderer.render(this.scene, this.active.camera);
    if (gl instanceof WebGL2RenderingContext) this.drawn = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    this.draw2D();
    for (const listener of this.renderListeners) listener();
  }

  /** The GPU has finished the last frame drawn (its fence has passed). */
  private gpuIdle(): boolean {
    const gl = this.renderer.getContext();
    if (!this.drawn || !(gl instanceof WebGL2RenderingContext)) return true;
    if (gl.clientWaitSync(this.drawn, 0, 0) === gl.TIMEOUT_EXPIRED) return false;
    gl.deleteSync(this.drawn);
    this.drawn = null;
    return true;
  }
}
