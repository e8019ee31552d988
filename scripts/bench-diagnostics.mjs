// `node scripts/bench-diagnostics.mjs`: what a build's diagnostics cost the page's main thread, on
// the built site (dist/) in headless Chromium. A text of 100,000 lines the parser refuses (100,000
// diagnostics, tests/browser/problems.test.ts's) is opened, then one key at a time is typed into
// it (each keystroke a new build with as many diagnostics); for each keystroke a performance trace
// gives the main thread's tasks from the keystroke until the linter has shown the build's
// problems: the task that receives the build (the worker's message: its deserialisation, the
// preview's delivery, the status line) and the linter's task (the conversion to CodeMirror
// diagnostics, their order, the Problems panel's state). Medians go to
// test-results/bench-diagnostics.json. Run by `npm run bench:studio`, not part of `npm test`. KEYSTROKES=N types fewer keys; PROFILE_OUT=path writes each keystroke's CPU profile
// (path-N.cpuprofile, for Chromium's DevTools).
import { writeFileSync } from 'node:fs';
import { chromium } from 'playwright-core';
import { servedSite, writeResults } from './bench-site.mjs';

const KEYSTROKES = Number(process.env.KEYSTROKES ?? 6);
const MANY = `axiom: F\n${'?\n'.repeat(100_000)}`;

const median = (values) => {
  const s = [...values].sort((a, b) => a - b);
  return s.length === 0 ? NaN : s[Math.floor(s.length / 2)];
};
const round = (ms) => Math.round(ms * 10) / 10;

/** The trace events a task's summary names. */
const PARTS = /^(EventDispatch|FunctionCall|HandlePostMessage|SerializedScriptValueFactory::deserialize|MinorGC|MajorGC|TimerFire|FireAnimationFrame|FireIdleCallback|Paint|Layout|UpdateLayoutTree|BlinkScheduler_PerformMicrotaskCheckpoint)$/;

/** The main thread's tasks of `trace` longer than 5 ms: duration, and the time of its named parts. */
function mainTasks(trace) {
  const events = JSON.parse(trace).traceEvents;
  const main = events.find((e) => e.name === 'thread_name' && e.args?.name === 'CrRendererMain' && events.some((t) => t.pid === e.pid && t.name === 'EventDispatch'));
  const mine = events.filter((e) => e.pid === main.pid && e.tid === main.tid && e.ph === 'X');
  const tasks = mine.filter((e) => e.name === 'RunTask' && e.dur > 5000);
  return tasks.map((task) => {
    const inside = mine.filter((e) => e !== task && e.ts >= task.ts && e.ts + e.dur <= task.ts + task.dur);
    const parts = {};
    for (const e of inside) {
      if (!PARTS.test(e.name)) continue;
      const key = e.name === 'EventDispatch' ? `EventDispatch ${e.args?.data?.type}` : e.name === 'FunctionCall' ? `FunctionCall ${e.args?.data?.functionName || ''}` : e.name;
      parts[key] = round((parts[key] ?? 0) + e.dur / 1000);
    }
    return { ms: round(task.dur / 1000), parts };
  });
}

/** The functions of a CPU profile that took most time themselves (ms), the 12 heaviest. */
function heaviest(profile) {
  const self = new Map();
  const byId = new Map(profile.nodes.map((n) => [n.id, n]));
  for (let i = 0; i < profile.samples.length; i++) {
    const { callFrame: f } = byId.get(profile.samples[i]);
    const key = `${f.functionName || '(anonymous)'} ${f.url.split('/').pop()}:${f.lineNumber + 1}`;
    self.set(key, (self.get(key) ?? 0) + (profile.timeDeltas[i + 1] ?? 0) / 1000);
  }
  return Object.fromEntries([...self].filter(([k]) => !k.startsWith('(idle)') && !k.startsWith('(program)')).sort((a, b) => b[1] - a[1]).slice(0, 12).map(([k, v]) => [k, round(v)]));
}

const { server, url } = await servedSite();
const samples = [];
try {
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  // The build's message: its data deserialised (read first, before the client's listener) and the
  // listener with the microtasks that follow it (the preview's delivery) up to the next task.
  await page.addInitScript(() => {
    const w = window;
    w.__marks = [];
    const add = Worker.prototype.addEventListener;
    Worker.prototype.addEventListener = function (type, listener, options) {
      if (type !== 'message') return add.call(this, type, listener, options);
      return add.call(
        this,
        type,
        (event) => {
          const t0 = performance.now();
          const data = event.data;
          const t1 = performance.now();
          listener(event);
          const t2 = performance.now();
          if (data?.kind === 'built') {
            const mark = { deserialise: t1 - t0, listener: t2 - t1, count: data.build.diagnostics.length ?? data.build.diagnostics.errors?.length };
            w.__marks.push(mark);
            setTimeout(() => (mark.withMicrotasks = performance.now() - t0));
          }
        },
        options,
      );
    };
  });
  await page.goto(url);
  await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
  await page.evaluate(() => window.__meristem?.ready);
  const generation = () => page.evaluate(() => window.__meristem.preview.generation);
  let before = await generation();
  await page.getByTestId('file-input').setInputFiles({ name: 'many-problems.lsys', mimeType: 'text/plain', buffer: Buffer.from(MANY) });
  await page.waitForFunction((g) => window.__meristem.preview.generation > g, before, { timeout: 60_000 });
  await page.waitForTimeout(3000);
  await page.locator('[data-testid=editor] .cm-line', { hasText: '?' }).first().click();
  await page.keyboard.press('End');
  for (let i = 0; i < KEYSTROKES; i++) {
    await page.evaluate(() => (window.__marks = []));
    before = await generation();
    const profiler = await page.context().newCDPSession(page);
    await profiler.send('Profiler.enable');
    await profiler.send('Profiler.setSamplingInterval', { interval: 200 });
    await profiler.send('Profiler.start');
    await browser.startTracing(page, { categories: ['devtools.timeline', 'disabled-by-default-devtools.timeline', 'toplevel', 'v8', 'blink'] });
    await page.keyboard.press(i % 2 === 0 ? 'Backspace' : 'Shift+Slash');
    await page.waitForFunction((g) => window.__meristem.preview.generation > g, before, { timeout: 60_000 });
    await page.waitForTimeout(1500); // the linter's turn (400 ms after the edit) and its panel
    const trace = (await browser.stopTracing()).toString();
    const { profile } = await profiler.send('Profiler.stop');
    await profiler.detach();
    if (process.env.PROFILE_OUT) writeFileSync(`${process.env.PROFILE_OUT}-${i}.cpuprofile`, JSON.stringify(profile));
    if (process.env.PROFILE_OUT) writeFileSync(`${process.env.PROFILE_OUT}-${i}.trace.json`, trace);
    const marks = await page.evaluate(() => window.__marks);
    samples.push({ marks, tasks: mainTasks(trace), functions: heaviest(profile) });
    console.log(JSON.stringify(samples.at(-1)));
  }
  await browser.close();
} finally {
  await server.close();
}
const total = (tasks, part) => tasks.reduce((sum, t) => sum + (part ? (t.parts[part] ?? 0) : t.ms), 0);
const summary = {
  diagnostics: samples[0]?.marks[0]?.count,
  // The build's message: reading its data (the deserialisation), then with the delivery's microtasks.
  deserialiseMs: round(median(samples.map((s) => s.marks[0]?.deserialise))),
  messageWithMicrotasksMs: round(median(samples.map((s) => s.marks[0]?.withMicrotasks))),
  // The task of the build's message (the trace's): deserialisation, delivery, the linter's pass it lets run.
  messageTaskMs: round(median(samples.map((s) => Math.max(0, ...s.tasks.map((t) => t.parts.HandlePostMessage ?? 0))))),
  // Per keystroke, in the main thread's tasks of more than 5 ms: all of them, the garbage collector's part.
  tasksOver5MsPerKeystrokeMs: round(median(samples.map((s) => total(s.tasks)))),
  garbageCollectionMs: round(median(samples.map((s) => total(s.tasks, 'MinorGC') + total(s.tasks, 'MajorGC')))),
  longestTaskMs: round(median(samples.map((s) => Math.max(0, ...s.tasks.map((t) => t.ms))))),
};
console.log(summary);
if (process.env.KEYSTROKES === undefined) writeResults('bench-diagnostics.json', { summary, samples });
