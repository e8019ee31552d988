// Every unit test file starts with the real WebAssembly core loaded (crate/pkg-core, and crate/pkg
// for the importers, the exporters, branch editing and the studio's inspector questions, built by
// `npm run build:wasm`), so modules that read the core's vocabulary work as they do on the page,
// and `inspectPlant` explains as the build worker does once it has loaded the studio core.
import { readFileSync } from 'node:fs';
import { initCore, initIo } from '../web/src/core';
import { startStudioCore } from '../web/src/core/studio-core';

await initCore(readFileSync(new URL('../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));
await initIo(readFileSync(new URL('../crate/pkg/meristem_bg.wasm', import.meta.url)));
await startStudioCore();
