// The studio's downloads are the command-line tool's files: the TypeScript facade over the real
// WebAssembly core (`exportModel`, what the Download menu calls) gives byte for byte what
// `meristem export` writes, for the same grammar, iterations, seed and view options (sides, smooth
// axes); OBJ comes as a zip whose entries are the tool's OBJ and MTL.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { unzipSync } from 'fflate';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { exportModel, initIo, MODEL_FORMATS, type ModelFormat } from '../../web/src/core';
import { exportWithCli, galleryDir, repoRoot, removeScratch, scratchDir } from './tools';

const dir = scratchDir('wasm');
afterAll(() => removeScratch(dir));

beforeAll(async () => {
  await initIo(readFileSync(join(repoRoot, 'crate/pkg/meristem_bg.wasm')));
});

/** Grammars and the options both sides get. */
const CASES: { example: string; iterations?: number; seed?: number; sides?: number; smoothAll?: boolean }[] = [
  { example: 'abop-1.24d.lsys' },
  { example: 'abop-1.25-bush.lsys', iterations: 4 },
  { example: 'abop-1.27-stochastic.lsys', iterations: 4, seed: 7 },
  { example: 'abop-2.06a-monopodial.lsys', iterations: 6, sides: 9, smoothAll: true },
];

describe('exportModel (wasm) against meristem export (native)', () => {
  for (const { example, iterations, seed, sides, smoothAll } of CASES) {
    const grammar = join(galleryDir, example);
    const cliOptions = [
      ...(iterations === undefined ? [] : ['--iterations', String(iterations)]),
      ...(seed === undefined ? [] : ['--seed', String(seed)]),
      ...(sides === undefined ? [] : ['--sides', String(sides)]),
      ...(smoothAll ? ['--smooth-all'] : []),
    ];
    it.each(MODEL_FORMATS.map((f) => f.format))(`${example} ${cliOptions.join(' ')}: %s, the same bytes`, (format: ModelFormat) => {
      const file = exportModel(readFileSync(grammar, 'utf8'), format, { name: 'plant', iterations, seed, sides, smoothAll });
      const cli = exportWithCli(grammar, join(dir, `plant.${format}`), cliOptions);
      if (format === 'obj') {
        expect([file.fileName, file.mimeType]).toEqual(['plant-obj.zip', 'application/zip']);
        const entries = unzipSync(file.bytes);
        expect(Object.keys(entries)).toEqual(['plant.obj', 'plant.mtl']);
        expect(Buffer.from(entries['plant.obj']).equals(cli)).toBe(true);
        expect(Buffer.from(entries['plant.mtl']).equals(readFileSync(join(dir, 'plant.mtl')))).toBe(true);
      } else if (format === 'pov') {
        // The scene and the texture images it names, written by the CLI beside it.
        expect([file.fileName, file.mimeType]).toEqual(['plant-pov.zip', 'application/zip']);
        const entries = unzipSync(file.bytes);
        const names = Object.keys(entries);
        expect(names[0]).toBe('plant.pov');
        expect(names.length).toBeGreaterThan(1);
        expect(Buffer.from(entries['plant.pov']).equals(cli)).toBe(true);
        for (const name of names.slice(1)) {
          expect(['bark.png', 'leaf.png']).toContain(name);
          expect(Buffer.from(entries[name]).equals(readFileSync(join(dir, name)))).toBe(true);
        }
      } else {
        expect(file.fileName).toBe(`plant.${format}`);
        expect(file.bytes.length).toBe(cli.length);
        expect(Buffer.from(file.bytes).equals(cli)).toBe(true);
      }
    });
  }

  it('another seed gives another plant (the seed reaches the core)', () => {
    const source = readFileSync(join(galleryDir, 'abop-1.27-stochastic.lsys'), 'utf8');
    const a = exportModel(source, 'glb', { seed: 7 }).bytes;
    const b = exportModel(source, 'glb', { seed: 8 }).bytes;
    expect(Buffer.from(a).equals(Buffer.from(b))).toBe(false);
  });

  it('throws on a grammar with errors and on an unknown format', () => {
    expect(() => exportModel('axiom: F[\n', 'wrl')).toThrow(/the grammar has errors/);
    expect(() => exportModel('axiom: F\n', 'stl' as ModelFormat)).toThrow(/unknown format 'stl'; the formats are wrl, glb, pov, obj, iv, svg/);
  });
});
