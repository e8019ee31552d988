// Highlighted modules drawn over the plant: their triangles in the highlight's colours, a little
// in front of the plant's own (which is dimmed meanwhile).
import { BufferAttribute, BufferGeometry, DoubleSide, Mesh, MeshStandardMaterial } from 'three';
import type { MeshBuffers } from '../core';
import { highlightOverlay, type Rgb } from './highlight';
import { atLeastAPixelWide } from './scene-setup';

/** The overlay of highlighted modules: add {@link drawn} to the scene. */
export class ModuleOverlay {
  readonly drawn = new Mesh(
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

  /**
   * Paints the triangles of `mesh`'s modules that `colourOf` names in its colour (those of its
   * tubes too when `tubes`), with the `normals` on the GPU; with no mesh or `colourOf`, nothing.
   */
  show(mesh: MeshBuffers | undefined, colourOf: ((module: number) => Rgb | null) | null, tubes: boolean, normals: Float32Array | Int16Array | undefined): void {
    const old = this.drawn.geometry;
    this.drawn.geometry = new BufferGeometry();
    old.dispose();
    if (!mesh || !colourOf) return;
    const overlay = highlightOverlay(mesh, colourOf, tubes, normals ?? mesh.normals);
    const geometry = this.drawn.geometry;
    geometry.setAttribute('position', new BufferAttribute(overlay.positions, 3));
    geometry.setAttribute('normal', new BufferAttribute(overlay.normals, 3));
    geometry.setAttribute('color', new BufferAttribute(overlay.colors, 3));
    geometry.computeBoundingSphere();
  }

  dispose(): void {
    this.drawn.geometry.dispose();
    this.drawn.material.dispose();
  }
}
