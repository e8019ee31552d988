// The parts of a plant scene shared by the studio's view and the gallery thumbnails, so both
// show a plant the same way: materials, and lights that follow the camera.
import type {
  Camera,
  Scene} from 'three';
import {
  DirectionalLight,
  DoubleSide,
  HemisphereLight,
  type Material,
  MeshBasicMaterial,
  MeshStandardMaterial,
  Vector4,
} from 'three';

/** The plant's lit material: vertex colours (the core's palette), both faces, matte. */
export function litPlantMaterial(): MeshStandardMaterial {
  return atLeastAPixelWide(new MeshStandardMaterial({ vertexColors: true, side: DoubleSide, roughness: 0.85, metalness: 0 }));
}

/** The unlit material (lighting off): the palette's colours as they are, no shading. */
export function unlitPlantMaterial(): MeshBasicMaterial {
  return atLeastAPixelWide(new MeshBasicMaterial({ vertexColors: true, side: DoubleSide }));
}

/**
 * The end of the vertex shader's `main` (after three.js's chunks have placed the vertex): the vertex
 * moves half a pixel outwards along its normal, in view space, and is projected again. One pixel's
 * size at the vertex's depth is 2·w / (P[1][1] · height in pixels): w is the depth for a
 * perspective camera and 1 for an orthographic one. Lighting and fog keep the vertex's own place
 * (three.js computed them from `mvPosition` before this). An element not grown yet at the growth
 * time (./growth.ts) stays a point, not a pixel-wide speck.
 */
const HALF_A_PIXEL_OUT = `
  vec3 outwards = normalMatrix * normal;
  float outwardsLength = length(outwards);
  if (outwardsLength > 0.0 && meristemGrown > 0.0) {
    float pixel = 2.0 * gl_Position.w / (projectionMatrix[1][1] * meristemPixelsHigh);
    mvPosition.xyz += outwards * (0.5 * pixel / outwardsLength);
    gl_Position = projectionMatrix * mvPosition;
  }
}`;

/**
 * The fraction of its size a vertex has grown to (./growth.ts sets it; 1 without growth): a vertex
 * not grown yet is not moved out, so an element not there yet is not drawn as a speck.
 */
export const GROWN = 'float meristemGrown = 1.0;';

const viewport = new Vector4();

/**
 * Pixels of the target drawn into for each pixel of the picture: 2 while a picture is drawn at
 * twice its size to be scaled down ({@link drawnSupersampled}), else 1.
 */
let supersampling = 1;

/**
 * Runs `draw` (a render into a target `scale` times the picture's size, which is then scaled down)
 * with {@link atLeastAPixelWide}'s pixel the picture's: a pixel of the picture, not of the target.
 */
export function drawnSupersampled<T>(scale: number, draw: () => T): T {
  supersampling = scale;
  try {
    return draw();
  } finally {
    supersampling = 1;
  }
}

/**
 * Makes `material` draw every surface at least about a pixel across: each vertex is moved half a
 * pixel (of whatever is drawn into: the canvas, a thumbnail, a snapshot) outwards along its
 * normal (a picture's pixel while it is {@link drawnSupersampled}). A tube thinner than a pixel, as the twigs of a big tree seen whole are, is then drawn a
 * pixel wide and unbroken, as a line would be, instead of falling between the multisamples as
 * scattered specks; everything else grows by half a pixel a side, which cannot be seen. Only the
 * picture changes: picking reads the mesh as it is, and the files written keep their sizes. Takes
 * the material's `onBeforeCompile` and `onBeforeRender` (the height of the target drawn into is
 * read before each draw).
 */
export function atLeastAPixelWide<M extends Material>(material: M): M {
  const pixelsHigh = { value: 1 };
  material.onBeforeCompile = (shader) => {
    shader.uniforms.meristemPixelsHigh = pixelsHigh;
    shader.vertexShader = `uniform float meristemPixelsHigh;\n${GROWN}\n${shader.vertexShader.replace(/\}\s*$/, HALF_A_PIXEL_OUT)}`;
  };
  material.onBeforeRender = (renderer) => {
    pixelsHigh.value = Math.max(1, renderer.getCurrentViewport(viewport).w / supersampling);
  };
  return material;
}

/** A sky/ground light for the scene. */
export function addSkyLight(scene: Scene): void {
  scene.add(new HemisphereLight(0xffffff, 0x6b5a48, 1.4));
}

/**
 * A headlight fixed to `camera` (above and to the right of the eye), so the side of the plant
 * the user looks at is always lit. The camera must be in the scene for its light to count.
 */
export function addHeadlight(camera: Camera): void {
  const headlight = new DirectionalLight(0xffffff, 1.9);
  headlight.position.set(0.6, 0.9, 0.4);
  camera.add(headlight, headlight.target);
  headlight.target.position.set(0, 0, -1);
}
