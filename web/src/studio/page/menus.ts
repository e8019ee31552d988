// The toolbar's menus (File, Download) are `<details>` elements that behave like menus.

/** A `<details>` menu closes like a menu: on a click elsewhere and on Escape. */
export function closeLikeAMenu(menu: HTMLDetailsElement): void {
  document.addEventListener('pointerdown', (event) => {
    if (menu.open && !menu.contains(event.target as Node)) menu.open = false;
  });
  menu.addEventListener('keydown', (event) => {
    if (event.key !== 'Escape' || !menu.open) return;
    menu.open = false;
    menu.querySelector('summary')?.focus();
  });
}
