// `npm run bench`: derivation speed of the WebAssembly core in Node, on the workloads of issue 3.
// Prints a table and writes test-results/bench.json (medians). The same grammars are benchmarked
// natively by criterion (crate/benches/derive.rs); both read them from the gallery.
import { readFileSync, mkdirSync, writeFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import os from 'node:os';
import { initSync, Grammar } from '../crate/pkg/meristem.js';

initSync({ module: readFileSync(new URL('../crate/pkg/meristem_bg.wasm', import.meta.url)) });

/** [gallery file, iterations] — keep in step with crate/benches/derive.rs. */
const WORKLOADS = [
  ['abop-1.24d.lsys', 10],
  ['abop-1.31a-hogeweg.lsys', 30],
  ['abop-1.31a-hogeweg.lsys', 50],
  ['abop-2.08a-ternary-tree.lsys', 8],
  ['abop-1.27-stochastic.lsys', 8],
  ['abop-eq-1.9-proportions.lsys', 16],
];

function median(values) {
  const s = [...values].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
}

const rows = [];
for (const [file, n] of WORKLOADS) {
  const source = readFileSync(new URL(`../public/examples/${file}`, import.meta.url), 'utf8');
  const grammar = Grammar.compile(source);
  if (!grammar) throw new Error(`${file} does not compile`);
  const modules = grammar.deriveLength(n);
  if (modules < 0) throw new Error(`${file} n=${n} does not derive`);
  // Warm up, then run for at least ~1 s or 15 runs.
  for (let i = 0; i < 3; i++) grammar.deriveLength(n);
  const times = [];
  const start = performance.now();
  while (times.length < 15 || (performance.now() - start < 1000 && times.length < 200)) {
    const t0 = performance.now();
    grammar.deriveLength(n);
    times.push(performance.now() - t0);
  }
  grammar.free();
  const ms = median(times);
  rows.push({ workload: `${file} n=${n}`, modules, median_ms: +ms.toFixed(3), runs: times.length, mmodules_per_s: +((modules / ms) / 1000).toFixed(1) });
}

console.table(rows);
const machine = `${os.cpus()[0]?.model ?? 'unknown CPU'}, ${os.cpus().length} cores, Node ${process.version}`;
mkdirSync(new URL('../test-results/', import.meta.url), { recursive: true });
writeFileSync(new URL('../test-results/bench.json', import.meta.url), JSON.stringify({ machine, date: new Date().toISOString(), rows }, null, 2));
console.log(`machine: ${machine}\nwritten: test-results/bench.json`);
