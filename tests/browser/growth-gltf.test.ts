// End-to-end (issue 45, "done when"): the studio's animated glTF of a growing plant, downloaded
// from the Download menu as a user would, is valid by the Khronos validator and played by three.js
// in the page: a page of its own beside the studio (three.js and its GLTFLoader served from the
// project's three, the version the studio bundles; the studio's first load carries neither)
// loads the file with GLTFLoader, plays its clip with an AnimationMixer, and the plant's bounding
// box grows over the clip, from a small part of the plant to the whole plant's box (the still glTF
// the same menu writes); two frames drawn by WebGL at two times of the clip show a plant, and differ.
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, posix } from 'node:path';
import { fileURLToPath } from 'node:url';
import { validateBytes } from 'gltf-validator';
import { chromium, type Browser, type Download, type Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { decodePng } from './pictures';
import { generation, nextBuild, openExample, openStudio, RESULTS } from './studio-page';

/** A 3D plant with leaves and both textures, small enough for a quick file. */
const EXAMPLE = 'abop-1.25-bush.lsys';
const ITERATIONS = 3;
const THREE_DIR = dirname(fileURLToPath(import.meta.resolve('three'))).replace(/\/build$/, '');
/** Where the player page and three.js's files are served (routed by the test, not the site's server). */
const PLAYER = '__gltf-player.html';
const THREE_PATH = '__three__/';

/** The player page's module: `window.playGlb(animated, still)` (base64 GLBs) plays the first and measures. */
const PLAYER_SCRIPT = `
import * as THREE from './${THREE_PATH}build/three.module.js';
import { GLTFLoader } from './${THREE_PATH}examples/jsm/loaders/GLTFLoader.js';
const bytes = (base64) => Uint8Array.from(atob(base64), (c) => c.charCodeAt(0)).buffer;
const SIZE = 256;
window.playGlb = async (animatedBase64, stillBase64) => {
  const loader = new GLTFLoader();
  const gltf = await loader.parseAsync(bytes(animatedBase64), '');
  const still = await loader.parseAsync(bytes(stillBase64), '');
  const [clip] = gltf.animations;
  const mixer = new THREE.AnimationMixer(gltf.scene);
  const action = mixer.clipAction(clip);
  action.setLoop(THREE.LoopOnce, 1);
  action.clampWhenFinished = true;
  action.play();
  // (A clip played to its end stays paused there: each time is played from the start again.)
  const at = (seconds) => {
    action.reset();
    mixer.setTime(seconds);
  };
  const boxAt = (seconds) => {
    at(seconds);
    gltf.scene.updateMatrixWorld(true);
    const box = new THREE.Box3().setFromObject(gltf.scene, true);
    return [...box.min.toArray(), ...box.max.toArray()];
  };
  const times = Array.from({ length: 9 }, (_, k) => (k / 8) * clip.duration);
  const boxes = times.map(boxAt);
  still.scene.updateMatrixWorld(true);
  const whole = new THREE.Box3().setFromObject(still.scene, true);
  let morphed = 0;
  gltf.scene.traverse((o) => { if (o.isMesh && o.morphTargetInfluences) morphed += 1; });

  const renderer = new THREE.WebGLRenderer({ preserveDrawingBuffer: true });
  renderer.setSize(SIZE, SIZE, false);
  document.body.append(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x555555, 2.5), gltf.scene);
  const centre = whole.getCenter(new THREE.Vector3());
  const radius = whole.getBoundingSphere(new THREE.Sphere()).radius;
  const camera = new THREE.PerspectiveCamera(40, 1, radius / 100, radius * 10);
  camera.position.copy(centre).add(new THREE.Vector3(0, 0, radius * 3));
  camera.lookAt(centre);
  const gl = renderer.getContext();
  const frameAt = (seconds) => {
    at(seconds);
    renderer.render(scene, camera);
    const pixels = new Uint8Array(SIZE * SIZE * 4);
    gl.readPixels(0, 0, SIZE, SIZE, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    return { pixels, png: renderer.domElement.toDataURL('image/png') };
  };
  const early = frameAt(0.7 * clip.duration);
  const late = frameAt(clip.duration);
  const plant = (p) => { let n = 0; for (let i = 0; i < p.length; i += 4) if (p[i] + p[i + 1] + p[i + 2] < 720) n += 1; return n; };
  let differing = 0;
  for (let i = 0; i < early.pixels.length; i += 4) {
    const d = Math.abs(early.pixels[i] - late.pixels[i]) + Math.abs(early.pixels[i + 1] - late.pixels[i + 1]) + Math.abs(early.pixels[i + 2] - late.pixels[i + 2]);
    if (d > 30) differing += 1;
  }
  return {
    clips: gltf.animations.map((a) => a.name),
    duration: clip.duration,
    morphed,
    times,
    boxes,
    whole: [...whole.min.toArray(), ...whole.max.toArray()],
    pixels: SIZE * SIZE,
    plantEarly: plant(early.pixels),
    plantLate: plant(late.pixels),
    differing,
    pngs: [early.png, late.png],
  };
};
window.playerReady = true;
`;

let browser: Browser;
let studio: Page;
let problems: string[];

beforeAll(async () => {
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
  ({ page: studio, problems } = await openStudio(browser));
  expect(await openExample(studio, EXAMPLE)).toBe('ok');
  const before = await generation(studio);
  await studio.getByTestId('iterations').fill(String(ITERATIONS));
  await nextBuild(studio, before);
});

afterAll(async () => {
  await browser?.close();
});

/** Clicks a download of the Download menu and returns the file's bytes. */
async function downloaded(testId: string): Promise<Buffer> {
  const menu = studio.getByTestId('downloads');
  if (!(await menu.evaluate((m) => (m as HTMLDetailsElement).open))) await menu.locator('summary').click();
  const [download]: [Download, unknown] = await Promise.all([studio.waitForEvent('download'), studio.getByTestId(testId).click()]);
  return readFileSync(await download.path());
}

/** A page beside the studio that plays GLBs with three.js (see PLAYER_SCRIPT). */
async function playerPage(): Promise<Page> {
  const page = await browser.newPage({ viewport: { width: 400, height: 400 } });
  const base = inject('studioUrl');
  await page.route(`${base}${PLAYER}`, (route) =>
    route.fulfill({ contentType: 'text/html', body: `<!doctype html><html><head><link rel="icon" href="data:,"></head><body><script type="module">${PLAYER_SCRIPT}</script></body></html>` }),
  );
  await page.route(`${base}${THREE_PATH}**`, (route) => {
    const file = new URL(route.request().url()).pathname.split(`/${THREE_PATH}`)[1];
    if (!/^(build|examples\/jsm)\/[\w/.-]+\.js$/.test(file) || file.includes('..')) return route.fulfill({ status: 404 });
    // three's examples import 'three': the build beside them.
    const toBuild = posix.relative(posix.dirname(file), 'build/three.module.js');
    const body = readFileSync(`${THREE_DIR}/${file}`, 'utf8').replace(/from\s+'three'/g, `from './${toBuild}'`);
    return route.fulfill({ contentType: 'text/javascript', body });
  });
  await page.goto(`${base}${PLAYER}`);
  await page.waitForFunction(() => (window as unknown as { playerReady?: boolean }).playerReady === true);
  return page;
}

interface Played {
  clips: string[];
  duration: number;
  morphed: number;
  times: number[];
  boxes: number[][];
  whole: number[];
  pixels: number;
  plantEarly: number;
  plantLate: number;
  differing: number;
  pngs: string[];
}

describe('the animated glTF of the growth, played by three.js in the page', () => {
  it(`${EXAMPLE}, n = ${ITERATIONS}: valid, and the plant's box grows over the clip to the whole plant's`, async () => {
    const animated = await downloaded('download-glb-growth');
    const still = await downloaded('download-glb');
    const report = await validateBytes(new Uint8Array(animated));
    expect(report.issues.messages).toEqual([]);
    expect(report.issues.numErrors).toBe(0);

    const player = await playerPage();
    const pageProblems: string[] = [];
    player.on('pageerror', (error) => pageProblems.push(error.message));
    player.on('console', (message) => message.type() === 'error' && pageProblems.push(message.text()));
    const played = await player.evaluate(
      ([a, s]) => (window as unknown as { playGlb: (a: string, s: string) => Promise<Played> }).playGlb(a, s),
      [animated.toString('base64'), still.toString('base64')],
    );
    played.pngs.forEach((png, k) => writeFileSync(new URL(`growth-gltf-${k === 0 ? 'early' : 'late'}.png`, RESULTS), Buffer.from(png.split(',')[1], 'base64')));

    expect(played.clips).toEqual(['growth']);
    expect(played.duration, '1 s a step').toBeCloseTo(ITERATIONS, 5);
    expect(played.morphed).toBeGreaterThan(0);
    const height = (box: number[]) => box[4] - box[1];
    const extent = (box: number[]) => Math.hypot(box[3] - box[0], box[4] - box[1], box[5] - box[2]);
    const whole = played.whole;
    for (let k = 1; k < played.boxes.length; k++) {
      expect(height(played.boxes[k]), `the height at ${played.times[k]} s`).toBeGreaterThanOrEqual(height(played.boxes[k - 1]) - 1e-4);
      expect(extent(played.boxes[k]), `the box at ${played.times[k]} s`).toBeGreaterThanOrEqual(extent(played.boxes[k - 1]) - 1e-4);
    }
    expect(height(played.boxes[0]), 'the clip starts small').toBeLessThan(0.5 * height(whole));
    const end = played.boxes[played.boxes.length - 1];
    const tolerance = 1e-3 * extent(whole);
    end.forEach((v, k) => expect(Math.abs(v - whole[k]), `corner ${k} of the box at the clip's end`).toBeLessThan(tolerance));

    // The frames WebGL drew: a plant in each (not a blank canvas), more of it later, and they differ.
    expect(played.plantEarly / played.pixels).toBeGreaterThan(0.002);
    expect(played.plantLate).toBeGreaterThan(played.plantEarly * 1.2);
    expect(played.differing / played.pixels).toBeGreaterThan(0.01);
    const late = decodePng(Buffer.from(played.pngs[1].split(',')[1], 'base64'));
    expect([late.width, late.height]).toEqual([256, 256]);
    expect(pageProblems).toEqual([]);
    expect(problems).toEqual([]);
  });
});
