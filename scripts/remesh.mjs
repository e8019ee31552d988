// Remeshes ABOP 1.24d at n = 10 (116,050 segments, 1,087,919 vertices) N times in one process, for
// counting the mesh stage's instructions in WebAssembly where the machine is too loaded to time it:
//   valgrind --tool=cachegrind --cache-sim=no node --no-liftoff --single-threaded \
//     scripts/remesh.mjs [pkg/meristem | pkg-core/meristem_core] N
// run for N = 1 and N = 4; a third of the difference of the two "I refs" is one remesh (the
// x86 instructions V8's optimising compiler made of the wasm, the same on a busy machine).
// Not part of `npm test` or `npm run bench` (docs/notes/performance-history.md, "The studio: keystroke to frame").
import { readFileSync } from 'node:fs';

const [pkg = 'pkg/meristem', n = '1'] = process.argv.slice(2);
const root = new URL('../', import.meta.url);
const core = await import(new URL(`crate/${pkg}.js`, root).href);
core.initSync({ module: readFileSync(new URL(`crate/${pkg}_bg.wasm`, root)) });
const source = readFileSync(new URL('public/examples/abop-1.24d.lsys', root), 'utf8');
const build = core.build(source, { iterations: 10, sketch: true });
for (let i = 0; i < Number(n); i++) build.remesh({ tubes: true });
console.log(`${Number(n)} remeshes, ${JSON.parse(build.stats()).vertices} vertices`);
build.free();
