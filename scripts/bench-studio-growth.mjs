// `npm run bench:studio`'s growth rows (issue 45): the main thread's work per frame while the
// timeline plays the growth of ABOP 1.24d at n = 10 (116,050 segments), and the frames per second
// it plays ABOP 1.24d at n = 7 (4,118 segments) at: in the Tubes mode, and in the Lines mode (the
// flat tree's own: its segments grown by the texel lines' shader; where a software rasterizer
// draws the view, what it draws in 2D is WebGL's while a growth time is shown). In headless
// Chromium on the built site (dist/). The timeline plays the whole growth once, t from 0 to N at 1
// step a second, as Play does. Every requestAnimationFrame callback of the page is timed (an init script wraps
// them): a frame's work is the sum of its callbacks, the timeline's tick and the view's draw call
// (the draw itself runs in the GPU process). The frames counted are those the view drew (an
// animation frame at which the GPU was still busy with the frame before draws nothing): over the
// whole growth, and over its last step alone (the whole plant's triangles drawn). Both of
// bench-studio.mjs's Chromium setups; BENCH_SETUP=software (or gpu) runs one, BENCH_WORKLOAD=0
// to 3 one workload. Results go to test-results/bench-studio-growth.json.
import { chromium } from 'playwright-core';
import { SETUPS, servedSite, writeResults } from './bench-site.mjs';

const WORKLOADS = [
  { name: 'ABOP 1.24d, n = 10 (116,050 segments), Tubes mode', iterations: 10, tubes: true },
  { name: 'ABOP 1.24d, n = 7 (4,118 segments), Tubes mode', iterations: 7, tubes: true },
  { name: 'ABOP 1.24d, n = 10 (116,050 segments), Lines mode', iterations: 10, tubes: false },
  { name: 'ABOP 1.24d, n = 7 (4,118 segments), Lines mode', iterations: 7, tubes: false },
];
const setups = Object.entries(SETUPS).filter(([name]) => process.env.BENCH_SETUP === undefined || name.toLowerCase().startsWith(process.env.BENCH_SETUP));

/**
 * Times every requestAnimationFrame callback: `window.__frames` maps each frame's time to its work
 * (ms), whether the view drew in it, and the growth time shown after it.
 */
function timeFrames() {
  const frames = new Map();
  window.__frames = frames;
  const request = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) =>
    request((time) => {
      const start = performance.now();
      const drawnBefore = window.__meristem?.rendered?.at;
      try {
        callback(time);
      } finally {
        const frame = frames.get(time) ?? { work: 0, drew: false, t: null };
        frame.work += performance.now() - start;
        frame.drew ||= window.__meristem?.rendered?.at !== drawnBefore;
        frame.t = window.__meristem?.growth?.().t ?? null;
        frames.set(time, frame);
      }
    });
}

/** Frames drawn per second among `frames` ([time, frame] pairs) that pass `which`. */
function drawnPerSecond(frames, which) {
  const times = frames.filter(([, frame]) => frame.drew && which(frame)).map(([time]) => time);
  if (times.length < 2) return NaN;
  return Math.round(((times.length - 1) / ((Math.max(...times) - Math.min(...times)) / 1000)) * 10) / 10;
}

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)] ?? NaN;

const { server, url } = await servedSite();
const results = [];
try {
  for (const [setup, args] of setups) {
    for (const workload of WORKLOADS.filter((_, k) => process.env.BENCH_WORKLOAD === undefined || String(k) === process.env.BENCH_WORKLOAD)) {
      const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args });
      const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
      await page.addInitScript(timeFrames);
      await page.goto(url);
      await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
      await page.getByTestId('iterations').fill(String(workload.iterations));
      if (workload.tubes) await page.getByTestId('render-lines').click(); // Tubes (the flat tree's lines otherwise)
      await page.getByTestId('timeline-slider').waitFor();
      await page.getByTestId('timeline-slider').fill('0'); // the timeline in use: the next build carries growth times
      await page.waitForFunction((n) => window.__meristem?.growth?.().span === n && window.__meristem.preview?.settled, workload.iterations, { timeout: 120_000 });
      const stats = await page.evaluate(() => window.__meristem.lastStats);
      await page.getByTestId('timeline-slider').fill('0');
      await page.waitForTimeout(500);
      const builds = await page.evaluate(() => window.__meristem.preview.generation);
      await page.evaluate(() => window.__frames.clear());
      await page.getByTestId('timeline-play').click();
      // Played to the end: the timeline stops there (loop is off).
      await page.waitForFunction(() => document.querySelector('[data-testid=timeline-play]')?.getAttribute('aria-pressed') === 'false', undefined, { timeout: 60_000, polling: 100 });
      const frames = await page.evaluate(() => [...window.__frames.entries()]);
      const rebuilt = (await page.evaluate(() => window.__meristem.preview.generation)) !== builds;
      const n = workload.iterations;
      const row = {
        setup,
        workload: workload.name,
        segments: stats.segments,
        vertices: stats.vertices,
        frames: frames.length,
        framesDrawn: frames.filter(([, frame]) => frame.drew).length,
        framesPerSecond: drawnPerSecond(frames, () => true),
        framesPerSecondBeforeLastStep: drawnPerSecond(frames, ({ t }) => t !== null && t < n - 1),
        framesPerSecondLastStep: drawnPerSecond(frames, ({ t }) => t === null || t >= n - 1),
        workPerFrameMs: Math.round(median(frames.map(([, frame]) => frame.work)) * 100) / 100,
        buildsWhilePlaying: rebuilt,
      };
      results.push(row);
      console.log(JSON.stringify(row));
      await browser.close();
    }
  }
} finally {
  await server.close();
}
writeResults('bench-studio-growth.json', { results });
