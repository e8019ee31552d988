// The surface editor (issue 46): a declared surface's control points moved in a 3D view, the
// grammar's patch lines following; loaded on first use (surface-editing-loader.ts).
export { wireSurfaceEditingLater } from './lazy-surface-editing';
export type { SurfaceEditing } from './wire-surface-editing';
