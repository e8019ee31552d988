// The surface editor's tools on the page, loaded once the vocabulary has arrived (after the first
// plant): the Surfaces menu in the view's tools and the editor that loads on its first opening.
import type { GrammarEditor } from '../../editor/grammar-text';
import type { Notice } from '../page';
import { LazySurfaceEditing } from './surface-editing-loader';
import { SurfacesMenu } from './surfaces-menu';

/** The menu and the editor, as the studio's wiring drives them. */
export interface SurfaceTools {
  /** The grammar text changed. */
  changed(text: string): void;
  /** Opens the editor on surface `letter`. */
  open(letter: string): void;
  /** Net point `k` of the surface the editor shows, on the page (tests); null when it is closed. */
  pointOnPage(k: number): { x: number; y: number } | null;
}

/** Puts the Surfaces menu after `after` and lists the surfaces of `editor`'s text. */
export function installSurfaceTools(after: Element, editor: GrammarEditor, notice: Notice): SurfaceTools {
  const editing = new LazySurfaceEditing({ editor }, notice);
  const menu = new SurfacesMenu(after, (letter) => editing.open(letter));
  menu.update(editor.text());
  return {
    changed: (text) => {
      menu.update(text);
      editing.textChanged();
    },
    open: (letter) => editing.open(letter),
    pointOnPage: (k) => editing.pointOnPage(k),
  };
}
