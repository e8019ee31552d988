// Branch editing (issue 8), wired to the studio's parts: the plant on screen with its edits,
// handles in Edit mode (loaded on first use).
import type { ViewControls } from '../controls';
import type { StudioParts } from '../parts';
import { LazyBranchEditing } from './branch-editing-loader';

/** Branch editing on the plant on screen; Edit mode stops the view following and the picking of modules. */
export function wireBranchEditing({ els, view, preview, notice, contexts }: StudioParts, { following, viewTools }: ViewControls): LazyBranchEditing {
  const branchEdits = new LazyBranchEditing(els.branchEditing, view, {
    shown: () => {
      const good = preview.lastGood;
      return good && { source: good.source, options: good.options, segments: good.build.stats.segments, flat: good.build.flat };
    },
    tell: (kind, message, items) => (message === null ? notice.hide() : notice.show(kind, message, items)),
    modeChanged: (on) => {
      following.editing(on);
      viewTools.showProjection();
      contexts.picking = !on;
      if (on) contexts.pickModule(null);
    },
  });
  preview.onDelivered((result) => {
    if (result.build.ok) branchEdits.plantShown();
  });
  return branchEdits;
}
