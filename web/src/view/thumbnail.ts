// Small pictures of plants for the gallery, drawn like the studio's view (same materials, lights
// and framing; flat plants face-on) on a transparent background, so they suit light and dark.
import { Mesh, OrthographicCamera, PerspectiveCamera, Scene, WebGLRenderer, LineBasicMaterial, LineSegments } from 'three';
import type { MeshBuffers } from '../core';
import { flatPose, framePose } from './framing';
import { plantGeometry } from './plant-geometry';
import { addHeadlight, addSkyLight, litPlantMaterial } from './scene-setup';

/** Renders plants one at a time into an offscreen canvas and returns each as a PNG data URL. */
export class ThumbnailRenderer {
  private readonly renderer: WebGLRenderer;
  private readonly material = litPlantMaterial();
  private readonly lineMaterial = new LineBasicMaterial({ vertexColors: true });

  /** `width` × `height` CSS pixels, drawn at twice that for sharp thumbnails on dense screens. */
  constructor(
    readonly width = 160,
    readonly height = 120,
  ) {
    this.renderer = new WebGLRenderer({ antialias: true, alpha: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(2);
    this.renderer.setSize(width, height, false);
    this.renderer.setClearColor(0x000000, 0);
  }

  /** The picture of one plant; `flat` plants are drawn face-on with an orthographic camera. */
  render(mesh: MeshBuffers, flat: boolean): string {
    const scene = new Scene();
    addSkyLight(scene);
    const geometry = plantGeometry(mesh);
    const asLines = mesh.indices.length === 0 && mesh.lines.length > 0;
    scene.add(asLines ? new LineSegments(geometry, this.lineMaterial) : new Mesh(geometry, this.material));
    const box = geometry.boundingBox!;
    const aspect = this.width / this.height;
    let camera: PerspectiveCamera | OrthographicCamera;
    if (flat) {
      const pose = flatPose(box, aspect);
      const h = pose.halfHeight;
      camera = new OrthographicCamera(-h * aspect, h * aspect, h, -h, pose.near, pose.far);
      camera.position.copy(pose.position);
      camera.lookAt(pose.target);
    } else {
      const perspective = new PerspectiveCamera(40, aspect);
      const pose = framePose(box, perspective.fov, aspect);
      perspective.position.copy(pose.position);
      perspective.near = pose.near;
      perspective.far = pose.far;
      perspective.lookAt(pose.target);
      camera = perspective;
    }
    camera.updateProjectionMatrix();
    addHeadlight(camera);
    scene.add(camera);
    this.renderer.render(scene, camera);
    const url = this.renderer.domElement.toDataURL('image/png');
    geometry.dispose();
    return url;
  }

  /** Releases the GPU context. */
  dispose(): void {
    this.material.dispose();
    this.lineMaterial.dispose();
    this.renderer.dispose();
    this.renderer.forceContextLoss();
  }
}
