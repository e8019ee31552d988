// The gallery's manifest (examples/index.json), fetched and checked: loaded with the dialog that
// shows it (./gallery-dialog.ts) or the Variants bar, never with the first plant. A damaged copy
// (a corrupted offline cache: issue 50, finding 10) is an error that says so; the service worker
// fetches an unreadable one again when online (public/sw-heal.js).
import { isGalleryManifest, type GalleryEntry } from './gallery-manifest';

/** The manifest, relative to the page (built by scripts/gallery-plugin.ts). */
const MANIFEST_URL = 'examples/index.json';

/** The gallery's manifest. */
export async function fetchManifest(): Promise<GalleryEntry[]> {
  const response = await fetch(MANIFEST_URL);
  if (!response.ok) throw new Error(`${MANIFEST_URL}: HTTP ${response.status}`);
  let manifest: unknown;
  try {
    manifest = JSON.parse(await response.text());
  } catch {
    throw new Error(`${MANIFEST_URL} is damaged: it is not JSON`);
  }
  if (!isGalleryManifest(manifest)) throw new Error(`${MANIFEST_URL} is damaged: it is not a list of examples`);
  return manifest;
}
