// Branch editing on demand (issue 22, the first load): the page's first branch edit loads
// ./branch-editor.ts and the core module that has branch editing (crate/pkg), once; the first
// plant downloads neither.
import type { editPlant } from './branch-editor';
import { onDemand } from './on-demand';

/** `editPlant` of ./branch-editor.ts: builds a plant and keeps it behind a `PlantEditor`. */
export type EditPlant = typeof editPlant;

/**
 * Loads branch editing once and resolves to its `editPlant`; later calls return the same promise.
 * A failed load (the network) is tried again by the next call.
 */
export const loadBranchEditing: () => Promise<EditPlant> = onDemand(async () => {
  const editor = await import('./branch-editor');
  await editor.initBranchEditing();
  return editor.editPlant;
});
