// Loaded by the service worker (vite.config.ts: workbox `importScripts`) before its own routes, so
// its fetch listener answers first: a damaged copy in the offline cache heals itself (issue 50,
// finding 10). The core's `.wasm` files (checked with WebAssembly.validate) and the gallery's
// manifest (examples/index.json, checked as JSON) are served from the precache only when intact;
// a damaged copy is dropped and fetched again from the network, and put back when the network's
// is intact. Offline, a damaged core is answered with HTTP 503 and a reason the page shows
// ("Could not start: … HTTP 503 …"); a damaged manifest is served as it is and the Gallery says
// it could not read it. Everything else goes on to workbox's routes. Plain JavaScript: public/ is
// copied as it is.
/* eslint-disable */
(() => {
  /** The intact-checks of the files this guards, by how their URL ends. */
  const CHECKS = [
    // The cores only (assets/meristem_core_bg-HASH.wasm, assets/meristem_bg-HASH.wasm): Pyodide's
    // wasm is workbox's runtime cache's, not the precache's, and must reach that route.
    [/\/assets\/meristem[\w-]*\.wasm$/, async (response) => WebAssembly.validate(await response.arrayBuffer())],
    [
      /\/examples\/index\.json$/,
      async (response) => {
        try {
          return Array.isArray(JSON.parse(await response.text()));
        } catch {
          return false;
        }
      },
    ],
  ];

  /** Said for a damaged core when the network is off (a reason phrase: visible ASCII only). */
  const DAMAGED_OFFLINE = '(the offline copy is damaged: connect to the network and reload)';

  /** Workbox's precache (its name starts so), or undefined before it exists. */
  async function precache() {
    const name = (await caches.keys()).find((key) => key.startsWith('workbox-precache'));
    return name === undefined ? undefined : caches.open(name);
  }

  /** The file from the precache when intact; else from the network (kept when intact); see above. */
  async function guarded(request, intact, isCore) {
    const cache = await precache();
    // By URL, as workbox matches its precache: its revision query and the response's Vary ignored.
    const keys = cache ? await cache.keys(request.url, { ignoreSearch: true, ignoreVary: true }) : [];
    const cached = keys.length > 0 ? await cache.match(keys[0], { ignoreVary: true }) : undefined;
    if (!cached) return fetch(request); // not precached (yet): as without this file
    if (await intact(cached.clone())) return cached;
    console.warn(`Meristem: the offline copy of ${request.url} is damaged; fetching it again`);
    let fresh;
    try {
      fresh = await fetch(request.url, { cache: 'reload' });
    } catch {
      return isCore ? new Response(null, { status: 503, statusText: DAMAGED_OFFLINE }) : cached;
    }
    if (fresh.ok && (await intact(fresh.clone()))) {
      for (const key of keys) await cache.put(key, fresh.clone());
    }
    return fresh;
  }

  self.addEventListener('fetch', (event) => {
    const { request } = event;
    if (request.method !== 'GET') return;
    const url = new URL(request.url);
    if (url.origin !== self.location.origin) return;
    const check = CHECKS.find(([pattern]) => pattern.test(url.pathname));
    if (!check) return;
    // (Should the cache itself fail, the network answers, as without this file.)
    event.respondWith(guarded(request, check[1], check[0].source.includes('wasm')).catch(() => fetch(request)));
  });
})();
