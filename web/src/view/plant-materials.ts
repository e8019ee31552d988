// The plant's materials in the view: lit or unlit, textured (bark and leaf) once both images are
// there and while the toggle is on, and the stand-in that hides the tubes in the Lines mode.
import { MeshBasicMaterial, type Material } from 'three';
import type * as Growth from './growth';
import { WHOLE, type GrowthUniform } from './growth-arrays';
import { litPlantMaterial, unlitPlantMaterial } from './scene-setup';
import { loadTexture, texturedMaterials, type TexturedMaterials } from './textures';

/** The plant's materials and the choice between them. */
export class PlantMaterials {
  /** The growth time every material of the plant (and its lines) is drawn at (./growth.ts). */
  readonly growthTime: GrowthUniform = { value: WHOLE };
  readonly lit = litPlantMaterial();
  readonly unlit = unlitPlantMaterial();
  /** Stands in for the tubes' material in the Lines mode: their triangles are not drawn. */
  private readonly hiddenTubes = new MeshBasicMaterial({ visible: false });
  /**
   * Bark and leaf textured materials ([bark, leaf, plain], by the mesh's material groups), made by
   * {@link loadTextures} (after the view's other materials, as before: three.js sorts what it
   * draws by the materials' order of making).
   */
  private textured!: TexturedMaterials;
  lighting = true;
  texturing = true;
  /** Images loaded so far (of 2): the plant shows untextured until both are there. */
  private texturesLoaded = 0;

  /**
   * Makes the textured materials (once, before any other use): their images load from
   * `assetBase` (the site's root; default: the page's address) once `after` settles; `loaded`
   * hears of each image that arrived (the plant may now be drawn textured), `failed` of one that
   * did not load.
   */
  loadTextures(assetBase: string | undefined, after: Promise<void>, loaded: () => void, failed: (message: string) => void): void {
    const texture = (name: 'bark' | 'leaf') =>
      loadTexture(
        name,
        () => {
          this.texturesLoaded++;
          loaded();
        },
        failed,
        assetBase,
        after,
      );
    this.textured = texturedMaterials(texture('bark'), texture('leaf'), this.lit, this.unlit);
  }

  /** Whether the plant is drawn textured (the toggle is on and both images are there). */
  get texturesOn(): boolean {
    return this.texturing && this.texturesLoaded === 2;
  }

  /**
   * The plant's material as chosen (lit or not, textured or not); by material kind (bark, leaf,
   * plain) when `lines`: in the Lines mode the tubes give way to the lines.
   */
  chosen(lines: boolean): Material | Material[] {
    const textured = this.lighting ? this.textured.lit : this.textured.unlit;
    const material = this.texturesOn ? textured : this.lighting ? this.lit : this.unlit;
    const kinds = Array.isArray(material) ? material : [material, material, material];
    return lines ? [this.hiddenTubes, kinds[1], kinds[2]] : material;
  }

  /**
   * Makes every material of the plant, and `more` (its lines'), grow with {@link growthTime}
   * (./growth.ts, loaded then): their programs are made again for the next frame.
   */
  grow({ growingMaterial }: typeof Growth, more: Material[]): void {
    for (const material of new Set([...this.all, ...more])) {
      growingMaterial(material, this.growthTime);
      material.needsUpdate = true;
    }
  }

  /** Every material the plant may be drawn with (whose programs can be compiled ahead). */
  get all(): Material[] {
    return [this.lit, this.unlit, ...this.textured.lit, ...this.textured.unlit];
  }

  /** The plant's colours times `dim` (below 1 while some modules are highlighted). */
  dim(dim: number): void {
    this.lit.color.setScalar(dim);
    this.unlit.color.setScalar(dim);
    for (const m of [...this.textured.lit, ...this.textured.unlit]) (m as MeshBasicMaterial).color.setScalar(dim);
  }

  dispose(): void {
    this.hiddenTubes.dispose();
    this.lit.dispose();
    this.unlit.dispose();
    this.textured.dispose();
  }
}
