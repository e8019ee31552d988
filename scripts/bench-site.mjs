// What the studio's benchmarks (bench-studio.mjs, bench-studio-movie.mjs) share: the two Chromium
// setups they run in, and the built site (dist/) served by vite's preview server.
import { mkdirSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import { preview } from 'vite';

/** Chromium's arguments for each setup. */
export const SETUPS = {
  'GPU compositing (SwiftShader)': ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  'software compositing (Chromium default without a GPU)': [],
};

/** Serves dist/ on a free port: the server (to close) and its address. */
export async function servedSite() {
  const server = await preview({ configFile: new URL('../vite.config.ts', import.meta.url).pathname, logLevel: 'warn', preview: { host: '127.0.0.1', port: 0 } });
  return { server, url: `http://127.0.0.1:${server.httpServer.address().port}/` };
}

/** Writes `test-results/NAME` with the date, the machine and `fields` (the results). */
export function writeResults(name, fields) {
  const dir = new URL('../test-results/', import.meta.url);
  mkdirSync(dir, { recursive: true });
  const machine = { date: new Date().toISOString(), cpu: os.cpus()[0]?.model, cores: os.cpus().length };
  writeFileSync(new URL(name, dir), `${JSON.stringify({ ...machine, ...fields }, null, 1)}\n`);
}
