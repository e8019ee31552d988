// `npm run bench:studio`'s growth rows (issue 45): the main thread's work per frame while the
// timeline plays the growth of ABOP 1.24d at n = 10 (116,050 segments), and the frames per second
// it plays ABOP 1.24d at n = 7 (4,118 segments) at: in the Tubes mode, and in the Lines mode (the
// flat tree's own: its segments grown by the texel lines' shader; where a software rasterizer
// draws the view, what it draws in 2D is WebGL's while a growth time is shown). In headless Chromium on the built
// site (dist/). Every requestAnimationFrame callback of the page is timed (an init script wraps
// them): a frame's work is the sum of its callbacks, the timeline's tick and the view's draw call
// (the draw itself runs in the GPU process). Both of bench-studio.mjs's Chromium setups;
// BENCH_SETUP=software (or gpu) runs one. Results go to test-results/bench-studio-growth.json.
import { chromium } from 'playwright-core';
import { SETUPS, servedSite, writeResults } from './bench-site.mjs';

const WORKLOADS = [
  { name: 'ABOP 1.24d, n = 10 (116,050 segments), Tubes mode', iterations: 10, tubes: true },
  { name: 'ABOP 1.24d, n = 7 (4,118 segments), Tubes mode', iterations: 7, tubes: true },
  { name: 'ABOP 1.24d, n = 10 (116,050 segments), Lines mode', iterations: 10, tubes: false },
  { name: 'ABOP 1.24d, n = 7 (4,118 segments), Lines mode', iterations: 7, tubes: false },
];
const PLAY_MS = 4000;
const setups = Object.entries(SETUPS).filter(([name]) => process.env.BENCH_SETUP === undefined || name.toLowerCase().startsWith(process.env.BENCH_SETUP));

/** Times every requestAnimationFrame callback: `window.__frames` gets each frame's time and work (ms). */
function timeFrames() {
  const frames = new Map();
  window.__frames = frames;
  const request = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) =>
    request((time) => {
      const start = performance.now();
      try {
        callback(time);
      } finally {
        frames.set(time, (frames.get(time) ?? 0) + performance.now() - start);
      }
    });
}

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)] ?? NaN;

const { server, url } = await servedSite();
const results = [];
try {
  for (const [setup, args] of setups) {
    for (const workload of WORKLOADS) {
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
      await page.waitForTimeout(PLAY_MS);
      await page.getByTestId('timeline-play').click();
      const frames = await page.evaluate(() => [...window.__frames.entries()]);
      const rebuilt = (await page.evaluate(() => window.__meristem.preview.generation)) !== builds;
      const times = frames.map(([time]) => time);
      const span = (Math.max(...times) - Math.min(...times)) / 1000;
      const row = {
        setup,
        workload: workload.name,
        segments: stats.segments,
        vertices: stats.vertices,
        frames: frames.length,
        framesPerSecond: Math.round(((frames.length - 1) / span) * 10) / 10,
        workPerFrameMs: Math.round(median(frames.map(([, work]) => work)) * 100) / 100,
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
