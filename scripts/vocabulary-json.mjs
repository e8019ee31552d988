// Writes crate/pkg-core/vocabulary.json: the language's vocabulary (modules, directives, keywords,
// functions and values, with their docs) as `vocabulary()` of the whole core (crate/pkg) gives it.
// The first plant's core (crate/pkg-core) leaves the vocabulary and its texts out (issue 22, the
// first load); the studio fetches this file after the first plant (web/src/core/vocabulary.ts),
// vite emits it next to the core, and the service worker precaches it with the rest.
// Run by scripts/build-wasm.sh once both packages are built.
import { readFileSync, writeFileSync } from 'node:fs';

const pkg = new URL('../crate/pkg/', import.meta.url);
const core = await import(new URL('meristem.js', pkg).href);
core.initSync({ module: readFileSync(new URL('meristem_bg.wasm', pkg)) });
const json = core.vocabulary();
JSON.parse(json); // a failure here stops the build rather than the page
writeFileSync(new URL('../crate/pkg-core/vocabulary.json', import.meta.url), json);
