// Every unit test file starts with the real WebAssembly core loaded (crate/pkg-core, and crate/pkg
// for the importers, the exporters, branch editing and the studio's inspector questions, built by
// `npm run build:wasm`), and the vocabulary, so modules that read it work as they do on the page,
// and `inspectPlant` explains as the build worker does once it has loaded the studio core.
import { readFileSync } from 'node:fs';
import { vocabulary } from '../crate/pkg/meristem.js';
import { initCore, initIo, useVocabulary } from '../web/src/core';
import { startStudioCore } from '../web/src/core/studio-core';

await initCore(readFileSync(new URL('../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));
await initIo(readFileSync(new URL('../crate/pkg/meristem_bg.wasm', import.meta.url)));
await startStudioCore();
// The vocabulary as the page fetches it (crate/pkg-core/vocabulary.json is written from the same call).
useVocabulary(JSON.parse(vocabulary()));
