// The 3D view (three.js): the plant mesh, lights, camera framing and orbit controls, and the
// gallery's thumbnails drawn the same way.
export { PlantView, type GrowthCamera, type ProjectionMode, type RenderMode } from './plant-view';
export type { RenderTarget } from './render-target';
export { sharedTarget } from './shared-renderer';
export type { Projection, ViewPose } from './camera-rig';
export type { FilmFrames, PictureLook } from './snapshot';
export { DEFAULT_LINE_WIDTH, LINE_WIDTH_MAX, LINE_WIDTH_MIN, lineWidthOf } from './segment-lines';
export { ThumbnailRenderer } from './thumbnail';
export { plantGeometry, lineGeometry, pointsBox } from './plant-geometry';
export { framePose, flatPose, type CameraPose, type FlatPose } from './framing';
export { scenePalette, type ScenePalette } from './palette';
