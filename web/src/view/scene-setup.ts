// The parts of a plant scene shared by the studio's view and the gallery thumbnails, so both
// show a plant the same way: materials, and lights that follow the camera.
import {
  Camera,
  DirectionalLight,
  DoubleSide,
  HemisphereLight,
  MeshBasicMaterial,
  MeshStandardMaterial,
  Scene,
} from 'three';

/** The plant's lit material: vertex colours (the core's palette), both faces, matte. */
export function litPlantMaterial(): MeshStandardMaterial {
  return new MeshStandardMaterial({ vertexColors: true, side: DoubleSide, roughness: 0.85, metalness: 0 });
}

/** The unlit material (lighting off): the palette's colours as they are, no shading. */
export function unlitPlantMaterial(): MeshBasicMaterial {
  return new MeshBasicMaterial({ vertexColors: true, side: DoubleSide });
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
