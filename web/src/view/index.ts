// The 3D view (three.js): the plant mesh, lights, camera framing and orbit controls.
export { PlantView } from './plant-view';
export { plantGeometry } from './plant-geometry';
export { framePose, type CameraPose } from './framing';
export { scenePalette, type ScenePalette } from './palette';
