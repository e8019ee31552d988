// The gallery dialog: every example of public/examples with its title, description and a
// thumbnail, under headings by ABOP chapter and source; choosing one opens it (the caller asks
// first when the editor's text was changed). Keyboard: Tab or the arrow keys move between examples
// (← → in reading order, ↑ ↓ to the nearest card of the row above or below, across groups), Enter
// opens, Escape closes. Loaded when first opened (issue 22: the first plant needs none of it).
import { fetchManifest } from './manifest-fetch';
import type { GalleryEntry } from './gallery-manifest';
import type { GalleryThumbnails } from './thumbnails';
import './gallery-dialog.css';

/** The gallery dialog of index.html (`#gallery`). */
export class GalleryDialog {
  private entries: GalleryEntry[] | undefined;
  private readonly images = new Map<string, HTMLImageElement>();

  /**
   * @param choose called with the example the user picked, after the dialog closed
   * @param current the file of the example in the editor, focused when the dialog opens
   */
  constructor(
    private readonly dialog: HTMLDialogElement,
    private readonly list: HTMLElement,
    private readonly thumbnails: GalleryThumbnails,
    private readonly choose: (entry: GalleryEntry) => void,
    private readonly current: () => string | undefined,
  ) {
    thumbnails.onPicture((file, url) => this.showPicture(file, url));
    list.addEventListener('keydown', (event) => this.moveFocus(event));
  }

  /** The manifest, fetched on first use. */
  async manifest(): Promise<GalleryEntry[]> {
    this.entries ??= await fetchManifest();
    return this.entries;
  }

  /**
   * Opens the dialog (and starts drawing the thumbnails not drawn yet). A manifest that could not
   * be fetched or read (the network off, a damaged offline copy: issue 50, finding 10) is said in
   * the dialog, and fetched again at the next opening.
   */
  async open(): Promise<void> {
    let entries: GalleryEntry[];
    try {
      entries = await this.manifest();
    } catch (error) {
      this.unreadable(error);
      return;
    }
    if (this.list.querySelector('.gallery-unreadable')) this.list.replaceChildren();
    if (this.list.childElementCount === 0) this.render(entries);
    if (!this.dialog.open) this.dialog.showModal();
    const current = this.current();
    const card = this.cards().find((c) => c.dataset.file === current) ?? this.cards()[0];
    card?.focus();
    card?.scrollIntoView({ block: 'nearest' });
    this.thumbnails.request(entries.map((e) => e.file));
  }

  /** Says in the open dialog that the list of examples could not be read, and why. */
  private unreadable(error: unknown): void {
    const item = document.createElement('li');
    item.className = 'gallery-unreadable';
    item.setAttribute('role', 'alert');
    item.textContent =
      `The list of examples could not be read (${error instanceof Error ? error.message : String(error)}). ` +
      (navigator.onLine ? 'Close the gallery and open it again to try once more.' : 'Connect to the network, then open the gallery again.');
    this.list.replaceChildren(item);
    if (!this.dialog.open) this.dialog.showModal();
  }

  private cards(): HTMLButtonElement[] {
    return [...this.list.querySelectorAll<HTMLButtonElement>('button.example-card')];
  }

  /** One list item per group: its heading and its cards. */
  private render(entries: GalleryEntry[]): void {
    const groups = new Map<string, GalleryEntry[]>();
    for (const entry of entries) groups.set(entry.group, [...(groups.get(entry.group) ?? []), entry]);
    this.list.replaceChildren(
      ...[...groups].map(([group, members], n) => {
        const item = document.createElement('li');
        item.className = 'gallery-group';
        const heading = document.createElement('h3');
        heading.id = `gallery-group-${n}`;
        heading.textContent = group;
        const cards = document.createElement('ul');
        cards.className = 'gallery-cards';
        cards.setAttribute('aria-labelledby', heading.id);
        cards.append(...members.map((entry) => this.card(entry)));
        item.append(heading, cards);
        return item;
      }),
    );
  }

  /** One example's card. */
  private card(entry: GalleryEntry): HTMLLIElement {
    const item = document.createElement('li');
    const card = document.createElement('button');
    card.type = 'button';
    card.className = 'example-card';
    card.dataset.file = entry.file;
    card.title = [entry.title, entry.description, entry.source && `Source: ${entry.source}`].filter(Boolean).join('\n\n');
    const image = document.createElement('img');
    image.alt = '';
    image.width = 160;
    image.height = 120;
    image.className = 'thumbnail';
    image.dataset.state = 'pending';
    this.images.set(entry.file, image);
    const picture = this.thumbnails.picture(entry.file);
    if (picture !== undefined) this.showPicture(entry.file, picture);
    const title = document.createElement('span');
    title.className = 'example-title';
    title.textContent = entry.title;
    const description = document.createElement('span');
    description.className = 'example-description';
    description.textContent = entry.description;
    card.append(image, title, description);
    card.addEventListener('click', () => {
      this.dialog.close();
      this.choose(entry);
    });
    item.append(card);
    return item;
  }

  private showPicture(file: string, url: string | null): void {
    const image = this.images.get(file);
    if (!image) return;
    if (url) image.src = url;
    image.dataset.state = url ? 'ready' : 'failed';
  }

  /** Arrow keys, Home and End move between the cards (grids under headings, read in order). */
  private moveFocus(event: KeyboardEvent): void {
    const cards = this.cards();
    const index = cards.indexOf(document.activeElement as HTMLButtonElement);
    if (index < 0) return;
    let next: number | undefined;
    if (event.key === 'ArrowRight' || event.key === 'ArrowLeft') next = Math.min(cards.length - 1, Math.max(0, index + (event.key === 'ArrowRight' ? 1 : -1)));
    else if (event.key === 'ArrowDown' || event.key === 'ArrowUp') next = verticalNeighbour(cards, index, event.key === 'ArrowDown') ?? index;
    else if (event.key === 'Home') next = 0;
    else if (event.key === 'End') next = cards.length - 1;
    if (next === undefined) return;
    event.preventDefault();
    cards[next].focus();
  }
}

/**
 * The card of the nearest row below (or above) card `index`, as laid out, whichever group it is
 * in; within that row, the one nearest in x. Undefined at the last (first) row.
 */
function verticalNeighbour(cards: HTMLElement[], index: number, down: boolean): number | undefined {
  const from = cards[index].getBoundingClientRect();
  const centre = (r: DOMRect) => r.left + r.width / 2;
  const boxes = cards.map((card) => card.getBoundingClientRect());
  const beyond = boxes.map((r, i) => [r, i] as const).filter(([r]) => (down ? r.top >= from.bottom - 1 : r.bottom <= from.top + 1));
  if (beyond.length === 0) return undefined;
  const rowTop = down ? Math.min(...beyond.map(([r]) => r.top)) : Math.max(...beyond.map(([r]) => r.top));
  const row = beyond.filter(([r]) => Math.abs(r.top - rowTop) <= 1);
  row.sort(([a], [b]) => Math.abs(centre(a) - centre(from)) - Math.abs(centre(b) - centre(from)));
  return row[0][1];
}
