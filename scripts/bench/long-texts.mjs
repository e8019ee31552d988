// `npm run bench`, issue 50 finding 7: long texts of many short lines through the first plant's
// core (crate/pkg-core, built for size), the core a share link or a pasted grammar meets first.
// Each row is one grammar of a few hundred KB, text to plant; target 500 ms. Before the resolver
// hashed what it looked up, 50,000 `#ignore` lines took 8.6 s here (0.06 s in crate/pkg: the
// speed build's optimiser took the search for an earlier directive of the same name out of the
// loop, the size build's did not), 50,000 `#random` variables 5.6 s, and one `#color` of 200,000
// values (finding 7's words(), which copied the directive once per word) 3.2 s natively.
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import { initSync, build } from '../../crate/pkg-core/meristem_core.js';

initSync({ module: readFileSync(new URL('../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)) });

const N = 50_000;
const lines = (f) => Array.from({ length: N }, (_, i) => f(i)).join('\n');
const params = Array.from({ length: 20_000 }, (_, i) => `p${i}`).join(',');

/** [what, grammar text]: each ends in an axiom, so every one builds a plant. */
const TEXTS = [
  ['50,000 lines `#ignore A`', `${lines(() => '#ignore A')}\naxiom: F`],
  ['50,000 lines `#color 1 0.5 0.5 0.5`', `${lines(() => '#color 1 0.5 0.5 0.5')}\naxiom: F`],
  ['50,000 lines `#angle 5` (each one a warning)', `${lines(() => '#angle 5')}\naxiom: F`],
  ['50,000 unknown directives `#xN 1` (each one an error)', `${lines((i) => `#x${i} 1`)}\naxiom: F`],
  ['50,000 `#define aN N`', `${lines((i) => `#define a${i} ${i}`)}\naxiom: F`],
  ['50,000 `#random rN uniform(0, 1)`', `${lines((i) => `#random r${i} uniform(0, 1)`)}\naxiom: F`],
  ['50,000 `#curve cN` (each one an error)', `${lines((i) => `#curve c${i} 0 0, 1 1`)}\naxiom: F`],
  ['one `#color` of 200,000 values', `#color 1 ${Array(200_000).fill('0.5').join(' ')}\naxiom: F`],
  ['a production of 20,000 parameters', `axiom: A(${params.replace(/p\d+/g, '1')})\nA(${params}) -> F A(${params})`],
];

/** The rows of the table: the median of 3 builds after one warm-up, each with its target. */
export function longTextRows() {
  return TEXTS.map(([what, text]) => {
    const times = [];
    let diagnostics = 0;
    for (let i = 0; i < 4; i++) {
      const t0 = performance.now();
      const plant = build(text, {});
      const ms = performance.now() - t0;
      diagnostics = JSON.parse(plant.diagnostics()).length;
      plant.free();
      if (i > 0) times.push(ms);
    }
    times.sort((a, b) => a - b);
    return { workload: `${what}: ${(text.length / 1e3).toFixed(0)} KB text → plant`, diagnostics, median_ms: +times[1].toFixed(1), runs: 3, target_ms: 500 };
  });
}
