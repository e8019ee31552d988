// The surface editor's wiring (./wire-surface-editing.ts), loaded once the vocabulary has arrived:
// the first load carries only this (issue 22). Its menu then reads the text as it is.
import { onVocabulary } from '../../core';
import type { StudioParts } from '../parts';
import type { SurfaceEditing } from './wire-surface-editing';

/** The surface editor on the studio's parts, wired when the vocabulary has arrived. */
export function wireSurfaceEditingLater(parts: StudioParts): SurfaceEditing {
  let editing: SurfaceEditing | undefined;
  onVocabulary(() => {
    import('./wire-surface-editing').then(
      ({ wireSurfaceEditing }) => (editing = wireSurfaceEditing(parts)),
      (error: unknown) => parts.notice.show('error', `The surface editor could not load: ${String(error)}`),
    );
  });
  return { pointOnPage: (k) => editing?.pointOnPage(k) ?? null };
}
