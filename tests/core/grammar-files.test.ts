// Opening grammar files through the real core's importers (web/src/studio/files/grammar-files.ts).
import { readdirSync, readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { initCore } from '../../web/src/core';
import { decodeText, lsysFileName, MAX_FILE_BYTES, openGrammarBytes, openObjectBytes } from '../../web/src/studio/files/grammar-files';
import { linkWithFragment } from '../../web/src/studio/links/share-button';

beforeAll(async () => {
  await initCore(readFileSync(new URL('../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));
});

const file = (path: string) => new Uint8Array(readFileSync(new URL(`../../crate/tests/import/${path}`, import.meta.url)));

describe('openGrammarBytes', () => {
  it('keeps a .lsys file as it is', () => {
    const text = '#angle 90\naxiom: F+F';
    expect(openGrammarBytes('square.lsys', new TextEncoder().encode(text))).toEqual({ ok: true, text, dialect: null, notes: [] });
  });

  it.each([
    ['lparser/abop-bush.ls', 'lparser'],
    ['cpfg/monopodial.l', 'cpfg'],
    ['lpy/ex_vonkoch.lpy', 'lpy'],
    ['green/worked-example.txt', 'green'],
  ])('imports %s as %s, with line-numbered notes', (path, dialect) => {
    const opened = openGrammarBytes(path.split('/')[1], file(path));
    expect(opened.ok).toBe(true);
    if (!opened.ok) return;
    expect(opened.dialect).toBe(dialect);
    expect(opened.text).toMatch(/axiom:/);
    for (const note of opened.notes) expect(note).toMatch(/^(line \d+: )?\S/);
  });

  it('reads a file that is not UTF-8 as Windows-1252 and says so', () => {
    const opened = openGrammarBytes('old.ls', new Uint8Array([...new TextEncoder().encode('# Lapr'), 0xe9, ...new TextEncoder().encode('\n2\n30\n10\nF\nF=FF\n@\n')]));
    expect(opened.ok && opened.notes[0]).toBe('The file is not UTF-8; it was read as Windows-1252.');
    expect(decodeText(new Uint8Array([0x41, 0xe9])).text).toBe('Aé');
  });

  it('refuses binary and oversized files with a reason', () => {
    expect(openGrammarBytes('a.png', new Uint8Array([0x89, 0x50, 0, 1]))).toEqual({ ok: false, error: 'a.png is not a text file' });
    const big = openGrammarBytes('big.lsys', new Uint8Array(MAX_FILE_BYTES + 1).fill(0x46));
    expect(big.ok).toBe(false);
    if (!big.ok) expect(big.error).toMatch(/too large/);
  });

  it('reads a text the importers do not recognise as Meristem text', () => {
    const text = 'axiom: F\nF -> FF';
    expect(openGrammarBytes('notes.txt', new TextEncoder().encode(text))).toEqual({ ok: true, text, dialect: null, notes: [] });
  });
});

describe('openObjectBytes', () => {
  const folder = (name: string, under = 'import-corpus/vlab') => {
    const dir = new URL(`../../crate/tests/${under}/${name}/`, import.meta.url);
    return readdirSync(dir).map((file) => ({ name: `${name}/${file}`, bytes: new Uint8Array(readFileSync(new URL(file, dir))) }));
  };

  it("imports a vlab object's folder with its view file's angle and its functions", () => {
    const opened = openObjectBytes(folder('05-monopodial'));
    expect(opened.ok).toBe(true);
    if (!opened.ok) return;
    expect(opened.dialect).toBe('cpfg');
    expect(opened.text).toMatch(/^#angle 9$/m);
    expect(opened.text).toMatch(/^#table internode /m);
    expect(opened.notes).toEqual([expect.stringMatching(/^the materials of material.mat become their diffuse colours/)]);
  });

  it("imports an lpfg object's timeline functions (.tset) and values (.vset) with it", () => {
    const opened = openObjectBytes(folder('Lychnis', 'import-timeline'));
    expect(opened.ok).toBe(true);
    if (!opened.ok) return;
    expect(opened.text).toMatch(/^#table LEAF_LENGTH 0 0 /m);
    expect(opened.text).toMatch(/^#define BR_END 15.4362 \/\/ val\(BR_END\) of aging.vset$/m);
    expect(opened.text).toContain('~l(LEAFSCALE*LEAF_LENGTH(((t)-0.07)/36.8935))');
    expect(opened.notes.filter((n) => /\.tset|\.vset|lpfg's (tfunc|val)/.test(n))).toEqual([]);
  });

  it('opens one grammar file as openGrammarBytes does, and says why a broken archive cannot be opened', () => {
    expect(openObjectBytes([{ name: 'a.lsys', bytes: new TextEncoder().encode('axiom: F') }])).toEqual({ ok: true, text: 'axiom: F', dialect: null, notes: [] });
    expect(openObjectBytes([{ name: 'plant.zip', bytes: new TextEncoder().encode('PK not a zip') }])).toEqual({
      ok: false,
      error: 'plant.zip: not a zip archive (no end of central directory)',
    });
  });
});

describe('file names and links', () => {
  it('makes a file name from a title', () => {
    expect(lsysFileName('ABOP Fig 1.24d: a plant by node rewriting')).toBe('abop-fig-124d-a-plant-by-node-rewriting.lsys');
    expect(lsysFileName('Untitled grammar')).toBe('untitled-grammar.lsys');
    expect(lsysFileName('../../etc/passwd')).toBe('etcpasswd.lsys');
    expect(lsysFileName('***')).toBe('grammar.lsys');
  });

  it('puts a fragment on the page address, replacing any', () => {
    expect(linkWithFragment({ href: 'https://a.b/x/y/?q=1', hash: '' }, '#s=1.abc')).toBe('https://a.b/x/y/?q=1#s=1.abc');
    expect(linkWithFragment({ href: 'https://a.b/x/#s=1.old', hash: '#s=1.old' }, '#s=1.new')).toBe('https://a.b/x/#s=1.new');
    expect(linkWithFragment({ href: 'https://a.b/x/#', hash: '' }, '')).toBe('https://a.b/x/');
  });
});
