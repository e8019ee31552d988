// The 3D view: one plant mesh, lights, an orbiting perspective camera or a face-on orthographic
// one for flat plants, an optional ground grid; renders on demand. It composes the parts, each in
// a file of its own: the renderer and its frames (./view-renderer.ts), the cameras
// (./camera-rig.ts), the plant on screen (./shown-plant.ts) and on its way to the GPU
// (./plant-upload.ts), its materials (./plant-materials.ts), highlighted modules
// (./module-overlay.ts), the grid (./ground-grid.ts), picking (./view-picking.ts), pictures
// (./snapshot.ts), what is drawn in 2D over the view where a software rasterizer draws it
// (./view-2d.ts).
import { Box3, Color, Scene, Vector3, type Camera, type Object3D, type WebGLRenderer } from 'three';
import type { Bounds, GpuArrays, MeshBuffers } from '../core';
import { CameraRig, type Projection, type ViewPose } from './camera-rig';
import { loadOrbitControls } from './camera-controls';
import { GroundGrid } from './ground-grid';
import { WHOLE } from './growth-arrays';
import { BezierHandles } from './handles';
import { highlightSegments, type Rgb } from './highlight';
import { scenePalette } from './palette';
import { PlantMaterials } from './plant-materials';
import { PlantUpload, type IncomingPlant } from './plant-upload';
import { addSkyLight, drawnSupersampled } from './scene-setup';
import { DEFAULT_LINE_WIDTH, SegmentLines } from './segment-lines';
import { ShownPlant } from './shown-plant';
import { ModuleOverlay } from './module-overlay';
import type { FilmFrames, PictureLook, PictureSource } from './snapshot';
import { View2D } from './view-2d';
import { FrameLoop, compileAhead, maxPictureSide } from './view-renderer';
import { ownTarget, type RenderTarget } from './render-target';
import { ViewPicking } from './view-picking';
import type * as Snapshot from './snapshot';
import type * as Growth from './growth';

const DARK_SCHEME = '(prefers-color-scheme: dark)';


/** How the projection is chosen: from the plant (`auto`: flat plants in 2D), or fixed by the user. */
export type ProjectionMode = 'auto' | Projection;

/**
 * How branches are drawn: `lines` of constant width in pixels (as the book's 2D figures), `tubes`
 * of the grammar's widths, or `auto`: lines for plants drawn in one plane, tubes for 3D ones.
 */
export type RenderMode = 'auto' | 'lines' | 'tubes';

/** Where the camera looks while the growth plays: at the whole (final) plant, or following what has grown. */
export type GrowthCamera = 'final' | 'follow';

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
  /** Where it draws: its own canvas, or one a shared renderer fills (./render-target.ts). */
  private readonly target: RenderTarget;
  /** Ends the listeners on the context's canvas (a shared renderer's outlives the view). */
  private readonly listening = new AbortController();
  private readonly frames: FrameLoop;
  private readonly scene = new Scene();
  // (The parts that make materials are made in this order, as before the split: three.js sorts
  // what it draws by the materials' order of making.)
  private readonly materials = new PlantMaterials();
  private readonly shown = new ShownPlant(this.materials.lit);
  private readonly upload: PlantUpload;
  private readonly grid = new GroundGrid(this.scene);
  /** Highlighted modules, drawn over the plant (which is dimmed meanwhile). */
  private readonly overlay = new ModuleOverlay();
  /** The selected branch's Bézier handles (branch editing). */
  private readonly handles = new BezierHandles();
  private readonly cameras: CameraRig;
  private readonly picking: ViewPicking;
  /** The Lines mode's segments (hidden while tubes are drawn). */
  private readonly segmentLines: SegmentLines;
  /** What is drawn in 2D over the view where a software rasterizer draws it; none elsewhere. */
  private readonly view2D: View2D | undefined;
  private lineWidthChosen = DEFAULT_LINE_WIDTH;
  private lineScale = 1;
  private renderMode: RenderMode = 'auto';
  /** Who needs tubes now whatever the mode (branch editing reshapes tubes). */
  private readonly tubeHolders = new Set<string>();
  /**
   * The last highlight asked for (of the plant last given: a new plant clears it), redrawn when
   * the render mode changes and when a plant that was uploading comes on screen.
   */
  private colourOf: ((module: number) => Rgb | null) | null = null;
  private mode: ProjectionMode = 'auto';
  /** The container's size changed since the drawing buffer was sized ({@link resize} is due). */
  private sizeStale = false;
  private readonly darkScheme = window.matchMedia(DARK_SCHEME);
  private readonly resizeObserver: ResizeObserver;
  /** A plant was given to {@link showPlant} (the textures load after its first frame). */
  private plantShown = false;
  /** Settles when the OrbitControls are attached (see {@link controlsReady}). */
  private readonly controlsLoaded: Promise<void>;
  /** The pictures' code (./snapshot.ts), once asked for (see {@link pictures}). */
  private picturesLoaded: Promise<typeof Snapshot> | undefined;
  /** A movie is being filmed (see {@link film}): the view draws only its frames. */
  private filming = false;
  /** The growth time shown (null: the whole plant), see {@link setGrowthTime}. */
  private growthAt: number | null = null;
  private growthCamera: GrowthCamera = 'final';
  /** Who hears of each plant put on screen ({@link onPlantShown}). */
  private readonly plantListeners = new Set<() => void>();
  /** The growth's shaders (./growth.ts), loaded by the first growth time shown. */
  private growthCode: typeof Growth | undefined;
  private growthLoading: Promise<unknown> | undefined;
  /** Degrees the camera was turned about the plant since it was last framed (a turntable's). */
  private turned = 0;

  /**
   * `assetBase`: the site's root, where the textures are (default: the page's address); `target`:
   * where it draws (default: a canvas and renderer of its own).
   */
  constructor(
    private readonly container: HTMLElement,
    { assetBase, target }: { assetBase?: string; target?: () => RenderTarget } = {},
  ) {
    this.target = (target ?? ownTarget)();
    const { renderer, software } = this.target;
    this.renderer = renderer;
    this.frames = new FrameLoop(renderer, {
      prepare: () => {
        if (this.sizeStale && !this.filming) this.resize(); // (while this frame is still queued: no other is asked for)
      },
      // (While a movie is filmed, its frames are the only ones drawn: see `film`.)
      render: () => {
        if (!this.filming) this.target.render(this.scene, this.cameras.camera);
      },
      after: () => {
        if (!this.filming) this.draw2D();
      },
    });
    // The images (150 KB, not part of any plant's first frame: it shows untextured until they are
    // there) load after the first frame that drew a plant, not beside the core and the script.
    const plantDrawn = new Promise<void>((resolve) => {
      const stop = this.onRender(() => {
        if (!this.plantShown) return;
        stop();
        resolve();
      });
    });
    this.materials.loadTextures(
      assetBase,
      plantDrawn,
      () => this.applyMaterial(),
      (message) => this.texturesFailed(message),
    );
    this.upload = new PlantUpload(renderer.getContext() as WebGL2RenderingContext, () => this.frames.gpuIdle(), (plant) => this.swapIn(plant));
    this.segmentLines = new SegmentLines(this.renderer.capabilities.maxTextureSize);
    const { canvas } = this.target;
    canvas.setAttribute('aria-label', '3D view of the plant; drag or the arrow keys to orbit, scroll or + and − to zoom, Home to fit');
    canvas.tabIndex = 0;
    canvas.addEventListener('keydown', (event) => this.cameras.onKey(event));
    const { signal } = this.listening;
    this.target.contextCanvas.addEventListener('webglcontextlost', () => this.contextLost(), { signal });
    this.target.contextCanvas.addEventListener('webglcontextrestored', () => this.contextRestored(), { signal });
    container.append(canvas);
    if (software) this.view2D = new View2D(container, this.target, this.segmentLines);

    addSkyLight(this.scene);
    this.cameras = new CameraRig(container, canvas, { change: () => this.requestRender(), home: () => this.frame() });
    this.picking = new ViewPicking(canvas, () => this.cameras.camera);
    this.controlsLoaded = plantDrawn.then(loadOrbitControls).then(
      (Controls) => this.cameras.attach(Controls),
      (error: unknown) => console.error('The camera controls could not load:', error),
    );
    this.scene.add(this.cameras.camera, this.shown.drawn, this.shown.lines, this.segmentLines.group, this.overlay.drawn, this.handles.group);
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
    return compileAhead(this.renderer, this.scene, this.cameras.camera, this.materials.all, [this.shown.lines.material, this.grid.material]);
  }

  /** The projection in use. */
  get projection(): Projection {
    return this.cameras.projection;
  }

  /** The camera in use (for tests and the future picking of segments). */
  get camera(): Camera {
    return this.cameras.camera;
  }

  /** The bounding box of what is shown: the mesh, or the lines of the fallback. */
  private visibleBox(): Box3 {
    return this.shown.box(this.usesLines);
  }

  /**
   * Replaces the plant; `flat` says it lies in the plane z = 0 (in `auto` mode it is then shown
   * face-on in 2D). The plant is framed (see the class comment) unless the user moved the camera
   * or the frame is held; a camera's first plant, and the one after {@link frameNextPlant}, always.
   * `gpu`, when given, holds the normals and colours packed smaller for the GPU (by the core, for
   * the build worker): a big plant reaches the GPU in less time. `bounds`: the build's
   * `stats.bounds`, which spare a pass over the mesh (see `plantGeometry`). A big plant goes to
   * the GPU over several tasks while the one before stays on screen ({@link uploading}; see
   * ./plant-upload.ts).
   */
  showPlant(mesh: MeshBuffers, flat = false, gpu?: GpuArrays, bounds?: Bounds): void {
    this.upload.cancel();
    this.colourOf = null; // a highlight names modules of the plant it was asked for
    if (mesh.indices.length === 0 && mesh.lines.length > 0) {
      this.swapIn({ mesh, flat });
      return;
    }
    this.upload.send(mesh, flat, gpu, bounds);
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
    this.view2D?.draw(this.cameras.camera);
  }

  /**
   * Draws the Lines mode's segments of the plant on screen in 2D where a software rasterizer draws
   * the view and the plant is big ({@link View2D.placeLines}); else leaves them to WebGL. Called
   * when the plant, the mode, the width or the highlight changes.
   */
  private placeLines(): void {
    const in2D = this.segmentsIn2D;
    this.segmentLines.drawn = !in2D;
    if (this.view2D?.placeLines(in2D ? this.shown.mesh : undefined)) this.requestRender();
  }

  /**
   * Whether the Lines mode's segments of the plant on screen are to be drawn in 2D ({@link placeLines}):
   * not while a growth time is shown (WebGL grows them by a uniform; see {@link setGrowthTime}).
   */
  private get segmentsIn2D(): boolean {
    return this.view2D !== undefined && this.growthAt === null && this.usesLines && this.view2D.wants(this.shown.mesh);
  }

  /**
   * A plant given to {@link showPlant} is still on its way to the GPU (the one before is on
   * screen meanwhile, and picking finds nothing).
   */
  get uploading(): boolean {
    return this.upload.pending !== undefined;
  }

  /** Puts a plant (its geometry on the GPU, or its lines) on screen in place of the old one. */
  private swapIn(plant: IncomingPlant): void {
    const { mesh, onGpu } = plant;
    this.plantShown = true;
    const asLines = onGpu === undefined;
    // One-pixel lines (a sketch, a plant too large to mesh) where a software rasterizer draws the
    // view: in 2D over it (./sketch-canvas.ts); the WebGL frame, drawn without them, costs that
    // rasterizer next to nothing. (The Lines mode's segments are drawn again by colourModules
    // below, if they are to be.)
    const lines2D = this.view2D?.showPlant(asLines ? mesh : undefined) ?? false;
    this.shown.lines.visible = !lines2D;
    this.shown.replace(plant);
    this.showGrowth(null); // a new plant shows whole until a growth time is set again
    // Whether WebGL draws them, said with them: its geometry of segments drawn in 2D is not made.
    this.segmentLines.show(asLines ? null : mesh, !this.segmentsIn2D);
    this.applyMaterial();
    this.colourModules(this.colourOf); // what was asked for while it uploaded, if anything
    // A mesh without tubes (the Lines mode's) may hold no triangle: its segments are drawn.
    const hasGeometry = mesh.indices.length > 0 || asLines || (mesh.segmentEnds.length > 0 && this.usesLines);
    if (hasGeometry) this.cameras.frameNextIfAsked();
    this.useProjection(this.wantedProjection(), hasGeometry);
    if (hasGeometry) this.follow();
    this.requestRender();
    // What is drawn in 2D, drawn now with the camera framed on it, not in the frame: the WebGL
    // frame comes on screen no later for it (the frame redraws it only if the camera or size changed).
    this.draw2D();
    for (const listener of this.plantListeners) listener();
  }

  /**
   * Calls `listener` each time a new plant is on screen (all of it on the GPU; shown whole, see
   * {@link setGrowthTime}); returns the function that stops it.
   */
  onPlantShown(listener: () => void): () => void {
    this.plantListeners.add(listener);
    return () => this.plantListeners.delete(listener);
  }

  /**
   * Shows the plant on screen at growth time `t` (in derivation steps, 0 … {@link growthSpan}; see
   * ./growth.ts), or whole (`null`, the default after every new plant). One uniform changes and a
   * frame is asked for: no build, no upload. A plant without growth arrays is shown whole. With
   * the camera {@link setGrowthCamera following} the growth, the camera frames what has grown.
   */
  setGrowthTime(t: number | null): void {
    const time = t === null || !Number.isFinite(t) ? null : t;
    if (time === this.growthAt) return;
    this.showGrowth(time);
    if (time !== null && !this.growthCode) this.loadGrowth();
    // What is drawn in 2D is WebGL's while a growth time is shown: the growth's shaders grow it
    // there by a uniform (grown on the CPU and drawn in 2D, ABOP 1.24d at n = 10 took 15 ms of the
    // page's thread a frame).
    if (this.view2D) {
      this.placeLines();
      this.shown.lines.visible = !this.view2D.thinIn2D(time === null);
    }
    const bounds = time !== null && this.growthCamera === 'follow' ? this.growthCode?.grownBounds(this.shown, time) : null;
    if (bounds) {
      const turned = this.turned;
      this.frame(bounds);
      this.turn(turned); // the turntable's angle kept
    }
    this.requestRender();
  }

  /** The growth time shown, or null (the whole plant). */
  get growthTime(): number | null {
    return this.growthAt;
  }

  private showGrowth(t: number | null): void {
    this.growthAt = t;
    this.materials.growthTime.value = t ?? WHOLE;
    this.growthCode?.drawGrown(this.shown.drawn, this.shown.pickable.geometry, this.renderer.getContext() as WebGL2RenderingContext, t);
  }

  /**
   * Loads the growth's shaders (a chunk of its own, which no first plant needs) and makes the
   * plant's materials grow with the growth time; the time shown meanwhile is shown again then.
   */
  private loadGrowth(): void {
    this.growthLoading ??= import('./growth').then(
      (code) => {
        this.growthCode = code;
        this.materials.grow(code, [this.shown.lines.material]);
        new code.LineGrowth(this.materials.growthTime).attach(this.segmentLines);
        const t = this.growthAt;
        this.growthAt = null;
        this.setGrowthTime(t);
        this.requestRender();
      },
      (error: unknown) => {
        this.growthLoading = undefined; // tried again by the next time shown
        console.error('The growth could not load:', error);
      },
    );
  }

  /** Settles once a growth time can be drawn (its shaders loaded); for tests and pictures. */
  get growthReady(): Promise<unknown> {
    this.loadGrowth();
    return this.growthLoading!;
  }

  /** N when the plant on screen carries growth arrays (it can be shown at any t in [0, N]), else null. */
  growthSpan(): number | null {
    return this.upload.pending ? null : this.shown.growthSpan;
  }

  /** Where the camera looks while the growth is shown: at the whole plant (`final`) or at what has grown (`follow`). */
  setGrowthCamera(mode: GrowthCamera): void {
    this.growthCamera = mode;
    if (mode === 'final') this.frame();
    else if (this.growthAt !== null) {
      const t = this.growthAt;
      this.growthAt = null;
      this.setGrowthTime(t);
    }
  }

  /** Turns the camera `degrees` about the plant's vertical axis (a turntable; flat plants stay face-on). */
  turn(degrees: number): void {
    this.turned = (this.turned + degrees) % 360;
    this.cameras.turn(degrees);
  }

  /** Frames the new plant on screen, or keeps the camera (and hints at a refit if the user moved it). */
  private follow(): void {
    if (this.cameras.follows()) this.frame();
  }

  /**
   * Holds the frame for `holder` (`on`) or lets it go: while anyone holds it, new plants keep the
   * camera where it is and no refit is hinted.
   */
  holdFrame(holder: string, on: boolean): void {
    this.cameras.hold(holder, on);
  }

  /** Follows the plant again from the next one, as if the user had not moved the camera. */
  followAgain(): void {
    this.cameras.moved = false;
  }

  /**
   * Calls `listener` with `true` when a new plant was not framed because the user had moved the
   * camera (a "Refit" hint is due), and with `false` once the view is framed again.
   */
  onRefitHint(listener: (shown: boolean) => void): () => void {
    return this.cameras.onRefitHint(listener);
  }

  /**
   * Paints the triangles of the modules `colourOf` names in its colour and dims the rest; `null`
   * restores the plant's own colours. (The line fallback of huge models is not highlighted.)
   */
  colourModules(colourOf: ((module: number) => Rgb | null) | null): void {
    this.colourOf = colourOf;
    // The modules are then the incoming plant's: they are painted when it is on screen.
    if (this.upload.pending) return;
    const mesh = this.shown.mesh;
    const lines = this.usesLines;
    const highlight = { over: mesh && colourOf && lines ? highlightSegments(mesh, colourOf) : null, dim: mesh && colourOf ? 0.55 : 1 };
    this.view2D?.highlight(highlight);
    this.segmentLines.highlight(highlight.over, highlight.dim);
    this.placeLines();
    this.overlay.show(mesh, colourOf, !lines, this.shown.normalsOnGpu);
    this.materials.dim(highlight.dim); // the rest dimmed while some modules are highlighted
    this.requestRender();
  }

  /** The module of the derived string drawn at a point of the page, or null (nothing there). */
  pickModule(clientX: number, clientY: number): number | null {
    if (this.upload.pending) return null;
    return this.picking.module(clientX, clientY, this.shown, this.usesLines, this.segmentLines);
  }

  /** The triangle of the mesh on screen at a point of the page, or null. */
  pickTriangle(clientX: number, clientY: number): number | null {
    if (this.upload.pending) return null;
    return this.picking.triangle(clientX, clientY, this.shown);
  }

  /**
   * After vertices of the mesh on screen were changed in place (its arrays are the geometry's),
   * uploads only `ranges` ((first vertex, count) pairs) and updates the bounds.
   */
  patchVertices(ranges: Uint32Array): void {
    this.shown.patchVertices(ranges, this.upload.pending);
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
    return this.handles.hit(this.picking.aim(clientX, clientY));
  }

  /** Where a point of the page meets the plane through `through` facing the camera (a drag's target). */
  dragTarget(clientX: number, clientY: number, through: [number, number, number]): [number, number, number] | null {
    return this.picking.dragTarget(clientX, clientY, through);
  }

  /** A model point's place on the page (CSS pixels), for tests and tooltips. */
  pageOf(point: [number, number, number]): { x: number; y: number } {
    return this.picking.pageOf(point);
  }

  /** Lets the mouse orbit the camera, or not (while a handle is dragged). */
  setOrbitEnabled(enabled: boolean): void {
    this.cameras.setOrbitEnabled(enabled);
  }

  /** The canvas, for pointer events. */
  get canvas(): HTMLCanvasElement {
    return this.target.canvas;
  }

  /**
   * Where the camera in use stands: what a share link keeps. `zoom` is the orthographic camera's
   * (1 for the perspective one).
   */
  cameraPose(): ViewPose {
    return this.cameras.pose();
  }

  /**
   * Puts the camera in use where `pose` says (after framing it on the plant on screen, for its
   * clipping planes and the grid), and keeps it there across later plants.
   */
  setCameraPose(pose: ViewPose): void {
    this.frame();
    this.cameras.setPose(pose);
    this.requestRender();
  }

  /** Frames the camera on the next plant shown (e.g. after another example was opened). */
  frameNextPlant(): void {
    this.cameras.frameNext = true;
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
    return this.shown.flat ? 'orthographic' : 'perspective';
  }

  private useProjection(projection: Projection, frameIfNew: boolean): void {
    if (!this.cameras.use(projection, this.scene)) return;
    this.container.dataset.projection = projection;
    this.resize();
    if (frameIfNew && !this.cameras.framed && !this.visibleBox().isEmpty()) this.frame();
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
    this.turned = 0;
    this.cameras.frame(box);
    this.placeGrid(box);
    this.requestRender();
  }

  /**
   * A PNG of the current view at `width` × `height` pixels (see ./snapshot.ts). With
   * `look.background` white or transparent the picture has that background and no grid; the
   * lines are `look.lineWidth` of its pixels wide.
   */
  async snapshot(width: number, height: number, look: PictureLook = { background: 'view' }): Promise<Blob> {
    const { snapshot } = await this.pictures();
    return snapshot(this.pictureSource(), width, height, look);
  }

  /**
   * A movie's frames (see ./snapshot.ts `filmFrames`): the camera turned about the plant, each
   * frame drawn at a size in `look`. The view draws nothing else until `close` puts it back.
   */
  async film(look: PictureLook): Promise<FilmFrames> {
    const { filmFrames } = await this.pictures();
    this.filming = true;
    return filmFrames(this.pictureSource(), look, () => {
      this.filming = false;
      this.requestRender();
    });
  }

  /** What pictures are drawn from, with the plant last given on screen. */
  private pictureSource(): PictureSource {
    this.upload.finish(); // the picture is of the plant last given
    const { renderer, scene, shown, grid, segmentLines, view2D } = this;
    const camera = this.cameras.camera;
    return {
      renderer,
      scene,
      camera,
      target: this.cameras.pose().target,
      shown,
      grid,
      segmentLines,
      view2D,
      white: new Color('#ffffff'),
      maxSide: maxPictureSide(renderer),
      draw: (scale: number) => drawnSupersampled(scale, () => renderer.render(scene, camera)),
      resize: () => this.resize(),
    };
  }

  /**
   * The pictures' code: a chunk of its own, which no first plant needs (the first load's budget,
   * tests/browser/first-load.test.ts), loaded by the first picture.
   */
  private pictures(): Promise<typeof Snapshot> {
    return (this.picturesLoaded ??= import('./snapshot'));
  }

  /** The largest picture side the GPU can draw (its renderbuffer and viewport limits). */
  maxPictureSide(): number {
    return maxPictureSide(this.renderer);
  }

  /** Shows or hides the ground grid. */
  setGridVisible(visible: boolean): void {
    this.grid.visible = visible;
    this.requestRender();
  }

  /** Lit and shaded (true), or the palette's colours unshaded (false). */
  setLighting(lit: boolean): void {
    this.materials.lighting = lit;
    this.applyMaterial();
  }

  /** Bark and leaf textures on (true, the default) or off (the palette's colours alone). */
  setTextures(on: boolean): void {
    this.materials.texturing = on;
    this.applyMaterial();
  }

  private applyMaterial(): void {
    const lines = this.usesLines;
    this.shown.material = this.materials.chosen(lines);
    this.segmentLines.visible = lines;
    this.container.dataset.render = lines ? 'lines' : 'tubes';
    this.container.dataset.textures = String(this.materials.texturesOn);
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
    const mesh = this.shown.mesh;
    if (!mesh || mesh.segmentModules.length === 0 || this.tubeHolders.size > 0) return false;
    return this.renderMode === 'lines' || (this.renderMode === 'auto' && this.shown.flat);
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

  /**
   * Draws `layer` with the plant (the environment's: ./environment-layer.ts), or draws it again
   * after it changed; `show` false takes it away.
   */
  drawLayer(layer: Object3D, show = true): void {
    if (show) this.scene.add(layer);
    else this.scene.remove(layer);
    this.requestRender();
  }

  /** Calls `listener` after every frame drawn; returns the function that stops it. */
  onRender(listener: () => void): () => void {
    return this.frames.onRender(listener);
  }

  /** Releases the GPU resources and listeners. */
  dispose(): void {
    this.resizeObserver.disconnect();
    this.darkScheme.removeEventListener('change', this.applyPalette);
    this.cameras.dispose();
    this.upload.cancel();
    this.shown.dispose(this.upload.buffers);
    for (const part of [this.overlay, this.segmentLines, this.materials, this.grid]) part.dispose();
    this.listening.abort();
    this.target.dispose();
    this.view2D?.clear();
  }

  /** The grid under (or behind, in 2D) the plant in `box`. */
  private placeGrid(box: Box3): void {
    this.grid.place(box, this.cameras.projection === 'orthographic', scenePalette(this.darkScheme.matches));
  }

  private readonly applyPalette = (): void => {
    const palette = scenePalette(this.darkScheme.matches);
    this.scene.background = palette.background;
    if (this.grid.placed) this.placeGrid(this.visibleBox());
    this.requestRender();
  };

  private resize(): void {
    this.sizeStale = false;
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.target.setSize(width, height);
    this.cameras.resize(width, height);
    this.requestRender();
  }

  /**
   * The browser took the view's WebGL context away (a phone's browser sent to the background, a
   * GPU reset): every buffer and fence of it went too. three.js makes its own again when the
   * context comes back; the plant's are the view's own (`GpuGeometry`): see
   * {@link contextRestored}.
   */
  private contextLost(): void {
    this.frames.forgetFence();
    this.upload.buffers.clear(true);
  }

  /**
   * The context is back (three.js has made its state again, its listener being first): the plant
   * on screen, and one on its way, go to the GPU again from their arrays, and the view draws.
   */
  private contextRestored(): void {
    this.contextLost(); // and any buffers given back while it was
    this.shown.restored(this.upload);
    this.upload.restored();
    this.requestRender();
  }

  private requestRender(): void {
    this.frames.request();
  }
}
