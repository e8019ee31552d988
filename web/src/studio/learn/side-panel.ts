// What the Learn panel and the assignment panel (its column's two occupants) do alike.
import type { GalleryThumbnails } from '../gallery/thumbnails';

/** Escape inside `panel` calls `close` (unless something in it took the key first). */
export function closeOnEscape(panel: HTMLElement, close: () => void): void {
  panel.addEventListener('keydown', (event) => {
    if (event.key !== 'Escape' || event.defaultPrevented) return;
    event.preventDefault();
    close();
  });
}

/** Puts each picture, as `thumbnails` draws it, into the image of its key in `images` (`data-state`: ready or failed). */
export function showPictures(thumbnails: GalleryThumbnails, images: ReadonlyMap<string, HTMLImageElement>): void {
  thumbnails.onPicture((key, url) => {
    const image = images.get(key);
    if (!image) return;
    if (url) image.src = url;
    image.dataset.state = url ? 'ready' : 'failed';
  });
}
