// The mouse and touch controls of one camera: three's OrbitControls, which load after the first
// plant has been drawn (issue 22, the first load: 20 KB of script the first frame does without).
// Until they are there the camera already has its target, and code moves it as the controls
// would (framing, a link's camera, the view's keys); then they take over the same target.
import type { OrthographicCamera, PerspectiveCamera, Vector3 } from 'three';
import { Vector3 as Point } from 'three';
import type { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

/** What the controls tell the view. */
export interface CameraControlsEvents {
  /** The camera moved (render again). */
  change(): void;
  /** A gesture of the user began (never a change made in code). */
  start(): void;
}

/** Loads three's OrbitControls once (a chunk of its own). */
export function loadOrbitControls(): Promise<typeof OrbitControls> {
  return import('three/examples/jsm/controls/OrbitControls.js').then((module) => module.OrbitControls);
}

/** A camera's controls: its target always, the OrbitControls once {@link attach} gave them. */
export class CameraControls {
  /** The point the camera looks at and orbits about (the OrbitControls' own target once attached). */
  readonly target: Vector3 = new Point();
  private orbit: OrbitControls | undefined;
  private on = false;
  private rotate = true;
  private disposed = false;

  constructor(
    private readonly camera: PerspectiveCamera | OrthographicCamera,
    private readonly element: HTMLElement,
    private readonly events: CameraControlsEvents,
  ) {}

  /** Whether the user's gestures move this camera (the one in use, and no handle is dragged). */
  get enabled(): boolean {
    return this.on;
  }

  set enabled(on: boolean) {
    this.on = on;
    if (this.orbit) this.orbit.enabled = on;
  }

  /** Whether a drag turns the camera (false: it pans, as in a 2D view). */
  set enableRotate(rotate: boolean) {
    this.rotate = rotate;
    if (this.orbit) this.orbit.enableRotate = rotate;
  }

  /** Whether the OrbitControls are there (the user can drag the camera). */
  get attached(): boolean {
    return this.orbit !== undefined;
  }

  /** After the camera or the target moved in code: the camera looks at the target. */
  update(): void {
    if (this.orbit) this.orbit.update();
    else this.camera.lookAt(this.target);
  }

  /** Hands the camera to OrbitControls (once), on the same target, enabled as these are. */
  attach(Controls: typeof OrbitControls): void {
    if (this.orbit || this.disposed) return;
    const orbit = new Controls(this.camera, this.element);
    orbit.target = this.target;
    orbit.enabled = this.on;
    orbit.enableRotate = this.rotate;
    orbit.addEventListener('change', () => this.events.change());
    orbit.addEventListener('start', () => this.events.start());
    orbit.update();
    // OrbitControls write `cursor: auto` on the element as they connect: the stylesheet's
    // cursors (Reshape's crosshair) would never show.
    this.element.style.removeProperty('cursor');
    this.orbit = orbit;
  }

  /** Removes the OrbitControls' listeners. */
  dispose(): void {
    this.disposed = true;
    this.orbit?.dispose();
  }
}
