// `npm run bench`: speed of the WebAssembly core in Node. Four tables: derivation on the workloads
// of issue 3; the whole pipeline and the mesh stage on those of issue 4, with issue 8's drag
// frame (one branch handle moved, the changed vertices copied out to JavaScript); the
// environment's programs of issue 47; and long texts through the first plant's core (issue 50,
// scripts/bench/long-texts.mjs). Writes
// test-results/bench.json (medians). The same workloads are benchmarked natively by criterion
// (crate/benches/derive.rs, crate/benches/pipeline.rs); all read their grammars from the gallery
// but the stepping rows of issue 45 (a `dt` grammar written here).
import { readFileSync, mkdirSync, writeFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import os from 'node:os';
import { initSync, Grammar, build, buildOn, LightBench } from '../crate/pkg/meristem.js';
import { longTextRows } from './bench/long-texts.mjs';

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

/** Runs `run` until ~1 s or 200 runs (at least 15) after 3 warm-ups; returns the median in ms. */
function time(run) {
  for (let i = 0; i < 3; i++) run();
  const times = [];
  const start = performance.now();
  while (times.length < 15 || (performance.now() - start < 1000 && times.length < 200)) {
    const t0 = performance.now();
    run();
    times.push(performance.now() - t0);
  }
  return { ms: median(times), runs: times.length };
}

const example = (file) => readFileSync(new URL(`../public/examples/${file}`, import.meta.url), 'utf8');
const copyOut = (b) => [b.positions(), b.normals(), b.colors(), b.indices(), b.ranges()];

// Issue 4: a tree the size of seed 001's (468 branches, 87,200 vertices) from grammar text to typed
// arrays in JavaScript, every stage included.
const pipelineRows = [];
// Issue 47: a stand of 9 trees of about 20,000 segments each (scripts/bench/stand-9.lsys) grown 10
// steps in one light grid, text to typed arrays: after the axiom and every step all 9 strings
// interpreted, the light program updated with all their parts and every bud's ?E answered, then
// the mesh. Target 2 s. cpu_ms is the process's CPU time (the wall time on a busy machine is more).
{
  const source = readFileSync(new URL('./bench/stand-9.lsys', import.meta.url), 'utf8');
  const probe = build(source, {});
  const stats = JSON.parse(probe.stats());
  probe.free();
  if (stats.segments < 9 * 19_000) throw new Error(`the stand has ${stats.segments} segments, not about 9 × 20,000`);
  const cpu = [];
  const runs = [];
  for (let i = 0; i < 5; i++) {
    const before = process.cpuUsage();
    const t0 = performance.now();
    const b = build(source, {});
    copyOut(b);
    b.free();
    runs.push(performance.now() - t0);
    const used = process.cpuUsage(before);
    cpu.push((used.user + used.system) / 1000);
  }
  const name = `stand of 9 trees, ${stats.segments.toLocaleString('en')} segments, 10 steps in light: text → typed arrays`;
  pipelineRows.push({ workload: name, vertices: stats.vertices, median_ms: +median(runs).toFixed(2), cpu_ms: +median(cpu).toFixed(2), runs: runs.length, target_ms: 2000 });
}
{
  const source = example('game-tree.lsys');
  const probe = build(source, {});
  const stats = JSON.parse(probe.stats());
  probe.free();
  const { ms, runs } = time(() => {
    const b = build(source, {});
    copyOut(b);
    b.free();
  });
  pipelineRows.push({ workload: 'game-tree.lsys: text → typed arrays', vertices: stats.vertices, median_ms: +ms.toFixed(2), runs, target_ms: 10 });
}
// Issue 4: the mesh stage alone on a million tube vertices (ABOP 2.8a, n = 9, 10 sides), arrays
// copied out included.
{
  const b = build(example('abop-2.08a-ternary-tree.lsys'), { iterations: 9, sides: 10 });
  const stats = JSON.parse(b.stats());
  const { ms, runs } = time(() => {
    b.remesh({ sides: 10 });
    copyOut(b);
  });
  b.free();
  pipelineRows.push({ workload: 'ABOP 2.8a n=9, 10 sides: mesh stage → typed arrays', vertices: stats.vertices, median_ms: +ms.toFixed(2), runs, target_ms: 100 });
}
// Issue 8: one drag frame of a branch of that tree: its handle P3 moved, the branch and its
// descendants re-placed and re-meshed, and the changed vertices copied out (what the studio
// uploads to the GPU). Target: 5 ms in wasm.
{
  const b = build(example('game-tree.lsys'), {}).intoEditor();
  // The branch at a path: from the roots down, at each level the child of that place.
  const [ranks, parents] = [b.branchRanks(), b.branchParents()];
  const branchAt = (path) =>
    path.reduce((at, place, depth) => ranks.findIndex((r, k) => r === place && parents[k] === (depth === 0 ? 0xffffffff : at)), -1);
  for (const [path, what] of [[[0, 0], 'a bough, 120 descendants'], [[0, 2, 0], 'a mid-level branch, 39 descendants']]) {
    const branch = branchAt(path);
    if (branch < 0) throw new Error(`no branch at ${path}`);
    const p3 = b.branchControlPoints().slice(12 * branch + 9, 12 * branch + 12);
    let frame = 0;
    let vertices = 0;
    const { ms, runs } = time(() => {
      frame += 1;
      const full = b.drag(branch, 3, p3[0] + 0.02 * (frame % 8), p3[1] - 0.05, p3[2] + 0.03);
      if (full) throw new Error(`drag of ${path} rebuilt the whole mesh: ${b.changeReason()}`);
      b.changedRanges();
      vertices = b.changedPositions().length / 3;
      b.changedNormals();
    });
    pipelineRows.push({ workload: `game-tree.lsys: drag branch [${path}] (${what}) → changed arrays`, vertices, median_ms: +ms.toFixed(2), runs, target_ms: 5 });
  }
  b.free();
}
// Issue 45: stepping a grammar of many small time steps (L-Py's continuous growth: `dt`), 10,236
// modules whose parameters grow each step, 1,000 steps. One step on from the kept build of 999
// steps (what the build worker does for a step forward and Play: `buildOn`), text to typed arrays
// with every stage after derive included (turtle, tubes, arrays copied out); then the same without
// the mesh (a sketch: lines only), and the whole derivation from the axiom it saves.
{
  const source = `#define dt 0.01
#iterations 1000
axiom: X(0)
X(k) : k < 11 -> /(137.5)[&(35)X(k+1)]X(k+1)
X(k) : k >= 11 -> A(0)
A(t) -> A(t + dt)
homomorphism:
A(t) -> F(0.05 + t)
`;
  const kept = build(source, { iterations: 999 }).intoInspector();
  const probe = buildOn(source, { iterations: 1000 }, kept);
  if (probe.continuedFrom !== 999) throw new Error(`the dt grammar was not continued (from ${probe.continuedFrom})`);
  const modules = probe.moduleCount;
  const stats = JSON.parse(probe.stats());
  probe.free();
  const name = `dt grammar (${modules.toLocaleString('en')} modules, ${stats.segments.toLocaleString('en')} segments)`;
  const step = (options) => () => {
    const b = buildOn(source, options, kept);
    copyOut(b);
    b.free();
  };
  const on = time(step({ iterations: 1000 }));
  pipelineRows.push({ workload: `${name}: step 999 → 1000 continued, meshed → typed arrays`, vertices: stats.vertices, median_ms: +on.ms.toFixed(2), runs: on.runs, target_ms: 5 });
  const sketch = time(step({ iterations: 1000, sketch: true }));
  pipelineRows.push({ workload: `${name}: step 999 → 1000 continued, lines only (no mesh)`, vertices: 0, median_ms: +sketch.ms.toFixed(2), runs: sketch.runs, target_ms: 5 });
  const whole = time(() => {
    const b = build(source, { iterations: 1000 });
    copyOut(b);
    b.free();
  });
  pipelineRows.push({ workload: `${name}: 1,000 steps from the axiom, meshed (what a step cost before)`, vertices: stats.vertices, median_ms: +whole.ms.toFixed(2), runs: whole.runs, target_ms: Infinity });
  kept.free();
}
console.table(pipelineRows);

// Issue 47: the environment. One light step (crate/src/environment/light/): the grid rebuilt from
// 100,000 segments (branches of 100 end to end, as a turtle draws them) in 128³ voxels, the sky's
// shadow and the sun's beam propagated, and 1,000 probes answered. Target 50 ms.
const environmentRows = [];
{
  const light = new LightBench(100_000, 1_000, 128, 1);
  light.update();
  const dims = [...light.dims()].join(' × ');
  const cpu = [];
  const { ms, runs } = time(() => {
    const before = process.cpuUsage();
    light.update();
    light.answer();
    const used = process.cpuUsage(before);
    cpu.push((used.user + used.system) / 1000);
  });
  environmentRows.push({ workload: `light step: 100,000 segments, ${dims} voxels, 1,000 probes (update + answer)`, MB: +(light.bytes() / 1e6).toFixed(1), median_ms: +ms.toFixed(2), cpu_ms: +median(cpu).toFixed(2), runs, target_ms: 50 });
  light.free();
}
console.table(environmentRows);
// Issue 50, finding 7: long texts through the first plant's core (scripts/bench/long-texts.mjs).
const longTexts = longTextRows();
console.table(longTexts);
const failures = [...pipelineRows, ...environmentRows, ...longTexts].filter((r) => r.median_ms > r.target_ms);
const machine = `${os.cpus()[0]?.model ?? 'unknown CPU'}, ${os.cpus().length} cores, Node ${process.version}`;
mkdirSync(new URL('../test-results/', import.meta.url), { recursive: true });
writeFileSync(new URL('../test-results/bench.json', import.meta.url), JSON.stringify({ machine, date: new Date().toISOString(), rows, pipeline: pipelineRows, environment: environmentRows, long_texts: longTexts }, null, 2));
console.log(`machine: ${machine}\nwritten: test-results/bench.json`);
for (const r of failures) console.log(`over target: ${r.workload}: ${r.median_ms} ms > ${r.target_ms} ms`);
