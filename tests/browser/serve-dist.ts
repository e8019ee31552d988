// Global setup of the browser suite: serves the built site (dist/) with vite's preview server on
// a free loopback port, under a sub-path (the site must work from any sub-path: every URL in it,
// the workers' and the wasm's included, is relative), and hands its URL to the tests as
// `inject('studioUrl')`.
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { preview } from 'vite';
import type { TestProject } from 'vitest/node';

declare module 'vitest' {
  export interface ProvidedContext {
    /** URL of the studio page served from dist/. */
    studioUrl: string;
  }
}

const repoRoot = fileURLToPath(new URL('../..', import.meta.url));
/** Where the site is served: not the server's root. */
const SUB_PATH = '/some/sub/path/';

/** Starts the preview server on dist/ and returns the teardown that stops it. */
export default async function serveDist(project: TestProject): Promise<() => Promise<void>> {
  if (!existsSync(`${repoRoot}/dist/index.html`)) {
    throw new Error('dist/index.html is missing: run `npx vite build` before the browser tests');
  }
  const server = await preview({
    configFile: `${repoRoot}/vite.config.ts`,
    logLevel: 'warn',
    base: SUB_PATH,
    preview: { host: '127.0.0.1', port: 0, strictPort: true, open: false },
  });
  const address = server.httpServer.address();
  if (address === null || typeof address === 'string') throw new Error('preview server has no TCP address');
  project.provide('studioUrl', `http://127.0.0.1:${address.port}${SUB_PATH}`);
  return async () => {
    await server.close();
  };
}
