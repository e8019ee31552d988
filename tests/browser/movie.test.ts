// End-to-end: movies of the plant from the Download menu's movie dialog, as a user makes them. The
// files downloaded are read by their specifications (./media-files.ts) for the frame count and size
// asked, and decoded by the browser's own decoders (WebCodecs' VideoDecoder for the WebM's frames,
// a <video> element for its playing size and length, ImageDecoder for the GIF's), whose frames
// must differ as the camera turns. Also: Cancel stops a movie and saves nothing; too big a movie is
// refused with a message; the dialog fits a phone.
import { readFileSync, writeFileSync } from 'node:fs';
import type { Download } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { unzipSync } from 'fflate';
import { readGif, readMp4, readWebm } from './media-files';
import { decodePng, foregroundMask, type Picture } from './pictures';
import { browser, page, problems, useStudio } from './session';
import { canvasPicture, openExample, pasteText, RESULTS, twoFrames } from './studio-page';

useStudio();

/** The studio opens on ABOP's Fig. 1.24d: files are named after its title. */
const NAME = 'abop-1.24d';

/** Opens the movie dialog from the Download menu. */
async function openMovieDialog(): Promise<void> {
  const dialog = page.getByTestId('movie-dialog');
  if (await dialog.isVisible()) return;
  await page.getByTestId('downloads').locator('summary').click();
  await page.getByTestId('download-movie').click();
  await dialog.waitFor({ state: 'visible' });
  await page.waitForFunction(() => document.querySelector('[data-testid=movie-format] option') !== null);
}

/** Sets the dialog's choices as a user would. */
async function choose(choices: { format: string; width: number; height: number; fps: number; seconds: number; turntable: boolean }): Promise<void> {
  await page.getByTestId('movie-format').selectOption(choices.format);
  await page.getByTestId('movie-width').fill(String(choices.width));
  await page.getByTestId('movie-height').fill(String(choices.height));
  await page.getByTestId('movie-fps').selectOption(String(choices.fps));
  await page.getByTestId('movie-timing').selectOption('duration');
  await page.getByTestId('movie-seconds').fill(String(choices.seconds));
  await page.getByTestId('movie-turntable').setChecked(choices.turntable);
}

/** Records the movie chosen and returns the download. */
async function record(): Promise<Download> {
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: 60_000 }), page.getByTestId('movie-record').click()]);
  await page.waitForFunction(() => document.querySelector('[data-testid=movie-dialog]')?.getAttribute('data-state') === 'idle');
  return download;
}

/** Makes the movie of `choices` through the dialog (its summary first saying `planned`), and returns the file downloaded (kept in test-results). */
async function movieFile(choices: Parameters<typeof choose>[0], planned: RegExp, fileName: string): Promise<Uint8Array> {
  await openMovieDialog();
  await choose(choices);
  await expect.poll(() => page.getByTestId('movie-summary').textContent()).toMatch(planned);
  const download = await record();
  expect(download.suggestedFilename()).toBe(fileName);
  await download.saveAs(new URL(fileName, RESULTS).pathname);
  return new Uint8Array(readFileSync(await download.path()));
}

describe('videos of the growth', () => {
  it('writes a WebM of the frame count and size asked, which the browser decodes and plays', async () => {
    const bytes = await movieFile({ format: 'webm', width: 320, height: 240, fps: 24, seconds: 0.5, turntable: true }, /^12 frames · 0\.5 s · 320 × 240/, `${NAME}.webm`);
    const webm = readWebm(bytes);
    expect(webm).toMatchObject({ width: 320, height: 240, codec: 'V_VP9' });
    expect(webm.blocks.length).toBe(12);
    expect(webm.blocks[0].keyframe).toBe(true);
    expect(webm.duration).toBeCloseTo(0.5, 1);
    expect(webm.blocks.map((b) => Math.round(b.time * 24))).toEqual([...Array(12).keys()]);
    await expect.poll(() => page.getByTestId('movie-summary').textContent()).toMatch(/^Saved .*\.webm · 12 frames · /);

    // The browser decodes each block into a 320 × 240 frame; the turning camera makes them differ.
    const decoded = await page.evaluate(async (blocks) => {
      const frames: { width: number; height: number; sum: number }[] = [];
      const canvas = new OffscreenCanvas(320, 240);
      const context = canvas.getContext('2d', { willReadFrequently: true })!;
      const decoder = new VideoDecoder({
        output: (frame) => {
          context.drawImage(frame, 0, 0);
          const pixels = context.getImageData(0, 0, 320, 240).data;
          let sum = 0;
          for (let i = 0; i < pixels.length; i += 4) sum += (pixels[i] * (i % 9973)) % 65_521;
          frames.push({ width: frame.displayWidth, height: frame.displayHeight, sum });
          frame.close();
        },
        error: (error) => frames.push({ width: -1, height: -1, sum: String(error).length }),
      });
      decoder.configure({ codec: 'vp09.00.31.08' });
      for (const [i, block] of blocks.entries()) {
        decoder.decode(new EncodedVideoChunk({ type: block.keyframe ? 'key' : 'delta', timestamp: i * 41_667, data: new Uint8Array(block.data) }));
      }
      await decoder.flush();
      return frames;
    }, webm.blocks.map((b) => ({ keyframe: b.keyframe, data: [...b.data] })));
    expect(decoded.length).toBe(12);
    expect(decoded.every((f) => f.width === 320 && f.height === 240)).toBe(true);
    expect(new Set(decoded.map((f) => f.sum)).size, 'the frames differ as the camera turns').toBeGreaterThan(6);

    // (In a page of its own: the studio's Content-Security-Policy admits no media from blob: URLs.)
    const blank = await browser.newPage();
    const played = await blank.evaluate(async (data) => {
      const video = document.createElement('video');
      video.muted = true;
      video.src = URL.createObjectURL(new Blob([new Uint8Array(data)], { type: 'video/webm' }));
      await new Promise((resolve, reject) => ((video.onloadedmetadata = resolve), (video.onerror = () => reject(new Error(String(video.error?.message))))));
      return { width: video.videoWidth, height: video.videoHeight, duration: video.duration };
    }, [...bytes]);
    await blank.close();
    expect(played.width).toBe(320);
    expect(played.height).toBe(240);
    expect(played.duration).toBeCloseTo(0.5, 1);
  });

  it('writes an MP4 where the browser encodes H.264, which the browser plays', async () => {
    await openMovieDialog();
    const offered = await page.getByTestId('movie-format').locator('option[value=mp4]').count();
    const encodes = await page.evaluate(async () => (await VideoEncoder.isConfigSupported({ codec: 'avc1.64001f', width: 1280, height: 720 })).supported === true);
    expect(offered, 'MP4 is offered exactly when the browser encodes H.264').toBe(encodes ? 1 : 0);
    if (!encodes) return;
    const bytes = await movieFile({ format: 'mp4', width: 320, height: 240, fps: 25, seconds: 0.4, turntable: true }, /^10 frames · 0\.4 s/, `${NAME}.mp4`);
    expect(readMp4(bytes)).toEqual({ width: 320, height: 240, format: 'avc1', samples: 10 });
    const blank = await browser.newPage();
    const played = await blank.evaluate(async (data) => {
      const video = document.createElement('video');
      video.src = URL.createObjectURL(new Blob([new Uint8Array(data)], { type: 'video/mp4' }));
      const loaded = await new Promise((resolve) => ((video.onloadedmetadata = () => resolve(true)), (video.onerror = () => resolve(false))));
      return { loaded, width: video.videoWidth, height: video.videoHeight, duration: video.duration };
    }, [...bytes]);
    await blank.close();
    // (Debian's Chromium encodes H.264 but may have no decoder for it: then only the file's boxes are checked.)
    if (played.loaded) expect(played).toMatchObject({ width: 320, height: 240 });
  });

});

describe('GIFs, PNG sequences, and movies stopped or refused', () => {
  it('writes a looping GIF of the frame count, size and delay asked, which the browser decodes', async () => {
    const bytes = await movieFile({ format: 'gif', width: 160, height: 120, fps: 20, seconds: 0.4, turntable: true }, /^8 frames · 0\.4 s · 160 × 120/, `${NAME}.gif`);
    const gif = readGif(bytes);
    expect(gif).toMatchObject({ width: 160, height: 120, loops: 0 });
    expect(gif.frames).toEqual(Array(8).fill({ width: 160, height: 120, delay: 5 }));

    const decoded = await page.evaluate(async (data) => {
      const decoder = new ImageDecoder({ data: new Uint8Array(data), type: 'image/gif' });
      await decoder.tracks.ready;
      const count = decoder.tracks.selectedTrack!.frameCount;
      const sums: number[] = [];
      const canvas = new OffscreenCanvas(160, 120);
      const context = canvas.getContext('2d', { willReadFrequently: true })!;
      for (let i = 0; i < count; i++) {
        const { image } = await decoder.decode({ frameIndex: i });
        context.drawImage(image, 0, 0);
        image.close();
        const pixels = context.getImageData(0, 0, 160, 120).data;
        let sum = 0;
        for (let p = 0; p < pixels.length; p += 4) sum += (pixels[p + 1] * (p % 9973)) % 65_521;
        sums.push(sum);
      }
      return { count, sums };
    }, [...bytes]);
    expect(decoded.count).toBe(8);
    expect(new Set(decoded.sums).size, 'the frames differ as the camera turns').toBeGreaterThan(4);
  });

  it('writes a PNG sequence: a zip of numbered PNGs of the size asked', async () => {
    const files = unzipSync(await movieFile({ format: 'png', width: 200, height: 150, fps: 10, seconds: 0.5, turntable: true }, /^5 frames/, `${NAME}-frames.zip`));
    expect(Object.keys(files)).toEqual([1, 2, 3, 4, 5].map((i) => `${NAME}-000${i}.png`));
    const pictures = Object.values(files).map((png) => decodePng(Buffer.from(png)));
    expect(pictures.map((p) => [p.width, p.height])).toEqual(Array(5).fill([200, 150]));
    expect(Buffer.compare(Buffer.from(files[`${NAME}-0001.png`]), Buffer.from(files[`${NAME}-0002.png`])), 'the camera turns').not.toBe(0);
    for (const [file, png] of Object.entries(files)) writeFileSync(new URL(file, RESULTS).pathname, png);
  });

  it('cancels a movie at once: nothing is saved, and the view is back as it was', async () => {
    await openMovieDialog();
    await choose({ format: 'webm', width: 640, height: 360, fps: 30, seconds: 60, turntable: true });
    const downloads: string[] = [];
    page.on('download', (d) => downloads.push(d.suggestedFilename()));
    await page.getByTestId('movie-record').click();
    await page.waitForFunction(() => Number((document.querySelector('[data-testid=movie-progress]') as HTMLProgressElement | null)?.value) >= 3);
    await page.getByTestId('movie-cancel').click();
    await page.waitForFunction(() => document.querySelector('[data-testid=movie-dialog]')?.getAttribute('data-state') === 'idle');
    await expect.poll(() => page.getByTestId('movie-summary').textContent()).toBe('Cancelled: nothing was saved');
    await page.waitForTimeout(300);
    expect(downloads).toEqual([]);
    await page.screenshot({ path: new URL('movie-dialog.png', RESULTS).pathname });
    await page.getByTestId('movie-close').click();
    // The view draws again at its own size.
    const canvas = await page.evaluate(() => {
      const c = document.querySelector('[data-testid=viewport] canvas') as HTMLCanvasElement;
      return { width: c.width, height: c.height, client: c.clientWidth * devicePixelRatio };
    });
    expect(canvas.width).toBe(Math.round(canvas.client));
  });

  it('refuses too big a movie with a message that says how to fit, and keeps Record off', async () => {
    await openMovieDialog();
    await choose({ format: 'gif', width: 1280, height: 720, fps: 25, seconds: 12, turntable: false });
    await expect.poll(() => page.getByTestId('movie-summary').textContent()).toMatch(/^An animated GIF of 300 frames at 1280 × 720 is 276\.5 million pixels; the most is 60 million/);
    expect(await page.getByTestId('movie-record').isDisabled()).toBe(true);
    await page.getByTestId('movie-close').click();
    expect(problems).toEqual([]);
  });
});

/** The foreground's left and right ends (pixels) along the row with most of it, and the colour a few pixels in from its left end. */
function filament(picture: Picture): { left: number; right: number; colour: [number, number, number] } {
  const mask = foregroundMask(picture);
  const { width, height, data } = picture;
  let row = 0;
  let most = -1;
  for (let y = 0; y < height; y++) {
    let n = 0;
    for (let x = 0; x < width; x++) n += mask[y * width + x];
    if (n > most) [row, most] = [y, n];
  }
  let [left, right] = [width, -1];
  for (let x = 0; x < width; x++) if (mask[row * width + x]) [left, right] = [Math.min(left, x), Math.max(right, x)];
  const i = 4 * (row * width + left + 4);
  return { left, right, colour: [data[i], data[i + 1], data[i + 2]] };
}

const colourDistance = (a: number[], b: number[]) => Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]);

/** Scrubs the timeline to `t` and waits for the timed plant derived at t (`modules` modules) on screen. */
async function scrubTimed(t: number, modules: number): Promise<void> {
  await page.getByTestId('timeline-slider').fill(String(t));
  await page.waitForFunction((n) => window.__meristem?.preview?.settled === true && window.__meristem.lastStats?.modules === n && window.__meristem.uploading?.() !== true, modules, { timeout: 30_000 });
  await twoFrames(page);
}

// Issue 45: a timed grammar is filmed as the timeline shows it, derived at each frame's t (not
// its whole plant's mesh grown on the GPU). ABOP 6.1's Anabaena (public/examples/abop-6.1-timed-
// anabaena.lsys): at t in [n, n + 1) the filament is the D0L-system's word n, its cells grown by
// their age, φ^(t + 1) long; worked by hand, word n starts with an a cell for odd n ≥ 3 (a_l a_l
// b_r …) and with a b cell for even n ≥ 2 (b_l a_r …), where the whole plant's (word 6) first
// cell is a b: a movie grown from the whole plant's mesh starts with a b at every t.
describe('the movie of a timed grammar', () => {
  it('films the plant derived at each frame’s t, as the timeline shows it, and puts the studio back', async () => {
    expect(await openExample(page, 'abop-6.1-timed-anabaena.lsys')).toBe('ok');
    await scrubTimed(3.5, 5);
    expect(await page.evaluate(() => window.__meristem!.growth!().span), 'a timed plant carries no growth arrays').toBeNull();
    expect(await page.evaluate(() => window.__meristem!.preview!.lastResult!.options.growth)).toBeUndefined();
    const studio = filament(await canvasPicture(page, 'movie-anabaena-studio-t3.5.png'));
    await scrubTimed(6, 21);
    await openMovieDialog();
    expect(await page.locator('#movie-range-note').textContent()).toBe('The plant grows from step 0 to 6.');
    const files = unzipSync(await movieFile({ format: 'png', width: 480, height: 200, fps: 10, seconds: 1.3, turntable: false }, /^13 frames · 1\.3 s · 480 × 200 · steps 0 to 6$/, 'timed-anabaena-filament-frames.zip'));
    const frames = Object.values(files).map((png) => filament(decodePng(Buffer.from(png))));
    expect(frames.length).toBe(13); // t = 0, 0.5, … 6
    const length = (t: number) => frames[2 * t].right - frames[2 * t].left;
    for (let k = 3; k < 13; k++) expect(length(k / 2), `the filament grows from t = ${(k - 1) / 2} to ${k / 2}`).toBeGreaterThan(length((k - 1) / 2));
    const phi = (1 + Math.sqrt(5)) / 2;
    for (const t of [4, 4.5, 5, 5.5, 6]) expect(length(t) / length(t - 1), `φ^(t + 1) long at t = ${t}`).toBeCloseTo(phi, 1);
    // The first cell: a at t = 3.5 and 5.5 (words 3 and 5), b at 2.5 and 4.5 (words 2 and 4).
    const first = (t: number) => frames[2 * t].colour;
    // (Colours 5 and 3 of the palette, two greens about 54 apart as drawn.)
    expect(colourDistance(first(3.5), first(5.5))).toBeLessThan(20);
    expect(colourDistance(first(2.5), first(4.5))).toBeLessThan(20);
    expect(colourDistance(first(3.5), first(4.5)), 'an a cell, then a b cell first').toBeGreaterThan(40);
    expect(colourDistance(first(3.5), studio.colour), 'as the timeline shows t = 3.5').toBeLessThan(20);
    // Back at the time the studio showed: the whole filament.
    await page.waitForFunction(() => window.__meristem?.preview?.settled === true && window.__meristem.lastStats?.modules === 21);
    await page.getByTestId('movie-close').click();
    expect(problems).toEqual([]);
  }, 180_000);

  it('cancels a timed movie at once, the studio back at its time', async () => {
    await scrubTimed(4.5, 8);
    await openMovieDialog();
    await choose({ format: 'webm', width: 320, height: 160, fps: 30, seconds: 30, turntable: false });
    await page.getByTestId('movie-record').click();
    await page.waitForFunction(() => Number((document.querySelector('[data-testid=movie-progress]') as HTMLProgressElement | null)?.value) >= 3);
    await page.getByTestId('movie-cancel').click();
    await expect.poll(() => page.getByTestId('movie-summary').textContent()).toBe('Cancelled: nothing was saved');
    await page.getByTestId('movie-close').click();
    // The filament derived at t = 4.5 again, as the timeline says.
    await page.waitForFunction(() => window.__meristem?.preview?.settled === true && window.__meristem.lastStats?.modules === 8 && window.__meristem.preview.lastResult?.options.time === 4.5);
    expect(await page.getByTestId('timeline-time').textContent()).toMatch(/^t 4\.50 of 6/);
    await scrubTimed(6, 21);
    expect(problems).toEqual([]);
  });

  it('fails with the reason when the plant cannot be derived at a frame’s t, saving nothing', async () => {
    // Whole at every whole t (each cell 0 old), a division by zero where a cell is half a step old.
    expect(await pasteText(page, '#terminal_age a 1\n#iterations 4\naxiom: a(0)\na(t) -> a(0) a(0)\nhomomorphism:\na(t) -> F(1 / (t - 0.5))\n')).toBe('ok');
    await openMovieDialog();
    await choose({ format: 'png', width: 160, height: 90, fps: 10, seconds: 0.9, turntable: false });
    const downloads: string[] = [];
    page.on('download', (d) => downloads.push(d.suggestedFilename()));
    await page.getByTestId('movie-record').click();
    await page.waitForFunction(() => document.querySelector('[data-testid=movie-summary]')?.getAttribute('data-state') === 'error', undefined, { timeout: 60_000 });
    expect(await page.getByTestId('movie-summary').textContent()).toMatch(/^The movie failed: the grammar has errors at t = 0\.5: division by zero/);
    expect(await page.getByTestId('movie-dialog').getAttribute('data-state')).toBe('idle');
    await page.getByTestId('movie-close').click();
    // The studio is back at its plant (the grammar's own iterations), without errors.
    await page.waitForFunction(() => window.__meristem?.preview?.settled === true && window.__meristem.preview.lastResult?.build.ok === true);
    expect(downloads).toEqual([]);
    // The page logs the movie's failure, and nothing else.
    const logged = problems.splice(0);
    expect(logged).toEqual([expect.stringMatching(/^console error: The movie failed: Error: the grammar has errors at t = 0\.5: division by zero/)]);
  });
});

describe('the movie dialog on a phone', () => {
  it('fits 375 px: no control is cut off', async () => {
    await page.setViewportSize({ width: 375, height: 740 });
    await openMovieDialog();
    const overflow = await page.evaluate(() =>
      [...document.querySelectorAll('[data-testid=movie-dialog] select, [data-testid=movie-dialog] input, [data-testid=movie-dialog] button')]
        .filter((e) => (e as HTMLElement).offsetParent !== null)
        .map((e) => ({ id: (e as HTMLElement).dataset.testid, right: e.getBoundingClientRect().right }))
        .filter((e) => e.right > 375),
    );
    await page.screenshot({ path: new URL('movie-dialog-phone.png', RESULTS).pathname });
    expect(overflow).toEqual([]);
    const dialog = await page.getByTestId('movie-dialog').evaluate((d) => ({ scroll: d.scrollWidth, client: d.clientWidth, right: d.getBoundingClientRect().right }));
    expect(dialog.scroll, 'nothing in the dialog is wider than it').toBeLessThanOrEqual(dialog.client);
    expect(dialog.right).toBeLessThanOrEqual(375);
    await page.getByTestId('movie-close').click();
  });
});
