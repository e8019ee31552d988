// A static file server that knows nothing of the app, as any static host: the files of dist/ under
// a sub-path, 404 for everything else. `replace` swaps a file's contents (a new deployment of it).
import { createReadStream, existsSync, statSync } from 'node:fs';
import { createServer, type Server } from 'node:http';
import { extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { createGzip } from 'node:zlib';

const DIST = fileURLToPath(new URL('../../dist/', import.meta.url));
const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.mjs': 'text/javascript',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.wasm': 'application/wasm',
  '.lsys': 'text/plain; charset=utf-8',
  '.md': 'text/markdown; charset=utf-8',
  '.json': 'application/json',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.webmanifest': 'application/manifest+json',
};

export interface StaticSite {
  /** The site's address, ending in the sub-path. */
  base: string;
  /** Files (by path under the sub-path) served with other contents than dist/'s. */
  replaced: Map<string, string>;
  /** How many requests reached the server. */
  readonly requests: number;
  close(): Promise<void>;
}

/** What a host compresses when the browser accepts gzip (`gzip: true`). */
const COMPRESSED = new Set(['.html', '.js', '.css', '.wasm', '.json', '.lsys', '.svg', '.webmanifest']);

/**
 * Serves dist/ under `subPath` (`/a/b/`) on a free loopback port; with `gzip`, compressed as hosts
 * do; `headers` go with every file (a lecturer's site that allows other origins: CORS).
 */
export async function serveStatic(subPath: string, { gzip = false, headers = {} as Record<string, string> } = {}): Promise<StaticSite> {
  const replaced = new Map<string, string>();
  let requests = 0;
  const server: Server = createServer((request, response) => {
    requests += 1;
    const path = decodeURIComponent(new URL(request.url ?? '/', 'http://x').pathname);
    if (!path.startsWith(subPath)) return void response.writeHead(404).end('not found');
    const relative = path.slice(subPath.length);
    let file = normalize(join(DIST, relative));
    if (!file.startsWith(DIST)) return void response.writeHead(403).end();
    if (existsSync(file) && statSync(file).isDirectory()) file = join(file, 'index.html');
    if (!existsSync(file)) return void response.writeHead(404).end('not found');
    const compress = gzip && COMPRESSED.has(extname(file)) && /\bgzip\b/.test(String(request.headers['accept-encoding']));
    response.writeHead(200, { ...headers, 'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream', ...(compress ? { 'Content-Encoding': 'gzip' } : {}) });
    const replacement = replaced.get(relative);
    if (replacement !== undefined) return void response.end(replacement);
    if (compress) createReadStream(file).pipe(createGzip({ level: 9 })).pipe(response);
    else createReadStream(file).pipe(response);
  });
  await new Promise<void>((done) => server.listen(0, '127.0.0.1', done));
  const address = server.address();
  if (!address || typeof address === 'string') throw new Error('no address');
  return {
    base: `http://127.0.0.1:${address.port}${subPath}`,
    replaced,
    get requests() {
      return requests;
    },
    close: () => new Promise((done) => server.close(() => done())),
  };
}
