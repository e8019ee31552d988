// The export suite (`npm run test:export`): every gallery example and golden grammar exported by
// the command-line tool and read back by the real consumers (the Khronos glTF validator, POV-Ray,
// tovrmlx3d, three.js's loaders, ivcat, an XML parser), and the wasm facade's bytes compared with
// the tool's. Slow by nature (a million-vertex model in six formats), so it has its own run.
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    root: fileURLToPath(new URL('../..', import.meta.url)),
    include: ['tests/export/**/*.test.ts'],
    environment: 'node',
    testTimeout: 300_000,
    hookTimeout: 300_000,
    // three.js's VRMLLoader holds a 90 MB VRML file as a syntax tree: about 3 GB.
    execArgv: ['--max-old-space-size=8192'],
  },
});
