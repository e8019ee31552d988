// The WebAssembly boundary's less-used doors called as a careless script would (issue 50,
// "Nothing breaks, everywhere"), through the REAL core in Node: the files of importObject,
// pythonMain and importDerived whose names, bytes and lengths disagree, and the growth
// animation's settings out of range in exportModel. Each gives a note or an Error in words, never
// a file cut short, dropped or written invalid without one.
import { describe, expect, it } from 'vitest';
import { exportModel, importDerived, importObject, pythonMain } from '../../crate/pkg/meristem.js';

const CPFG = new TextEncoder().encode('Lsystem: 1\nderivation length: 2\nAxiom: F\nF --> F[+F]F\nendlsystem\n');
const LPY = new TextEncoder().encode('Axiom: F\nderivation length: 2\nproduction:\nF --> F[+F]F\nendlsystem\n');

interface Imported {
  text: string;
  notes: { line: number; message: string }[];
  dialect: string | null;
}

/** Names, bytes and lengths that disagree, each with what the note or Error says. */
const DISAGREEING: [string, string[], Uint8Array, number[], RegExp][] = [
  ['a name without a length', ['plant.l', 'plant.v'], CPFG, [CPFG.length], /2 names but 1 lengths/],
  ['a length without a name', ['plant.l'], CPFG, [CPFG.length, 5], /1 names but 2 lengths/],
  ['lengths past the bytes', ['plant.l'], CPFG, [CPFG.length + 100], new RegExp(`add up to ${CPFG.length + 100} bytes, but ${CPFG.length} bytes were given`)],
  ['a "negative" length', ['plant.l', 'b.l'], CPFG, [0xffffffff, 3], new RegExp(`add up to 4294967298 bytes, but ${CPFG.length}`)],
  ['lengths short of the bytes', ['plant.l'], CPFG, [3], new RegExp(`add up to 3 bytes, but ${CPFG.length}`)],
];

describe('files whose names, bytes and lengths disagree', () => {
  for (const [what, names, bytes, lengths, says] of DISAGREEING) {
    it(`${what}: importObject and importDerived give a note, pythonMain throws`, () => {
      // Before: the file cut at the bytes' end, or the extra name dropped, imported without a word.
      const imported = JSON.parse(importObject(names, bytes, new Uint32Array(lengths))) as Imported;
      expect(imported.text).toBe('');
      expect(imported.dialect).toBeNull();
      expect(imported.notes).toHaveLength(1);
      expect(imported.notes[0].message).toMatch(/^the files opened together do not agree: /);
      expect(imported.notes[0].message).toMatch(says);
      const derived = JSON.parse(importDerived('{}', 'plant.l', names, bytes, new Uint32Array(lengths), 0)) as Imported;
      expect(derived.text).toBe('');
      expect(derived.notes[0].message).toMatch(says);
      expect(() => pythonMain(names, bytes, new Uint32Array(lengths))).toThrow(says);
    });
  }

  it('agreeing files are read as before, empty names and no files alike', () => {
    const imported = JSON.parse(importObject(['plant.l'], CPFG, new Uint32Array([CPFG.length]))) as Imported;
    expect(imported.dialect).toBe('cpfg');
    expect(imported.text).toContain('axiom: F');
    const two = new Uint8Array([...LPY, ...CPFG]);
    expect(JSON.parse(pythonMain(['model.lpy', 'notes.txt'], two, new Uint32Array([LPY.length, CPFG.length])))).toEqual({ main: 'model.lpy', dialect: 'lpy' });
    const nothing = JSON.parse(importObject([], new Uint8Array(), new Uint32Array())) as Imported;
    expect(nothing.dialect).toBeNull();
    expect(nothing.notes[0].message).toMatch(/no L-system file/);
    expect(JSON.parse(pythonMain([''], new Uint8Array(), new Uint32Array([0])))).toBeNull();
  });
});

describe("exportModel's growth animation settings", () => {
  const source = 'axiom: F\nF -> F[+F]F\n#iterations 2\n';
  const glb = (options: object) => exportModel(source, { format: 'glb', animate: true, ...options });

  it('out of range are refused in words, not replaced or written as an invalid glTF', () => {
    // 1e40 seconds per step wrote infinite keyframe times; -1 and 0 became 1, 1e9 targets 16.
    for (const secondsPerStep of [1e40, -1, 0, Number.NaN, 0.0009, 3601]) {
      expect(() => glb({ secondsPerStep })).toThrow(/seconds per step must be from 0\.001 to 3600/);
    }
    for (const targetsPerStep of [0, 17, 1e9]) {
      expect(() => glb({ targetsPerStep })).toThrow(/targets per step must be from 1 to 16/);
    }
    const file = glb({ secondsPerStep: 3600, targetsPerStep: 16 });
    expect(file.bytes().length).toBeGreaterThan(0);
    file.free();
  });
});
