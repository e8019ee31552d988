// The surface editor (issue 46), wired to the studio's parts: opened from the Surfaces menu of the
// view's tools or from the text (the gutter's marker, Alt+B on a surface's line), following every
// change of the text. Loaded once the vocabulary has arrived (./lazy-surface-editing.ts, the first
// load's part): the menu reads the directives' names from it (./surface-tools.ts), and the editor
// loads on its first opening. The curve editor (../curves) opens from the same gutter: it is wired here.
import { onVocabulary } from '../../core';
import { wireCurveEditing } from '../curves';
import type { StudioParts } from '../parts';
import type { SurfaceTools } from './surface-tools';

/** The surface editor as the test hook sees it. */
export interface SurfaceEditing {
  /** Net point `k` of the surface the editor shows, on the page; null when it is closed. */
  pointOnPage(k: number): { x: number; y: number } | null;
}

/** The surface editor on the grammar in `editor`; its menu goes after the branch tools. */
export function wireSurfaceEditing({ els, editor, notice }: StudioParts): SurfaceEditing {
  wireCurveEditing({ editor, notice });
  let tools: SurfaceTools | undefined;
  const loaded = new Promise<SurfaceTools>((resolve, reject) =>
    onVocabulary(() => {
      const after = els.branchEditing.toggle.parentElement ?? els.branchEditing.toggle;
      import('./surface-tools').then(({ installSurfaceTools }) => resolve((tools = installSurfaceTools(after, editor, notice))), reject);
    }),
  );
  loaded.catch((error: unknown) => notice.show('error', `The surface editor could not load: ${String(error)}`));
  editor.onChange((text) => tools?.changed(text));
  editor.onOpenEditor(({ what, name }) => {
    if (what === 'surface') void loaded.then((t) => t.open(name));
  });
  return { pointOnPage: (k) => tools?.pointOnPage(k) ?? null };
}
