// The gallery: its manifest (built from the examples' headers), the examples fetched, the dialog
// with thumbnails (loaded when first opened: gallery-loader.ts).
export { lazyGallery } from './gallery-loader';
export { fetchExample } from './gallery';
export type { GalleryEntry } from './gallery-manifest';
