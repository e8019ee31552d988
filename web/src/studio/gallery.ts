// The gallery dialog: every example of public/examples with its title, description and a
// thumbnail; choosing one opens it (the caller asks first when the editor's text was changed).
// Keyboard: Tab or the arrow keys move between examples, Enter opens, Escape closes.
import { isGalleryManifest, type GalleryEntry } from './gallery-manifest';
import type { GalleryThumbnails } from './thumbnails';

/** The manifest, relative to the page (built by scripts/gallery-plugin.ts). */
const MANIFEST_URL = 'examples/index.json';

const texts = new Map<string, Promise<string>>();

/** The text of an example (fetched once per visit). */
export function fetchExample(file: string): Promise<string> {
  let text = texts.get(file);
  if (!text) {
    text = fetch(`examples/${encodeURIComponent(file)}`).then((response) => {
      if (!response.ok) throw new Error(`examples/${file}: HTTP ${response.status}`);
      return response.text();
    });
    text.catch(() => texts.delete(file));
    texts.set(file, text);
  }
  return text;
}

/** The gallery's manifest. */
export async function fetchManifest(): Promise<GalleryEntry[]> {
  const response = await fetch(MANIFEST_URL);
  if (!response.ok) throw new Error(`${MANIFEST_URL}: HTTP ${response.status}`);
  const manifest: unknown = await response.json();
  if (!isGalleryManifest(manifest)) throw new Error(`${MANIFEST_URL} is not a gallery manifest`);
  return manifest;
}

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

  /** Opens the dialog (and starts drawing the thumbnails not drawn yet). */
  async open(): Promise<void> {
    const entries = await this.manifest();
    if (this.list.childElementCount === 0) this.render(entries);
    if (!this.dialog.open) this.dialog.showModal();
    const current = this.current();
    const card = this.cards().find((c) => c.dataset.file === current) ?? this.cards()[0];
    card?.focus();
    card?.scrollIntoView({ block: 'nearest' });
    this.thumbnails.request(entries.map((e) => e.file));
  }

  private cards(): HTMLButtonElement[] {
    return [...this.list.querySelectorAll<HTMLButtonElement>('button.example-card')];
  }

  private render(entries: GalleryEntry[]): void {
    this.list.replaceChildren(
      ...entries.map((entry) => {
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
      }),
    );
  }

  private showPicture(file: string, url: string | null): void {
    const image = this.images.get(file);
    if (!image) return;
    if (url) image.src = url;
    image.dataset.state = url ? 'ready' : 'failed';
  }

  /** Arrow keys, Home and End move between the cards (a grid read in order). */
  private moveFocus(event: KeyboardEvent): void {
    const cards = this.cards();
    const index = cards.indexOf(document.activeElement as HTMLButtonElement);
    if (index < 0) return;
    const columns = Math.max(1, Math.round(this.list.clientWidth / (cards[0].parentElement?.clientWidth || 1)));
    const moves: Record<string, number> = { ArrowRight: 1, ArrowLeft: -1, ArrowDown: columns, ArrowUp: -columns };
    let next: number | undefined;
    if (event.key in moves) next = Math.min(cards.length - 1, Math.max(0, index + moves[event.key]));
    else if (event.key === 'Home') next = 0;
    else if (event.key === 'End') next = cards.length - 1;
    if (next === undefined) return;
    event.preventDefault();
    cards[next].focus();
  }
}
