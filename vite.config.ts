// Build and unit-test configuration of the studio.
// - vite: the page lives in web/ (with embed.html and the <meristem-plant> element, web/src/embed/), the
//   example gallery in public/ (served as-is), the site is built to dist/ with relative URLs (`base: './'`)
//   so it works from any sub-path. The build worker (web/src/build/
//   worker.ts) is bundled as an ES module worker. The gallery manifest (examples/index.json) comes
//   from a plugin (scripts/gallery-plugin.ts), served in dev and emitted in the build; so does the
//   course (lessons/index.json and lessons/SLUG.json, from public/lessons/*.md: scripts/lessons-plugin.ts),
//   and the language reference, docs/LANGUAGE.md rendered to HTML (scripts/reference-plugin.ts).
// - vitest (`npx vitest run`): unit tests next to the code in web/src and the cross-boundary tests in
//   tests/core (and the plugins' in scripts), all in node against the real WebAssembly core. The browser suite has its own config
//   (tests/browser/vitest.config.ts).
import { fileURLToPath } from 'node:url';
import { VitePWA } from 'vite-plugin-pwa';
import type { HtmlTagDescriptor, Plugin } from 'vite';
import { defineConfig } from 'vitest/config';
import { galleryManifestPlugin } from './scripts/gallery-plugin.ts';
import { lessonsPlugin } from './scripts/lessons-plugin.ts';
import { PYODIDE_DIR, pyodideAssetsPlugin, pyodideVersion } from './scripts/pyodide-plugin.ts';
import { referencePlugin } from './scripts/reference-plugin.ts';
import { INITIAL_EXAMPLE } from './web/src/studio/files/initial-example.ts';

const repoRoot = fileURLToPath(new URL('.', import.meta.url));

/**
 * Offline and installable (issue 22): a service worker (workbox, generated at build time) precaches
 * everything the built site holds — the page, the workers, the core's wasm, the gallery, the
 * lessons, the reference, the textures — and a web app manifest with the icons of public/icons
 * (scripts/make-icons.mjs). `prompt`: a new version waits until the user reloads from the studio's
 * "A new version is ready" bar (web/src/studio/page/app-update.ts registers it). Every URL is relative,
 * so it works from any sub-path; query strings (embed.html?controls=…) are ignored when matching.
 * Pyodide (dist/pyodide/, about 13 MB: scripts/pyodide-plugin.ts) is not precached: a visitor who
 * never opens an L-Py or lpfg model never downloads it. The first model that needs Python fetches
 * it, and the service worker keeps it then (cache first, in a cache named after Pyodide's version,
 * so an upgrade fetches the new files), so Python models open offline after that. A damaged copy
 * of the core's wasm or of the gallery's manifest in the cache is checked for and fetched again
 * (public/sw-heal.js, issue 50, finding 10).
 */
function offlineApp() {
  return VitePWA({
    registerType: 'prompt',
    injectRegister: false,
    includeAssets: [],
    manifest: {
      name: 'Meristem — L-system studio',
      short_name: 'Meristem',
      description: 'Write an L-system grammar, see the plant grow in 3D.',
      start_url: './',
      scope: './',
      display: 'standalone',
      background_color: '#f6f7f9',
      theme_color: '#2e7d32',
      icons: [
        { src: 'icons/icon-192.png', sizes: '192x192', type: 'image/png' },
        { src: 'icons/icon-512.png', sizes: '512x512', type: 'image/png' },
        { src: 'icons/maskable-512.png', sizes: '512x512', type: 'image/png', purpose: 'maskable' },
        { src: 'icons/icon.svg', sizes: 'any', type: 'image/svg+xml' },
      ],
    },
    workbox: {
      globPatterns: ['**/*.{html,js,css,wasm,json,lsys,png,svg,webmanifest}'],
      globIgnores: [`${PYODIDE_DIR}/**`, 'sw-heal.js'],
      // Before workbox's routes: a damaged copy of the core or of the gallery's manifest heals (public/sw-heal.js).
      importScripts: ['sw-heal.js'],
      maximumFileSizeToCacheInBytes: 8 * 1024 * 1024,
      ignoreURLParametersMatching: [/.*/],
      navigateFallback: null,
      runtimeCaching: [
        {
          urlPattern: new RegExp(`/${PYODIDE_DIR}/[^/?]+$`),
          handler: 'CacheFirst',
          options: { cacheName: `meristem-pyodide-${pyodideVersion()}`, cacheableResponse: { statuses: [200] } },
        },
      ],
    },
  });
}

/**
 * The first load (issue 22): index.html and embed.html ask for the core's wasm at once (a preload,
 * fetched with the page's script rather than after it has run), the fetch `coreModule()` makes;
 * index.html also runs the boot script (web/src/boot.ts: the core compiles and the build worker
 * starts while the studio's script still downloads) and preloads the example the studio opens
 * with (`INITIAL_EXAMPLE` of web/src/main.ts), which it fetches when there is no text to restore.
 */
function preloadCore(): Plugin {
  return {
    name: 'meristem-preload-core',
    apply: 'build',
    transformIndexHtml: {
      order: 'post',
      handler(_html, context) {
        const files = Object.keys(context.bundle ?? {});
        const wasm = files.find((file) => /meristem_core_bg-[^/]*\.wasm$/.test(file));
        if (!wasm) return [];
        const tags: HtmlTagDescriptor[] = [{ tag: 'link', attrs: { rel: 'preload', href: `./${wasm}`, as: 'fetch', type: 'application/wasm', crossorigin: '' }, injectTo: 'head' }];
        const boot = files.find((file) => /^assets\/boot-[^/]*\.js$/.test(file));
        if (context.filename.endsWith('index.html') && boot) {
          // async: it runs once it has arrived, not after the studio's script (module scripts run in order).
          tags.push({ tag: 'script', attrs: { type: 'module', async: true, src: `./${boot}` }, injectTo: 'head' });
          tags.push({ tag: 'link', attrs: { rel: 'preload', href: `examples/${INITIAL_EXAMPLE}`, as: 'fetch', crossorigin: '' }, injectTo: 'head' });
        }
        return tags;
      },
    },
  };
}

export default defineConfig({
  root: 'web',
  base: './',
  publicDir: '../public',
  plugins: [
    galleryManifestPlugin(`${repoRoot}public/examples`),
    lessonsPlugin(`${repoRoot}public/lessons`),
    referencePlugin(`${repoRoot}docs/LANGUAGE.md`),
    preloadCore(),
    pyodideAssetsPlugin(),
    offlineApp(),
  ],
  worker: { format: 'es' },
  build: {
    outDir: '../dist',
    emptyOutDir: true,
    // Three ways in: the studio, the view-only page for iframes (embed.html#s=…), and the
    // <meristem-plant> element for course pages, at a stable address (meristem-plant.js).
    rollupOptions: {
      input: {
        index: `${repoRoot}web/index.html`,
        embed: `${repoRoot}web/embed.html`,
        'meristem-plant': `${repoRoot}web/src/embed/element.ts`,
        // The studio page's boot script (issue 22): preloadCore puts it in index.html.
        boot: `${repoRoot}web/src/boot.ts`,
      },
      output: {
        entryFileNames: (chunk) => (chunk.name === 'meristem-plant' ? 'meristem-plant.js' : 'assets/[name]-[hash].js'),
      },
    },
    // three.js + CodeMirror are one ~1 MB chunk by nature; there is nothing to split off yet.
    chunkSizeWarningLimit: 1500,
    // Every browser the studio runs in (WebAssembly, module workers) knows modulepreload: no
    // polyfill, one request fewer before the first plant (issue 22).
    modulePreload: { polyfill: false },
  },
  test: {
    root: repoRoot,
    environment: 'node',
    include: ['web/src/**/*.test.ts', 'tests/core/**/*.test.ts', 'scripts/**/*.test.ts'],
    setupFiles: ['tests/unit-setup.ts'],
  },
});
