// Small pictures of plants for the gallery, drawn like the studio's view (same materials, lights
// and framing; flat plants face-on) on a transparent background, so they suit light and dark.
// It runs where a canvas is: in the thumbnail worker on an OffscreenCanvas (the page never waits
// for a big plant to be drawn), or on a page's canvas.
import { LineBasicMaterial, LineSegments, Mesh, Scene, WebGLRenderer } from 'three';
import type { MeshBuffers } from '../core';
import { orthographicCameraOn, perspectiveCameraOn } from './framing';
import { plantGeometry } from './plant-geometry';
import { addHeadlight, addSkyLight, litPlantMaterial } from './scene-setup';

/** Renders plants one at a time into a canvas and returns each as a PNG. */
export class ThumbnailRenderer {
  private readonly renderer: WebGLRenderer;
  private readonly material = litPlantMaterial();
  private readonly lineMaterial = new LineBasicMaterial({ vertexColors: true });

  /** Draws into `canvas` at `width` × `height` CSS pixels, twice as many device pixels for sharpness. */
  constructor(
    private readonly canvas: OffscreenCanvas | HTMLCanvasElement,
    readonly width = 160,
    readonly height = 120,
  ) {
    this.renderer = new WebGLRenderer({ canvas, antialias: true, alpha: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(2);
    this.renderer.setSize(width, height, false);
    this.renderer.setClearColor(0x000000, 0);
  }

  /** The picture of one plant as a PNG; `flat` plants are drawn face-on with an orthographic camera. */
  render(mesh: MeshBuffers, flat: boolean): Promise<Blob> {
    const scene = new Scene();
    addSkyLight(scene);
    const geometry = plantGeometry(mesh);
    const asLines = mesh.indices.length === 0 && mesh.lines.length > 0;
    scene.add(asLines ? new LineSegments(geometry, this.lineMaterial) : new Mesh(geometry, this.material));
    const box = geometry.boundingBox!;
    const aspect = this.width / this.height;
    const camera = flat ? orthographicCameraOn(box, aspect) : perspectiveCameraOn(box, aspect);
    addHeadlight(camera);
    scene.add(camera);
    this.renderer.render(scene, camera);
    geometry.dispose();
    const canvas = this.canvas;
    if ('convertToBlob' in canvas) return canvas.convertToBlob({ type: 'image/png' });
    return new Promise((resolve, reject) => canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('no picture'))), 'image/png'));
  }

  /** Releases the GPU context. */
  dispose(): void {
    this.material.dispose();
    this.lineMaterial.dispose();
    this.renderer.dispose();
    this.renderer.forceContextLoss();
  }
}
