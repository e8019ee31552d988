// VRML 2.0: every gallery example and the golden grammars, exported by the command-line tool, are
// read by tovrmlx3d (Castle Game Engine) with nothing on stderr and by three.js's VRMLLoader with
// no warning and every triangle; every coordIndex names a point that exists (neither tool checks
// that); and view3dscene, under Xvfb, draws the small ones from their Viewpoint on white.
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import { basename, join } from 'node:path';
import { LineSegments, Mesh, type BufferGeometry, type Object3D } from 'three';
import { VRMLLoader } from 'three/examples/jsm/loaders/VRMLLoader.js';
import { afterAll, afterEach, describe, expect, it, vi } from 'vitest';
import { exportWithCli, galleryDir, galleryExamples, goldenDir, goldenNames, runTool, keepPicture, removeScratch, scratchDir, statsOf } from './tools';

const dir = scratchDir('vrml');
afterAll(() => removeScratch(dir));

/** What a VRML file holds according to its coordIndex lists. */
interface IndexCheck {
  points: number;
  /** Faces (or lines) per index list, in order. */
  primitives: number[];
  /** Problems found: an index out of range, a face that is not a triangle (or a line of two). */
  problems: string[];
}

/** The numbers between `keyword [` and the `]` that closes it. */
function numbersAfter(text: string, from: number): { values: number[]; end: number } {
  const open = text.indexOf('[', from);
  const close = text.indexOf(']', open);
  const body = text.slice(open + 1, close).trim();
  return { values: body === '' ? [] : body.split(/[\s,]+/).filter((t) => t !== '').map(Number), end: close };
}

/**
 * Reads the shared `Coordinate` point list and checks every `coordIndex` list against it: each
 * index an integer in range, each face ended by -1 after exactly `arity` indices.
 */
export function checkCoordIndex(text: string, arity: number): IndexCheck {
  const problems: string[] = [];
  const pointAt = text.indexOf('point [');
  const points = pointAt < 0 ? 0 : numbersAfter(text, pointAt).values.length / 3;
  if (!Number.isInteger(points)) problems.push('the point list does not hold whole triples');
  const primitives: number[] = [];
  let at = text.indexOf('coordIndex [');
  while (at >= 0) {
    const { values, end } = numbersAfter(text, at);
    let face = 0;
    let count = 0;
    for (const value of values) {
      if (value === -1) {
        if (face !== arity) problems.push(`a face of ${face} indices in list ${primitives.length}`);
        face = 0;
        count++;
      } else if (!Number.isInteger(value) || value < 0 || value >= points) {
        problems.push(`index ${value} out of range (${points} points) in list ${primitives.length}`);
      } else face++;
    }
    if (face !== 0) problems.push(`list ${primitives.length} does not end with -1`);
    primitives.push(count);
    at = text.indexOf('coordIndex [', end);
  }
  return { points, primitives, problems };
}

/** Parses with three's VRMLLoader; returns the triangles and line segments of the plant's shapes. */
function loadWithThree(text: string): { triangles: number; lines: number } {
  const scene = new VRMLLoader().parse(text, '');
  let triangles = 0;
  let lines = 0;
  const count = (geometry: BufferGeometry) => geometry.index?.count ?? geometry.getAttribute('position').count;
  scene.traverse((object: Object3D) => {
    if (object.parent?.renderOrder === -Infinity) return; // the Background's sky sphere
    if (object instanceof Mesh) triangles += count(object.geometry) / 3;
    if (object instanceof LineSegments) lines += count(object.geometry) / 2;
  });
  return { triangles, lines };
}

function tovrmlx3d(path: string): { status: number | null; stderr: string } {
  return runTool('tovrmlx3d', [path, '--encoding', 'xml'], { discardStdout: true });
}

afterEach(() => {
  vi.restoreAllMocks();
});

describe('VRML from the command-line tool', () => {
  it.each(galleryExamples())('%s: tovrmlx3d and VRMLLoader read it, every coordIndex in range', (name) => {
    const grammar = join(galleryDir, name);
    const path = join(dir, `${name}.wrl`);
    const text = exportWithCli(grammar, path).toString('utf8');
    const stats = statsOf(grammar);
    expect(text.startsWith('#VRML V2.0 utf8\n')).toBe(true);

    const indices = checkCoordIndex(text, 3);
    expect(indices.problems.slice(0, 5)).toEqual([]);
    expect(indices.points).toBe(stats.vertices);
    expect(indices.primitives.reduce((a, b) => a + b, 0)).toBe(stats.triangles);

    const converted = tovrmlx3d(path);
    expect(converted.stderr).toBe('');
    expect(converted.status).toBe(0);

    const warn = vi.spyOn(console, 'warn').mockImplementation(() => undefined);
    expect(loadWithThree(text).triangles).toBe(stats.triangles);
    expect(warn.mock.calls).toEqual([]);
  });

  it.each(goldenNames())('golden %s.wrl: read by both, in range', (name) => {
    const path = join(goldenDir, `${name}.wrl`);
    const text = readFileSync(path, 'utf8');
    const lines = name.endsWith('-lines');
    expect(checkCoordIndex(text, lines ? 2 : 3).problems).toEqual([]);
    expect(tovrmlx3d(path)).toMatchObject({ status: 0, stderr: '' });
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => undefined);
    const read = loadWithThree(text);
    expect(lines ? read.lines : read.triangles).toBeGreaterThan(0);
    expect(warn.mock.calls).toEqual([]);
  });

  it('the checks can fail: an index out of range, a stray field', () => {
    const good = readFileSync(join(goldenDir, 'leafy-3d.wrl'), 'utf8');
    const outOfRange = good.replace(/coordIndex \[\n\s+(\d+)/, 'coordIndex [\n      99999');
    expect(checkCoordIndex(outOfRange, 3).problems[0]).toMatch(/^index 99999 out of range/);
    const strayField = good.replace('WorldInfo {', 'WorldInfo { colour 1');
    const path = join(dir, 'stray-field.wrl');
    writeFileSync(path, strayField);
    expect(tovrmlx3d(path).stderr).not.toBe('');
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => undefined);
    loadWithThree(good.replace('diffuseColor', 'diffuseColour'));
    expect(warn).toHaveBeenCalled();
  });
});

/** Examples small enough to render with view3dscene (about a second each). */
const SMALL_VERTICES = 20_000;
/**
 * A picture "is not blank" with this many plant pixels (a blank one has none). Thin plants are a
 * few pixels at 320 × 240: the stem of ABOP 1.8's signal plant is under a pixel wide and drops out.
 */
const MIN_PLANT_PIXELS = 20;

/** Renders a VRML file with view3dscene under Xvfb; returns the plant's pixels (not white). */
function view3dscene(path: string, png: string): number {
  const run = runTool('xvfb-run', ['-a', '-s', '-screen 0 640x480x24', 'view3dscene', path, '--geometry', '320x240', '--screenshot', '0', png], {
    discardStdout: true,
  });
  expect(run.status, run.stderr).toBe(0);
  expect(existsSync(png), `view3dscene wrote no ${png}`).toBe(true);
  keepPicture(png, `view3dscene-${basename(png).replace(/^view-/, '').replace(/\.lsys\.png$/, '.png')}`);
  const picture = PNG.sync.read(readFileSync(png));
  expect([picture.width, picture.height]).toEqual([320, 240]);
  let plant = 0;
  for (let i = 0; i < picture.data.length; i += 4) {
    if (765 - picture.data[i] - picture.data[i + 1] - picture.data[i + 2] > 30) plant++;
  }
  return plant;
}

describe('view3dscene draws the exported VRML from its Viewpoint', () => {
  const small = galleryExamples().filter((name) => statsOf(join(galleryDir, name)).vertices <= SMALL_VERTICES);

  it.each(small)('%s: a picture with the plant on white', (name) => {
    const path = join(dir, `view-${name}.wrl`);
    exportWithCli(join(galleryDir, name), path);
    expect(view3dscene(path, join(dir, `view-${name}.png`))).toBeGreaterThanOrEqual(MIN_PLANT_PIXELS);
  });

  it.each(goldenNames())('golden %s.wrl: a picture with the plant on white', (name) => {
    expect(view3dscene(join(goldenDir, `${name}.wrl`), join(dir, `golden-${name}.png`))).toBeGreaterThanOrEqual(MIN_PLANT_PIXELS);
  });

  it('the pixel check can fail: a file with no shape is blank', () => {
    const text = readFileSync(join(goldenDir, 'leafy-3d.wrl'), 'utf8');
    const path = join(dir, 'no-shape.wrl');
    writeFileSync(path, text.slice(0, text.indexOf('# colour index')));
    expect(view3dscene(path, join(dir, 'no-shape.png'))).toBe(0);
  });
});
