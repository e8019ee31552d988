import { describe, expect, it } from 'vitest';
import { exportModel } from '../../core';
import { parseStageSvg, stagesSvg } from './stages-svg';
import { figureName } from '../files';
import { stagesOf } from './stages';

const PLANT = '#angle 20\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF\n';
const svgOf = (iterations: number) => new TextDecoder().decode(exportModel(PLANT, 'svg', { iterations }).bytes);

describe('the Stages figure as SVG', () => {
  it("reads the core's SVG: its viewBox and drawing, without title and description", () => {
    const parsed = parseStageSvg(svgOf(2))!;
    expect(parsed.viewBox).toHaveLength(4);
    expect(parsed.viewBox[3]).toBeGreaterThan(0);
    expect(parsed.body).toContain('<path');
    expect(parsed.body).not.toContain('<title>');
    expect(parseStageSvg('<svg>no box</svg>')).toBeNull();
  });

  it('puts each plant in its column at one scale, standing on the baseline, with its caption', () => {
    const drawings = [1, 2, 3].map((n) => ({ svg: svgOf(n), caption: `n = ${n}` }));
    const svg = stagesSvg(drawings, 3, 1, 'plant: stages');
    // One root element, its drawings wrapped whole (every <g> opened is closed, none nested wrongly).
    expect(svg.match(/<svg\b/g)).toHaveLength(1);
    expect(svg.match(/<g\b/g)!.length).toBe(svg.match(/<\/g>/g)!.length);
    const [, , width, height] = /viewBox="([^"]+)"/.exec(svg)![1].split(' ').map(Number);
    const groups = [...svg.matchAll(/<g transform="translate\(([-\d.e]+) ([-\d.e]+)\)">/g)];
    expect(groups).toHaveLength(3);
    const texts = [...svg.matchAll(/<text [^>]*>([^<]*)<\/text>/g)].map((t) => t[1]);
    expect(texts).toEqual(['n = 1', 'n = 2', 'n = 3']);
    // Translations only: the plants keep the core's scale, so the tallest (n = 3) sets the rows.
    const boxes = drawings.map((d) => parseStageSvg(d.svg)!.viewBox);
    const tile = width / 3;
    groups.forEach((g, i) => {
      const [tx, ty] = [Number(g[1]), Number(g[2])];
      const [x, y, w, h] = boxes[i];
      expect(tx + x + w / 2, 'centred in its column').toBeCloseTo(tile * (i + 0.5), 3);
      expect(ty + y + h, 'on the common baseline').toBeCloseTo(boxes[2][3] * 1.04, 3);
    });
    expect(height).toBeGreaterThan(boxes[2][3]);
  });

  it('draws no stroke thinner than a pixel of the figure', () => {
    const svg = stagesSvg([1, 5].map((n) => ({ svg: svgOf(n), caption: `n = ${n}` })), 2, 1, 'x');
    const [, , width, height] = /viewBox="([^"]+)"/.exec(svg)![1].split(' ').map(Number);
    const pixel = Math.max(width, height) / 1600;
    const widths = [...svg.matchAll(/stroke-width="([^"]+)"/g)].map((m) => Number(m[1]));
    expect(widths.length).toBeGreaterThan(0);
    for (const w of widths) expect(w).toBeGreaterThanOrEqual(pixel * 0.999);
  });

  it('draws every stroke of every stage at the line width asked for, in pixels of the figure, each stage fitted or not', () => {
    for (const fit of ['one', 'each'] as const) {
      const svg = stagesSvg([2, 5].map((n) => ({ svg: svgOf(n), caption: `n = ${n}` })), 2, 1, 'x', fit, 3);
      const [, , width, height] = /viewBox="([^"]+)"/.exec(svg)![1].split(' ').map(Number);
      const pixel = Math.max(width, height) / 1600;
      const groups = svg.split('<g transform=').slice(1);
      expect(groups).toHaveLength(2);
      for (const group of groups) {
        const k = Number(/^"[^"]*scale\(([\d.e-]+)\)/.exec(group)?.[1] ?? 1);
        const widths = [...group.matchAll(/stroke-width="([^"]+)"/g)].map((m) => (Number(m[1]) * k) / pixel);
        expect(widths.length).toBeGreaterThan(0);
        for (const w of widths) expect(w, `${fit}: 3 pixels`).toBeCloseTo(3, 2);
      }
    }
  });

  it('enlarges each drawing to fill its tile when asked', () => {
    const drawings = [1, 3].map((n) => ({ svg: svgOf(n), caption: `n = ${n}` }));
    const svg = stagesSvg(drawings, 2, 1, 'x', 'each');
    const [small, large] = drawings.map((d) => parseStageSvg(d.svg)!.viewBox);
    const k = Number(/scale\(([\d.e-]+)\)/.exec(svg)![1]);
    expect(k, 'n = 1 grows to the tile of n = 3').toBeCloseTo(Math.min(large[2] / small[2], large[3] / small[3]), 5);
    expect(svg.match(/scale\(/g), 'the largest keeps its size').toHaveLength(1);
  });

  it('leaves a tile with only its caption when a plant drew nothing', () => {
    const svg = stagesSvg([{ svg: null, caption: 'n = 0 (nothing drawn)' }, { svg: svgOf(1), caption: 'n = 1' }], 2, 1, 'x');
    expect(svg.match(/<g transform/g)).toHaveLength(1);
    expect(svg).toContain('n = 0 (nothing drawn)');
  });
});

describe('the stages a range asks for', () => {
  it('is a column per iteration, a row per seed', () => {
    const { stages, grid } = stagesOf(1, 3, [7, 8]);
    expect(grid).toEqual({ columns: 3, rows: 2, scale: 'one' });
    expect(stages.map((s) => [s.iterations, s.seed, s.caption])).toEqual([
      [1, 7, 'n = 1, seed 7'],
      [2, 7, 'n = 2, seed 7'],
      [3, 7, 'n = 3, seed 7'],
      [1, 8, 'n = 1, seed 8'],
      [2, 8, 'n = 2, seed 8'],
      [3, 8, 'n = 3, seed 8'],
    ]);
  });

  it('is a row of specimens for one iteration and several seeds (ABOP Fig. 1.27)', () => {
    const { stages, grid } = stagesOf(5, 5, [1, 2, 3]);
    expect(grid).toEqual({ columns: 3, rows: 1, scale: 'one' });
    expect(stages.map((s) => s.caption)).toEqual(['seed 1', 'seed 2', 'seed 3']);
  });

  it("keeps the grammar's own seed with one seed", () => {
    const { stages } = stagesOf(0, 1, [undefined]);
    expect(stages.map((s) => [s.seed, s.caption])).toEqual([
      [undefined, 'n = 0'],
      [undefined, 'n = 1'],
    ]);
  });

  it('names the files after the grammar opened', () => {
    expect(figureName('abop-1.24d.lsys')).toBe('abop-1.24d');
    expect(figureName('file/my tree.ls')).toBe('my-tree');
    expect(figureName('saved/123')).toBe('plant');
    expect(figureName('')).toBe('plant');
  });

  it('names the files after the grammar’s title first', () => {
    expect(figureName('abop-1.24d.lsys', '// ABOP Fig 1.24d: a plant by node rewriting\naxiom: X')).toBe('abop-1.24d');
    expect(figureName('saved/7', '// Barnsley fern\n#angle 25')).toBe('barnsley-fern');
    expect(figureName('saved/7', '// ABOP Fig. 1.10b: Sierpinski gasket')).toBe('abop-1.10b');
    expect(figureName('file/x.lsys', '  // Mon arbre préféré!  \naxiom: F')).toBe('mon-arbre-préféré');
    expect(figureName('file/x.lsys', '//  :\naxiom: F'), 'an empty title: the file').toBe('x');
    expect(figureName('file/x.lsys', 'axiom: F\n// later'), 'a comment not at the top is no title').toBe('x');
    expect(figureName('saved/1', '// ../../etc/passwd')).toBe('etc-passwd');
    expect(figureName('saved/1', '// ' + 'a'.repeat(100)).length).toBe(48);
  });
});
