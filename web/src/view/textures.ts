// Bark and leaf textures for the plant view: the images shipped in public/textures/, loaded
// relative to the site's root (the site may be served from any sub-path, a plant embedded in
// another site's page loads them from Meristem's), and the lit and unlit material
// triples (bark, leaf, plain) indexed by the mesh's material kinds (see addMaterialGroups).
import { ImageLoader, type Material, RepeatWrapping, SRGBColorSpace, Texture } from 'three';
import { litPlantMaterial, unlitPlantMaterial } from './scene-setup';

/** Where a shipped texture is: under `base`, the site's root (the page's own address by default). */
export function textureUrl(name: 'bark' | 'leaf', base: string = document.baseURI): string {
  return new URL(`textures/${name}.png`, base).href;
}

/**
 * A texture whose image loads once `after` settles (at once by default); `onLoad` runs when it
 * arrived (to render again). The image rows run top-down from v = 0, as in glTF (`flipY` off), and
 * it repeats both ways.
 */
export function loadTexture(name: 'bark' | 'leaf', onLoad: () => void, onError: (message: string) => void, base?: string, after: Promise<void> = Promise.resolve()): Texture {
  const texture = new Texture();
  texture.flipY = false;
  texture.wrapS = RepeatWrapping;
  texture.wrapT = RepeatWrapping;
  texture.colorSpace = SRGBColorSpace;
  const url = textureUrl(name, base);
  void after.then(() =>
    new ImageLoader().load(
      url,
      (image) => {
        texture.image = image;
        texture.needsUpdate = true;
        onLoad();
      },
      undefined,
      () => onError(`The ${name} texture could not be loaded.`),
    ),
  );
  return texture;
}

/** The textured materials of the plant: [bark, leaf, plain], lit and unlit. */
export interface TexturedMaterials {
  lit: Material[];
  unlit: Material[];
  dispose(): void;
}

/**
 * Bark: the bark texture times the vertex colour. Leaf: the leaf texture times the vertex colour,
 * cut out where the image is transparent (`alphaTest`), both sides shaded. Plain (spheres):
 * `plainLit` / `plainUnlit`, the untextured materials.
 */
export function texturedMaterials(bark: Texture, leaf: Texture, plainLit: Material, plainUnlit: Material): TexturedMaterials {
  // The plant's own materials (scene-setup.ts), with a texture: set before their first use, when
  // three.js compiles their program.
  const barkLit = Object.assign(litPlantMaterial(), { map: bark });
  const leafLit = Object.assign(litPlantMaterial(), { map: leaf, alphaTest: 0.5 });
  const barkUnlit = Object.assign(unlitPlantMaterial(), { map: bark });
  const leafUnlit = Object.assign(unlitPlantMaterial(), { map: leaf, alphaTest: 0.5 });
  return {
    lit: [barkLit, leafLit, plainLit],
    unlit: [barkUnlit, leafUnlit, plainUnlit],
    dispose() {
      for (const m of [barkLit, leafLit, barkUnlit, leafUnlit]) m.dispose();
      bark.dispose();
      leaf.dispose();
    },
  };
}
