// The view's two cameras: an orbiting perspective one and a face-on orthographic one (for flat
// plants, pan and zoom only), each with its controls and headlight; which is in use, framing one
// on a box, whether a new plant is framed (the holds on the frame, the "Refit" hint), its pose for
// a share link, and the keys that move it.
import type { Box3} from 'three';
import { MathUtils, OrthographicCamera, PerspectiveCamera, Spherical, Vector3, type Scene } from 'three';
import type { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { CameraControls } from './camera-controls';
import { flatPose, framePose } from './framing';
import { addHeadlight } from './scene-setup';

/** `perspective`: orbit in 3D; `orthographic`: the XY plane face-on (2D), pan and zoom only. */
export type Projection = 'perspective' | 'orthographic';

/** A camera's place: eye, the point it looks at (the orbit's centre), and the orthographic zoom. */
export interface ViewPose {
  position: [number, number, number];
  target: [number, number, number];
  zoom: number;
}

/** One of the two cameras with its controls and whether it has been framed on a plant yet. */
interface RiggedCamera<C extends PerspectiveCamera | OrthographicCamera> {
  camera: C;
  controls: CameraControls;
  framed: boolean;
}

/** What the rig tells the view. */
export interface CameraRigEvents {
  /** The camera moved (render again). */
  change(): void;
  /** The Home key: fit the plant on screen. */
  home(): void;
}

/**
 * The perspective and the orthographic camera of a view in `container` (whose size gives the
 * aspect), moved by the user on `canvas`. {@link moved} says whether the user orbited, panned or
 * zoomed since the last fit; {@link follows} whether a new plant is to be framed.
 */
export class CameraRig {
  private readonly perspective: RiggedCamera<PerspectiveCamera>;
  private readonly orthographic: RiggedCamera<OrthographicCamera>;
  private active: RiggedCamera<PerspectiveCamera> | RiggedCamera<OrthographicCamera>;
  /** The user orbited, panned or zoomed since the last fit: new plants keep the camera. */
  moved = false;
  /** Frame the next plant shown, even if the camera was moved (a new grammar was opened). */
  frameNext = false;
  /** Who holds the frame now (e.g. `editing`, `play`): while anyone does, new plants keep it. */
  private readonly holders = new Set<string>();
  private refitHinted = false;
  private readonly refitListeners = new Set<(shown: boolean) => void>();

  constructor(
    private readonly container: HTMLElement,
    private readonly canvas: HTMLElement,
    private readonly events: CameraRigEvents,
  ) {
    this.perspective = this.rig(new PerspectiveCamera(40, 1, 0.01, 1000));
    this.orthographic = this.rig(new OrthographicCamera(-1, 1, 1, -1, 0.01, 1000));
    this.orthographic.controls.enableRotate = false; // a 2D view pans and zooms
    this.active = this.perspective;
    this.perspective.controls.enabled = true;
  }

  private rig<C extends PerspectiveCamera | OrthographicCamera>(camera: C): RiggedCamera<C> {
    addHeadlight(camera);
    const controls = new CameraControls(camera, this.canvas, {
      change: () => this.events.change(),
      start: () => (this.moved = true),
    });
    return { camera, controls, framed: false };
  }

  /** Hands both cameras to three's OrbitControls (the mouse and touch move them from then on). */
  attach(Controls: typeof OrbitControls): void {
    this.perspective.controls.attach(Controls);
    this.orthographic.controls.attach(Controls);
  }

  /** The camera in use. */
  get camera(): PerspectiveCamera | OrthographicCamera {
    return this.active.camera;
  }

  /** The projection in use. */
  get projection(): Projection {
    return this.active === this.orthographic ? 'orthographic' : 'perspective';
  }

  /** Whether the camera in use has been framed on a plant. */
  get framed(): boolean {
    return this.active.framed;
  }

  /** A plant came: if {@link frameNext} asked for it, both cameras are to be framed on it, moved or not. */
  frameNextIfAsked(): void {
    if (!this.frameNext) return;
    this.frameNext = false;
    this.perspective.framed = false;
    this.orthographic.framed = false;
  }

  /**
   * Whether a new plant is to be framed: always by a camera not framed yet; else not while the
   * frame is held, nor once the user moved the camera (then a refit is hinted).
   */
  follows(): boolean {
    if (!this.active.framed) return true;
    else if (this.holders.size > 0) return false;
    else if (!this.moved) return true;
    this.hintRefit(true);
    return false;
  }

  /** Holds the frame for `holder` (`on`) or lets it go. */
  hold(holder: string, on: boolean): void {
    if (on) this.holders.add(holder);
    else this.holders.delete(holder);
  }

  /** Calls `listener` when the refit hint shows (`true`) or goes (`false`); returns the function that stops it. */
  onRefitHint(listener: (shown: boolean) => void): () => void {
    this.refitListeners.add(listener);
    return () => this.refitListeners.delete(listener);
  }

  /** Shows the hint or takes it away (its listeners hear of a change only). */
  private hintRefit(shown: boolean): void {
    if (shown === this.refitHinted) return;
    this.refitHinted = shown;
    for (const listener of this.refitListeners) listener(shown);
  }

  /**
   * Puts the camera of `projection` in use (and its headlight in `scene`, in place of the other's);
   * false if it was in use already.
   */
  use(projection: Projection, scene: Scene): boolean {
    const next = projection === 'orthographic' ? this.orthographic : this.perspective;
    if (next === this.active) return false;
    this.active.controls.enabled = false;
    scene.remove(this.active.camera); // its headlight goes with it
    this.active = next;
    this.active.controls.enabled = true;
    scene.add(this.active.camera);
    return true;
  }

  /** Lets the mouse orbit the camera in use, or not (while a handle is dragged). */
  setOrbitEnabled(enabled: boolean): void {
    this.active.controls.enabled = enabled;
  }

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

  /** Both cameras take the aspect of a view `width` × `height`. */
  resize(width: number, height: number): void {
    this.perspective.camera.aspect = width / height;
    this.perspective.camera.updateProjectionMatrix();
    this.fitOrthographic();
  }

  /** Points the camera in use at the whole of `box`, and follows the plant again (no refit hint). */
  frame(box: Box3): void {
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
  }

  /**
   * Where the camera in use stands: what a share link keeps. `zoom` is the orthographic camera's
   * (1 for the perspective one).
   */
  pose(): ViewPose {
    const { camera, controls } = this.active;
    return {
      position: camera.position.toArray() as [number, number, number],
      target: controls.target.toArray() as [number, number, number],
      zoom: this.active === this.orthographic ? this.orthographic.camera.zoom : 1,
    };
  }

  /** Puts the camera in use where `pose` says (once framed), and keeps it there across later plants. */
  setPose(pose: ViewPose): void {
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
  }

  /**
   * Keys on the focused view: the arrows orbit (in 2D they pan), + and − zoom, Home fits the plant;
   * Shift makes the steps finer. Other keys (Ctrl+Z for branch edits) pass.
   */
  onKey(event: KeyboardEvent): void {
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
      Home: () => this.events.home(),
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
    this.events.change();
  }

  /**
   * Turns the perspective camera `degrees` about the vertical through its target (a turntable; the
   * face-on camera of flat plants does not turn).
   */
  turn(degrees: number): void {
    if (this.active.camera instanceof OrthographicCamera || degrees === 0) return;
    this.orbit(degrees, 0);
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
    this.events.change();
  }

  /** Removes the controls' listeners. */
  dispose(): void {
    this.perspective.controls.dispose();
    this.orthographic.controls.dispose();
  }
}
