// A vite plugin that serves Pyodide (Python 3.14 compiled to WebAssembly, npm package `pyodide`,
// MPL-2.0) from the site itself: the five files the runtime needs, from node_modules/pyodide, under
// `pyodide/` beside the page, in dev (`npm start`) and in the build (dist/pyodide/). Never a CDN:
// the studio runs L-Py and lpfg models offline once Pyodide has been loaded (the service worker
// keeps these files in a cache of their own on first use: vite.config.ts). Nothing of it is in the
// first load: web/src/python/python-worker.ts imports `pyodide/pyodide.mjs` when a model needs
// Python.
import { createReadStream, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import type { Plugin } from 'vite';

/** Where the files are, relative to the page. */
export const PYODIDE_DIR = 'pyodide';

/**
 * The runtime's files: the loader, the interpreter (its JavaScript and WebAssembly), the standard
 * library and the lock file it reads at start; 13.5 MB, 6.3 MB gzipped (314.0.7). Packages beyond the standard library are never
 * loaded (the L-system runtime is pure Python), so none is served.
 */
export const PYODIDE_FILES = ['pyodide.mjs', 'pyodide.asm.mjs', 'pyodide.asm.wasm', 'python_stdlib.zip', 'pyodide-lock.json'] as const;

const TYPES: Record<string, string> = {
  mjs: 'text/javascript',
  wasm: 'application/wasm',
  zip: 'application/zip',
  json: 'application/json',
};

/** The folder of the installed npm package `pyodide`. */
export function pyodidePackageDir(): string {
  return dirname(createRequire(import.meta.url).resolve('pyodide/package.json'));
}

/** The installed Pyodide's version (the service worker's cache is named after it). */
export function pyodideVersion(): string {
  return (JSON.parse(readFileSync(join(pyodidePackageDir(), 'package.json'), 'utf8')) as { version: string }).version;
}

/** The plugin: `pyodide/FILE` served in dev and emitted into the build. */
export function pyodideAssetsPlugin(): Plugin {
  const dir = pyodidePackageDir();
  const served = new Set<string>(PYODIDE_FILES);
  return {
    name: 'meristem-pyodide-assets',
    configureServer(server) {
      server.middlewares.use((request, response, next) => {
        const path = (request.url ?? '').split('?')[0];
        const match = /\/pyodide\/([^/]+)$/.exec(path);
        if (!match || !served.has(match[1])) return next();
        response.setHeader('Content-Type', TYPES[match[1].split('.').pop() ?? ''] ?? 'application/octet-stream');
        createReadStream(join(dir, match[1])).pipe(response);
      });
    },
    generateBundle() {
      for (const file of PYODIDE_FILES) {
        this.emitFile({ type: 'asset', fileName: `${PYODIDE_DIR}/${file}`, source: readFileSync(join(dir, file)) });
      }
    },
  };
}
