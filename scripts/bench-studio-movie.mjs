// `npm run bench:studio`'s movie row (issue 45): the time to write a 10 s, 30 fps, 1280 × 720 WebM
// of ABOP 1.24d at n = 7 (4,118 segments, Tubes mode) through the Download menu's movie dialog, in
// headless Chromium on the built site (dist/): from the click on Record to the download, with
// the frames drawn by the view (software WebGL here: no GPU) and encoded by WebCodecs' VP9
// encoder. The plant grows over the movie where the view has growth times (the timeline's), and
// the camera turns once about it. Both of bench-studio.mjs's Chromium setups; BENCH_SETUP=software
// (or gpu) runs one. Results go to test-results/bench-studio-movie.json. Not part of `npm test`.
import { chromium } from 'playwright-core';
import { SETUPS, servedSite, writeResults } from './bench-site.mjs';

const MOVIE = { width: 1280, height: 720, fps: 30, seconds: Number(process.env.BENCH_SECONDS ?? 10) };
const setups = Object.entries(SETUPS).filter(([name]) => process.env.BENCH_SETUP === undefined || name.toLowerCase().startsWith(process.env.BENCH_SETUP));

const { server, url } = await servedSite();
const results = [];
try {
  for (const [setup, args] of setups) {
    const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args });
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 }, acceptDownloads: true });
    await page.goto(url);
    await page.waitForFunction(() => (window.__meristem?.lastStats?.segments ?? 0) > 0);
    await page.getByTestId('render-lines').click(); // Tubes
    await page.waitForFunction(() => (window.__meristem?.lastStats?.vertices ?? 0) > 0, null, { timeout: 60_000 });
    const stats = await page.evaluate(() => window.__meristem.lastStats);
    await page.getByTestId('downloads').locator('summary').click();
    await page.getByTestId('download-movie').click();
    await page.getByTestId('movie-dialog').waitFor({ state: 'visible' });
    await page.getByTestId('movie-format').selectOption('webm');
    await page.getByTestId('movie-size').selectOption(`${MOVIE.width}x${MOVIE.height}`);
    await page.getByTestId('movie-fps').selectOption(String(MOVIE.fps));
    await page.getByTestId('movie-timing').selectOption('duration');
    await page.getByTestId('movie-seconds').fill(String(MOVIE.seconds));
    await page.getByTestId('movie-turntable').setChecked(true);
    const started = Date.now();
    const [download] = await Promise.all([page.waitForEvent('download', { timeout: 600_000 }), page.getByTestId('movie-record').click()]);
    const ms = Date.now() - started;
    const summary = await page.getByTestId('movie-summary').textContent();
    const frames = MOVIE.fps * MOVIE.seconds;
    const row = {
      setup,
      workload: `WebM ${MOVIE.seconds} s, ${MOVIE.fps} fps, ${MOVIE.width} × ${MOVIE.height} of ABOP 1.24d, n = 7 (${stats.segments} segments), Tubes mode`,
      frames,
      writtenMs: ms,
      perFrameMs: Math.round((ms / frames) * 10) / 10,
      file: download.suggestedFilename(),
      summary,
    };
    results.push(row);
    console.log(JSON.stringify(row));
    await browser.close();
  }
} finally {
  await server.close();
}
writeResults('bench-studio-movie.json', { results });
console.log('\n| setup | workload | written in (Record → download) | per frame | target |');
console.log('| --- | --- | ---: | ---: | ---: |');
for (const r of results) console.log(`| ${r.setup} | ${r.workload} | ${(r.writtenMs / 1000).toFixed(1)} s | ${r.perFrameMs} ms | ≤ 30 s |`);
