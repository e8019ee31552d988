// Makes docs/img/growth.gif, the README's picture of a plant growing, with Meristem itself: the
// built studio (dist/, `vite build` first) in headless Chromium opens ABOP Fig. 1.24a at n = 5,
// uses the timeline once (so that the plant carries its growth times), and records an animated GIF
// through Download ▸ Movie of the growth, as a user would.
//   node scripts/readme-gif.mjs
import { copyFileSync } from 'node:fs';
import { chromium } from 'playwright-core';
import { servedSite } from './bench-site.mjs';

const OUT = new URL('../docs/img/growth.gif', import.meta.url).pathname;
const { server, url } = await servedSite();
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 }, acceptDownloads: true });
  await page.goto(url);
  await page.waitForFunction(() => window.__meristem?.preview?.settled === true && (window.__meristem.lastStats?.segments ?? 0) > 0, undefined, { timeout: 60_000 });
  // Fig. 1.24a from the gallery (the first text is the initial example: nothing to confirm).
  await page.getByTestId('open-gallery').click();
  await page.locator('[data-testid=gallery-list] button[data-file="abop-1.24a.lsys"]').click();
  await page.waitForFunction(() => window.__meristem?.preview?.lastResult?.source.includes('1.24a') && window.__meristem.preview.settled, undefined, { timeout: 60_000 });
  await page.getByTestId('iterations').fill('5');
  await page.getByTestId('timeline-slider').waitFor();
  await page.getByTestId('timeline-slider').fill('5'); // the timeline in use: builds carry growth times
  await page.waitForFunction(() => window.__meristem?.growth?.().span === 5, undefined, { timeout: 60_000 });
  await page.getByTestId('downloads').locator('summary').click();
  await page.getByTestId('download-movie').click();
  await page.waitForFunction(() => document.querySelector('[data-testid=movie-format] option') !== null);
  await page.getByTestId('movie-format').selectOption('gif');
  await page.getByTestId('movie-size').selectOption('');
  await page.getByTestId('movie-width').fill('360');
  await page.getByTestId('movie-height').fill('360');
  await page.getByTestId('movie-fps').selectOption('10');
  await page.getByTestId('movie-timing').selectOption('duration');
  await page.getByTestId('movie-seconds').fill('5');
  await page.getByTestId('movie-background').selectOption('white');
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: 120_000 }), page.getByTestId('movie-record').click()]);
  copyFileSync(await download.path(), OUT);
  console.log(`wrote ${OUT} (${await page.getByTestId('movie-summary').textContent()})`);
} finally {
  await browser.close();
  server.httpServer.close();
}
