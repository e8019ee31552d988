// `npm run bench:studio`: keystroke-to-frame time of the studio in headless Chromium, on the built
// site (dist/). For each workload the grammar is opened, then one key at a time is typed into the
// `#angle` line (Backspace makes `#angle 2`, `0` makes `#angle 20` again: every keystroke gives a
// new valid grammar); each keystroke is timed from its keydown event to the end of the frame that
// draws its plant (its JavaScript: the frame is then handed to the GPU), to the next animation
// frame after it, and to the GPU's end of that frame (a fence). Each key waits until the previous
// key's frames are done on the GPU, so each is measured alone. Two Chromium setups: GPU compositing on
// SwiftShader (as on a machine with a GPU) and Chromium's default without a GPU (software
// compositing: every WebGL frame is read back on the main thread, waiting for the rasterizer).
// Medians go to test-results/bench-studio.json. Not part of `npm test`.
// While working on one stage: BENCH_SETUP=software (or gpu) and BENCH_WORKLOAD=0 (an index of
// WORKLOADS) run one of each, and KEYSTROKES=N types fewer keys; the file is then not written.
import { chromium } from 'playwright-core';
import { SETUPS, servedSite, writeResults } from './bench-site.mjs';

const KEYSTROKES = Number(process.env.KEYSTROKES ?? 16);
// The flat example is drawn as lines (`auto`), which mesh no tubes: the tube frame is measured with
// the Tubes mode chosen (the Lines toggle), and the Lines mode as the studio opens.
const WORKLOADS = [
  { name: 'ABOP 1.24d, n = 10 (116,050 segments), Tubes mode', iterations: '10', tubes: true },
  { name: 'ABOP 1.24d, n = 10, Lines mode (auto, flat)', iterations: '10', tubes: false },
  { name: 'ABOP 1.24d, n = 7 (4,118 segments), Tubes mode', iterations: '', tubes: true },
];

const only = (entries, chosen, matches) => (chosen === undefined ? entries : entries.filter((entry, i) => matches(entry, i, chosen)));
const setups = only(Object.entries(SETUPS), process.env.BENCH_SETUP, ([name], _, chosen) => name.toLowerCase().startsWith(chosen));
const workloads = only(WORKLOADS, process.env.BENCH_WORKLOAD, (_, i, chosen) => i === Number(chosen));
const partial = setups.length < Object.keys(SETUPS).length || workloads.length < WORKLOADS.length || KEYSTROKES !== 16;

const median = (values) => {
  const s = [...values].sort((a, b) => a - b);
  return s.length === 0 ? NaN : s[Math.floor(s.length / 2)];
};
const round = (ms) => Math.round(ms * 10) / 10;

const { server, url } = await servedSite();
const results = [];
try {
  for (const [setup, args] of setups) {
    const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args });
    for (const workload of workloads) {
      const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
      await page.goto(url);
      await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
      if (workload.iterations) {
        await page.getByTestId('iterations').fill(workload.iterations);
        await page.waitForFunction((n) => window.__meristem?.lastStats?.iterations === n, Number(workload.iterations), { timeout: 60_000 });
      }
      if (workload.tubes) {
        await page.getByTestId('render-lines').click();
        await page.waitForFunction(() => (window.__meristem?.lastStats?.vertices ?? 0) > 0, null, { timeout: 60_000 });
      }
      await page.getByTestId('frame').click();
      const stats = await page.evaluate(() => window.__meristem.lastStats);
      // In the page: the keydown time, and for each delivered build its arrival, cost and first frame.
      await page.evaluate(() => {
        const w = window;
        w.__bench = { keydown: 0, deliveries: [] };
        addEventListener('keydown', (e) => (w.__bench.keydown = e.timeStamp), { capture: true });
        w.__meristem.preview.onDelivered((r) =>
          w.__bench.deliveries.push({ source: r.source, at: performance.now(), generation: w.__meristem.preview.generation, roundTrip: r.roundTripMillis, worker: r.workerMillis, studioCore: r.studioCore, timings: r.build.timings }),
        );
      });
      await page.locator('[data-testid=editor] .cm-line', { hasText: '#angle' }).click();
      await page.keyboard.press('End');
      const samples = [];
      for (let i = 0; i < KEYSTROKES; i++) {
        await page.keyboard.press(i % 2 === 0 ? 'Backspace' : 'Digit0');
        const expected = i % 2 === 0 ? '#angle 2\n' : '#angle 20\n';
        const sample = await page.evaluate(
          (text) =>
            new Promise((resolve) => {
              const poll = () => {
                const b = window.__bench;
                const d = b.deliveries.at(-1);
                const r = window.__meristem.rendered;
                if (d && d.source.includes(text) && r && r.generation >= d.generation) {
                  // The GPU done with that frame: a fence after it (the frame is only handed to
                  // the GPU when its JavaScript ends; a software GPU rasterizes it afterwards).
                  const gl = document.querySelector('[data-testid=viewport] canvas').getContext('webgl2');
                  const fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
                  gl.flush();
                  let nextFrame = null;
                  requestAnimationFrame(() => (nextFrame = performance.now()));
                  const done = () => {
                    if (nextFrame === null || gl.getSyncParameter(fence, gl.SYNC_STATUS) !== gl.SIGNALED) return void setTimeout(done, 1);
                    gl.deleteSync(fence);
                    const sketched = window.__meristem.sketched;
                    resolve({
                      keydown: b.keydown,
                      delivered: d.at,
                      rendered: r.at,
                      gpuDone: performance.now(),
                      sketched: sketched !== null && sketched > b.keydown && sketched <= r.at ? sketched : null,
                      nextFrame,
                      roundTrip: d.roundTrip,
                      worker: d.worker,
                      studioCore: d.studioCore,
                      timings: d.timings,
                    });
                  };
                  done();
                } else setTimeout(poll, 1);
              };
              poll();
            }),
          expected,
        );
        samples.push(sample);
        // Let the (software) GPU finish: two more frames, then a pause.
        await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
        await page.waitForTimeout(300);
      }
      const pick = (f) => round(median(samples.map(f)));
      const row = {
        setup,
        workload: workload.name,
        segments: stats.segments,
        vertices: stats.vertices,
        // The first frame that shows the edited plant: its sketch (big plants) or the plant itself.
        keystrokeToFirstFrameMs: pick((s) => (s.sketched ?? s.rendered) - s.keydown),
        sketched: samples.filter((s) => s.sketched !== null).length,
        keystrokeToDrawnMs: pick((s) => s.rendered - s.keydown),
        keystrokeToNextFrameMs: pick((s) => s.nextFrame - s.keydown),
        keystrokeToGpuDoneMs: pick((s) => s.gpuDone - s.keydown),
        roundTripMs: pick((s) => s.roundTrip),
        workerMs: pick((s) => s.worker),
        coreMs: pick((s) => s.timings.parseResolve + s.timings.derive + s.timings.interpret + s.timings.mesh),
        meshMs: pick((s) => s.timings.mesh),
        deliveredToDrawnMs: pick((s) => s.rendered - s.delivered),
        // Builds made by the studio core (crate/pkg, built for speed), which the page asks the
        // worker to load once its first load is done, rather than the first plant's (crate/pkg-core).
        studioCoreBuilds: samples.filter((s) => s.studioCore).length,
      };
      results.push(row);
      console.log(JSON.stringify(row));
      await page.close();
    }
    await browser.close();
  }
} finally {
  await server.close();
}
if (!partial) {
  writeResults('bench-studio.json', { keystrokes: KEYSTROKES, results });
}
console.log('\n| setup | workload | keystroke → first frame of the new plant | → tubes drawn | → next frame | → GPU done | round trip (request → build on the page) | in the worker | core stages | of which mesh | build on the page → drawn | built by the studio core |');
console.log('| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |');
for (const r of results)
  console.log(
    `| ${r.setup} | ${r.workload} | ${r.keystrokeToFirstFrameMs} ms${r.sketched ? ' (sketch)' : ''} | ${r.keystrokeToDrawnMs} ms | ${r.keystrokeToNextFrameMs} ms | ${r.keystrokeToGpuDoneMs} ms | ${r.roundTripMs} ms | ${r.workerMs} ms | ${r.coreMs} ms | ${r.meshMs} ms | ${r.deliveredToDrawnMs} ms | ${r.studioCoreBuilds} of ${KEYSTROKES} |`,
  );
