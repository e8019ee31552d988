// The surface editor (issue 46), wired to the studio's parts: opened from the Surfaces menu of the
// view's tools or from the text (the gutter's marker, Alt+B on a surface's line), following every
// change of the text.
import { onVocabulary } from '../../core';
import type { StudioParts } from '../parts';
import { LazySurfaceEditing } from './surface-editing-loader';
import { SurfacesMenu } from './surfaces-menu';

/** The surface editor on the grammar in `editor`; its menu goes after the branch tools. */
export function wireSurfaceEditing({ els, editor, notice }: StudioParts): LazySurfaceEditing {
  const editing = new LazySurfaceEditing({ editor }, notice);
  const after = els.branchEditing.toggle.parentElement ?? els.branchEditing.toggle;
  const menu = new SurfacesMenu(after, (letter) => editing.open(letter));
  editor.onChange((text) => {
    menu.update(text);
    editing.textChanged();
  });
  editor.onOpenSurface((letter) => editing.open(letter));
  onVocabulary(() => menu.update(editor.text())); // the menu reads the directives' names from it
  return editing;
}
