// The studio page's own logic: building on edit, the status line, downloads.
export { PlantBuilder, type TimedBuild } from './plant-builder';
export { reportPlant, reportErrors, plural, type StatusReport } from './status';
export { debounce } from './debounce';
export { ContextView } from './context-view';
export { afterPaint, fileSize, pictureSize, saveFile, PICTURE_MAX, PICTURE_MIN, type PictureSize } from './downloads';
