// The studio page's own logic: building on edit, the status line.
export { PlantBuilder, type TimedBuild } from './plant-builder';
export { reportPlant, reportErrors, plural, type StatusReport } from './status';
export { debounce } from './debounce';
export { ContextView } from './context-view';
