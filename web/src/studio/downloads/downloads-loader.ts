// Downloads: the plant on screen (the last good build's text and options, with the edits); the
// menu's code loads after the first plant (issue 22).
import type { BranchEdits } from '../branches';
import type { StudioParts } from '../parts';
import { figureName } from '../files/save-file';

/** Loads the Downloads menu and connects it to the plant on screen. */
export function loadDownloads({ els, view, preview, opening, timeline }: StudioParts, branchEdits: BranchEdits): Promise<void> {
  return import('./download-menu').then(({ installDownloads }) =>
    installDownloads(
      els.downloads,
      view,
      () => {
        const good = preview.lastGood;
        return good && { source: good.source, options: { ...good.options, edits: branchEdits.document() }, name: figureName(opening.namedFile, good.source) };
      },
      { timeline, preview },
    ),
  );
}
