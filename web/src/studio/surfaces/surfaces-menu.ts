// The Surfaces menu of the view's tools: one entry per surface the grammar declares (`#surface X`,
// `#patch X`), each opening the surface editor on it; hidden while the grammar declares none.
// Light (the first plant's page carries it): the editor itself loads on the first opening.
import { declaredSurfaces } from '../../editor/surface-lines';
import { closeLikeAMenu } from '../page';

/** The menu, made in the view's tools after `after`. */
export class SurfacesMenu {
  private readonly menu = document.createElement('details');
  private readonly items = document.createElement('div');
  private letters = '';

  constructor(
    after: Element,
    private readonly open: (letter: string) => void,
  ) {
    const menu = this.menu;
    menu.className = 'downloads tool-menu surfaces-menu';
    menu.dataset.testid = 'surfaces-menu';
    menu.hidden = true;
    const summary = document.createElement('summary');
    summary.textContent = 'Surfaces ▾';
    summary.title = "Edit a surface's control points in a 3D view: the grammar's patch lines follow";
    this.items.className = 'download-menu';
    menu.append(summary, this.items);
    after.after(menu);
    closeLikeAMenu(menu);
  }

  /** Lists the surfaces `text` declares. */
  update(text: string): void {
    const surfaces = declaredSurfaces(text);
    const letters = surfaces.map((s) => s.letter).join('');
    if (letters === this.letters) return;
    this.letters = letters;
    this.menu.hidden = surfaces.length === 0;
    if (surfaces.length === 0) this.menu.open = false;
    this.items.replaceChildren(
      ...surfaces.map(({ letter }) => {
        const button = document.createElement('button');
        button.type = 'button';
        button.className = 'menu-item';
        button.dataset.testid = `edit-surface-${letter}`;
        button.setAttribute('aria-haspopup', 'dialog');
        button.textContent = `Edit ~${letter}…`;
        button.addEventListener('click', () => {
          this.menu.open = false;
          this.open(letter);
        });
        return button;
      }),
    );
  }
}
