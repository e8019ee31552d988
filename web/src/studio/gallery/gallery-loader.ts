// The gallery loads when first opened (issue 22: the first plant does not need it).
import { lazyDialog, type LazyDialog, type StudioElements } from '../page';
import type { TextOpening } from '../files';
import { fetchExample } from './gallery';

/** The gallery dialog, loaded on first use; an example chosen there opens through `opening`. */
export function lazyGallery(els: Pick<StudioElements, 'gallery' | 'galleryList'>, opening: TextOpening): LazyDialog {
  return lazyDialog('the gallery', async () => {
    const [{ GalleryDialog }, { GalleryThumbnails }] = await Promise.all([import('./gallery-dialog'), import('./thumbnails')]);
    return new GalleryDialog(els.gallery, els.galleryList, new GalleryThumbnails(fetchExample), (entry) => opening.openExample(entry), () => opening.currentFile);
  });
}
