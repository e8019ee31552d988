// Cross-boundary tests of the importers: the TypeScript facade over the REAL WebAssembly core,
// compared with the command-line tool built from the same Rust code.
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { buildPlant, importGrammar, initCore } from '../../web/src/core';

const repoRoot = fileURLToPath(new URL('../..', import.meta.url));
const input = (relative: string) => `crate/tests/import/${relative}`;

beforeAll(async () => {
  await initCore(readFileSync(new URL('../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));
});

/** What `meristem import FILE` prints: the text on stdout, the notes as `FILE:LINE: note: …` on stderr. */
function cli(relative: string): { text: string; notes: string[] } {
  const run = spawnSync(
    'cargo',
    ['run', '--quiet', '--release', '--manifest-path', 'crate/Cargo.toml', '--bin', 'meristem', '--', 'import', input(relative)],
    { cwd: repoRoot, encoding: 'utf8' },
  );
  expect(run.status).toBe(0);
  return { text: run.stdout, notes: run.stderr.split('\n').filter((l) => l.includes(': note: ')) };
}

describe('importGrammar', () => {
  it('imports an Lparser file as the CLI does, notes and all', () => {
    const relative = 'lparser/abop-monopodial-tree.ls';
    const source = readFileSync(new URL(`../../${input(relative)}`, import.meta.url), 'utf8');
    const imported = importGrammar(source, 'abop-monopodial-tree.ls');
    expect(imported.dialect).toBe('lparser');
    const fromCli = cli(relative);
    expect(imported.text).toBe(fromCli.text);
    expect(fromCli.notes.map((n) => n.replace(/^.*\.ls:/, ''))).toEqual(imported.notes.map((n) => `${n.line}: note: ${n.message}`));
    expect(imported.notes.map((n) => n.line)).toEqual([15, 20, 23]);
    expect(imported.notes[2].message).toContain("'~' without a value");
    // The translation builds in the studio's pipeline without a diagnostic.
    const plant = buildPlant(imported.text);
    expect([...plant.diagnostics]).toEqual([]);
    expect(plant.stats.segments).toBeGreaterThan(0);
  }, 300_000); // the first run compiles the release CLI

  it('tells the dialect from the content, or takes it by name', () => {
    const green = readFileSync(new URL(`../../${input('green/worked-example.txt')}`, import.meta.url), 'utf8');
    const imported = importGrammar(green, 'example.txt');
    expect(imported.dialect).toBe('green');
    expect(imported.text).toContain('#random p = uniform(0,1)');
    expect(buildPlant(imported.text, { seed: 3 }).derived).toBe('A(2)B(6)[A(3)]B(4)');
    expect(importGrammar('Axiom: F\nF --> FF\n', 'lpy').dialect).toBe('lpy');
    const lpy = importGrammar('R = 1.5\nAxiom: A(1)\nproduction:\nA(s) --> F(s)A(s/R)\n', 'tree.lpy');
    expect(lpy.text).toContain('#define R 1.5');
    expect(lpy.notes).toEqual([]);
  });

  it('reports what it cannot read instead of throwing', () => {
    const unknown = importGrammar('axiom: F\n', 'plant.txt');
    expect(unknown).toEqual({
      text: '',
      notes: [{ line: 0, message: expect.stringContaining('cannot tell which dialect') }],
      dialect: null,
    });
    const broken = importGrammar('Lsystem: 1\nAxiom: A\nA --> B(frob(1))\n', 'x.l');
    expect(broken.dialect).toBe('cpfg');
    expect(broken.notes).toEqual([{ line: 3, message: expect.stringContaining("unknown function 'frob'") }]);
    expect([...buildPlant(broken.text).diagnostics].filter((d) => d.severity === 'error')).toEqual([]);
  });
});
