// POV-Ray: the small gallery examples and the golden grammars, exported by the command-line tool,
// render with POV-Ray 3.7 without a parse warning to a picture that shows a plant, framed whole.
import { copyFileSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import { afterAll, describe, expect, it } from 'vitest';
import { exportWithCli, galleryDir, galleryExamples, goldenDir, goldenNames, runTool, keepPicture, removeScratch, scratchDir, statsOf } from './tools';

/** "Small" examples, the ones rendered: up to this many mesh vertices (a second or so each). */
const SMALL_VERTICES = 50_000;
const WIDTH = 320;
const HEIGHT = 240;
/** A picture "is not blank" with at least this many plant pixels (a blank one has none). */
const MIN_PLANT_PIXELS = 20;

const dir = scratchDir('pov');
afterAll(() => removeScratch(dir));

interface Render {
  /** Pixels clearly not the white background. */
  plantPixels: number;
  /** Plant pixels on the picture's outermost rows and columns (0 when the plant is framed whole). */
  onBorder: number;
}

/** Renders `name.pov` in the scratch folder (POV-Ray may write there) and measures the picture. */
function render(name: string): Render {
  const run = runTool('povray', [`+I${name}.pov`, `+O${name}.png`, `+W${WIDTH}`, `+H${HEIGHT}`, '-D', '+A0.3'], { cwd: dir });
  expect(run.status, run.stderr).toBe(0);
  expect(run.stderr).not.toMatch(/Parse (Warning|Error)|Possible Parse Error/);
  keepPicture(join(dir, `${name}.png`), `pov-${name.replace(/\.lsys$/, '')}.png`);
  const png = PNG.sync.read(readFileSync(join(dir, `${name}.png`)));
  expect([png.width, png.height]).toEqual([WIDTH, HEIGHT]);
  let plant = 0;
  let onBorder = 0;
  for (let y = 0; y < png.height; y++)
    for (let x = 0; x < png.width; x++) {
      const i = 4 * (y * png.width + x);
      const distance = 765 - png.data[i] - png.data[i + 1] - png.data[i + 2];
      if (distance <= 30) continue;
      plant++;
      if (x === 0 || y === 0 || x === png.width - 1 || y === png.height - 1) onBorder++;
    }
  return { plantPixels: plant, onBorder };
}

const small = galleryExamples().filter((name) => statsOf(join(galleryDir, name)).vertices <= SMALL_VERTICES);

describe('POV-Ray renders the exported scenes', () => {
  it('has small examples to render', () => {
    expect(small.length).toBeGreaterThanOrEqual(15);
  });

  it.each(small)('%s: a picture of the whole plant on white', (name) => {
    exportWithCli(join(galleryDir, name), join(dir, `${name}.pov`));
    const picture = render(name);
    // Thin plants are a few pixels wide at this size (a ray tracer can miss a sub-pixel stem).
    expect(picture.plantPixels, 'plant pixels').toBeGreaterThanOrEqual(MIN_PLANT_PIXELS);
    expect(picture.onBorder, 'plant pixels on the border: the camera cuts the plant').toBe(0);
  });

  it.each(goldenNames())('golden %s.pov', (name) => {
    copyFileSync(join(goldenDir, `${name}.pov`), join(dir, `golden-${name}.pov`));
    const picture = render(`golden-${name}`);
    expect(picture.plantPixels).toBeGreaterThanOrEqual(MIN_PLANT_PIXELS);
    expect(picture.onBorder).toBe(0);
  });

  it('draws a leaf: a polygon leaf fills its outline with the leaf image, not its cut-out', () => {
    // ABOP's leaf outline, face-on: its polygon keeps its whole outline (the image's opaque band);
    // with POV-Ray's use_alpha read the wrong way round, only the corners outside that band showed.
    const grammar = join(dir, 'leaf.lsys');
    writeFileSync(grammar, '#angle 30\naxiom: !(0.2)F(0.2){-f+f+f-|-f+f+f}\n');
    exportWithCli(grammar, join(dir, 'leaf.pov'));
    const picture = render('leaf');
    expect(picture.onBorder).toBe(0);
    // The leaf is about a fifth of the picture (a blank one, or one of corners only, under 1 %).
    expect(picture.plantPixels / (WIDTH * HEIGHT)).toBeGreaterThan(0.08);
  });

  it('the pixel check can fail: a scene without the plant is blank', () => {
    const scene = readFileSync(join(goldenDir, 'leafy-3d.pov'), 'utf8');
    const withoutPlant = scene.replace('object { Meristem_Plant double_illuminate }', '');
    expect(withoutPlant).not.toBe(scene);
    writeFileSync(join(dir, 'no-plant.pov'), withoutPlant);
    expect(render('no-plant').plantPixels).toBe(0);
  });
});
