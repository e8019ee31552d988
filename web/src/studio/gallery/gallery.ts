// The example gallery's files: the texts of public/examples and their manifest, fetched once per
// visit. The dialog that shows them is ./gallery-dialog.ts, loaded when it is first opened.
import { isGalleryManifest, type GalleryEntry } from './gallery-manifest';

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
