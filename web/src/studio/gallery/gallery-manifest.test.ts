import { describe, expect, it } from 'vitest';
import { readdirSync, readFileSync } from 'node:fs';
import { exampleGroup, galleryManifest, isGalleryManifest, parseExampleHeader } from './gallery-manifest';

describe('parseExampleHeader', () => {
  it('reads the title, the source and the description lines', () => {
    const text = '// ABOP Fig 1.24d: a plant\n// Source: The Book, Fig. 1.24d.\n// The apex X makes\n// two branches.\n#angle 20\n// not the header\n';
    expect(parseExampleHeader('abop-1.24d.lsys', text)).toEqual({
      file: 'abop-1.24d.lsys',
      title: 'ABOP Fig 1.24d: a plant',
      source: 'The Book, Fig. 1.24d.',
      description: 'The apex X makes two branches.',
      group: 'Other',
    });
  });

  it('copes with a missing source, a missing header and CRLF', () => {
    expect(parseExampleHeader('a.lsys', '// Title\r\n// Just words.\r\naxiom: F')).toMatchObject({ title: 'Title', source: '', description: 'Just words.' });
    expect(parseExampleHeader('bare.lsys', 'axiom: F')).toEqual({ file: 'bare.lsys', title: 'bare', source: '', description: '', group: 'Other' });
  });
});

describe('exampleGroup', () => {
  it.each([
    ['Prusinkiewicz & Lindenmayer, The Algorithmic Beauty of Plants (1990), Fig. 1.24d.', 'ABOP chapter 1: graphical modeling using L-systems'],
    ['Prusinkiewicz & Lindenmayer, The Algorithmic Beauty of Plants (1990), eq. 1.7 and Fig. 1.34.', 'ABOP chapter 1: graphical modeling using L-systems'],
    ['Prusinkiewicz & Lindenmayer, The Algorithmic Beauty of Plants (1990), section 1.10.2.', 'ABOP chapter 1: graphical modeling using L-systems'],
    ['Prusinkiewicz & Lindenmayer, The Algorithmic Beauty of Plants (1990), Fig. 2.6a (after Honda 1971).', 'ABOP chapter 2: modeling of trees'],
    ['Lluch, Vicent, Vivó, Quirós, "Green: a tool for modelling natural elements" (seed 000), Fig. 1.', "Green's RL-systems"],
    ['Jou, Park, Bahng, "L-system tree with particle attributes" (shared/seeds/002), Fig 2 and Table 1.', 'Jou, Park and Bahng: particle attributes'],
    ["Laurens Lapré's Lparser examples, fern-plant.ls", 'Lparser'],
    ['Palubicki et al., "Self-organizing tree models for image synthesis" (SIGGRAPH 2009).', 'Open L-systems: plants and their environment'],
    ['Měch & Prusinkiewicz, "Visual models of plants interacting with their environment" (SIGGRAPH 1996).', 'Open L-systems: plants and their environment'],
    ['Rathod, Tyagi, "L-systems based 3D tree modeling" (shared/seeds/003).', 'Other'],
    ['', 'Other'],
  ])('%s is in %s', (source, group) => {
    expect(exampleGroup(source)).toBe(group);
  });
});

describe('galleryManifest', () => {
  it('lists the .lsys files sorted, and passes its own check', () => {
    const manifest = galleryManifest([
      ['b.lsys', '// B'],
      ['notes.txt', 'x'],
      ['a.lsys', '// A'],
    ]);
    expect(manifest.map((e) => e.file)).toEqual(['a.lsys', 'b.lsys']);
    expect(isGalleryManifest(JSON.parse(JSON.stringify(manifest)))).toBe(true);
    expect(isGalleryManifest([{ file: 'a.lsys' }])).toBe(false);
    expect(isGalleryManifest({})).toBe(false);
  });

  it('gives every example of the real gallery a title, a source and a description', () => {
    const dir = new URL('../../../../public/examples/', import.meta.url);
    const files = readdirSync(dir).filter((f) => f.endsWith('.lsys'));
    const manifest = galleryManifest(files.map((f) => [f, readFileSync(new URL(f, dir), 'utf8')] as const));
    expect(manifest).toHaveLength(files.length);
    // In the gallery's order: ABOP chapters 1 to 6, Green, Jou, Lparser, the open L-systems, Other.
    expect([...new Set(manifest.map((e) => e.group))]).toEqual([
      'ABOP chapter 1: graphical modeling using L-systems',
      'ABOP chapter 2: modeling of trees',
      'ABOP chapter 3: developmental models of herbaceous plants',
      'ABOP chapter 4: phyllotaxis',
      'ABOP chapter 5: models of plant organs',
      'ABOP chapter 6: animation of plant development',
      "Green's RL-systems",
      'Jou, Park and Bahng: particle attributes',
      'Lparser',
      'Open L-systems: plants and their environment',
      'Other',
    ]);
    for (const entry of manifest) expect(entry.group.startsWith('ABOP'), entry.file).toBe(entry.file.startsWith('abop-'));
    for (const entry of manifest) {
      expect(entry.title, entry.file).not.toBe(entry.file.replace(/\.lsys$/, ''));
      expect(entry.source, entry.file).not.toBe('');
      expect(entry.description.length, entry.file).toBeGreaterThan(20);
      expect(entry.description, `${entry.file}: a source spilling into the description`).toMatch(/^["“A-Z]/);
    }
  });
});
