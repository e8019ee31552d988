// A vite plugin that serves the gallery manifest (`examples/index.json`: title, source and
// description of every public/examples/*.lsys, read from their header comments) in dev and emits
// it as an asset of the build, from the same function, so `npm start` and `npm run build` agree.
// Nothing is written into public/.
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Plugin } from 'vite';
import { galleryManifest } from '../web/src/studio/gallery/gallery-manifest.ts';

/** Where the manifest is, relative to the page. */
export const MANIFEST_PATH = 'examples/index.json';

/** The manifest of the examples in `dir`, as JSON text. */
export function manifestJson(dir: string): string {
  const files = readdirSync(dir).filter((file) => file.endsWith('.lsys'));
  return `${JSON.stringify(galleryManifest(files.map((file) => [file, readFileSync(join(dir, file), 'utf8')] as const)), null, 1)}\n`;
}

/** The plugin; `examplesDir` is the folder of the `.lsys` files (public/examples). */
export function galleryManifestPlugin(examplesDir: string): Plugin {
  return {
    name: 'meristem-gallery-manifest',
    configureServer(server) {
      // Read on every request, so an example edited while `npm start` runs shows at once.
      server.middlewares.use((request, response, next) => {
        const path = (request.url ?? '').split('?')[0];
        if (!path.endsWith(`/${MANIFEST_PATH}`)) return next();
        response.setHeader('Content-Type', 'application/json');
        response.end(manifestJson(examplesDir));
      });
    },
    generateBundle() {
      this.emitFile({ type: 'asset', fileName: MANIFEST_PATH, source: manifestJson(examplesDir) });
    },
  };
}
