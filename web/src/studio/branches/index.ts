// Branch editing (issue 8): handles on the plant on screen; loaded on first use (branch-editing-loader.ts).
export type { BranchEdits } from './branch-editing-loader';
export { wireBranchEditing } from './wire-branch-editing';
