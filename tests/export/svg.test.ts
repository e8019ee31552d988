// SVG: every gallery example and the golden grammars, exported by the command-line tool, are
// well-formed XML (fast-xml-parser's validator and parser) with a view box and one line piece per
// drawn segment.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { XMLParser, XMLValidator } from 'fast-xml-parser';
import { afterAll, describe, expect, it } from 'vitest';
import { exportWithCli, galleryDir, galleryExamples, goldenDir, goldenNames, removeScratch, scratchDir, statsOf } from './tools';

const dir = scratchDir('svg');
afterAll(() => removeScratch(dir));

interface SvgRead {
  viewBox: number[];
  /** Straight pieces of all paths (`L` commands). */
  pieces: number;
  polygons: number;
  circles: number;
}

/** Validates and parses an SVG, counting what it draws. */
function readSvg(text: string): SvgRead {
  const valid = XMLValidator.validate(text);
  if (valid !== true) throw new Error(`not well-formed XML: ${valid.err.msg} at line ${valid.err.line}`);
  const parser = new XMLParser({ ignoreAttributes: false, attributeNamePrefix: '', isArray: (name) => ['path', 'polygon', 'circle'].includes(name) });
  const document = parser.parse(text) as {
    svg: { xmlns: string; viewBox: string; g: { path?: { d: string }[]; polygon?: unknown[]; circle?: unknown[] } };
  };
  const { svg } = document;
  if (svg.xmlns !== 'http://www.w3.org/2000/svg') throw new Error('not in the SVG namespace');
  const paths = svg.g.path ?? [];
  return {
    viewBox: svg.viewBox.split(' ').map(Number),
    pieces: paths.reduce((sum, p) => sum + (p.d.match(/L/g)?.length ?? 0), 0),
    polygons: svg.g.polygon?.length ?? 0,
    circles: svg.g.circle?.length ?? 0,
  };
}

describe('SVG from the command-line tool', () => {
  it.each(galleryExamples())('%s: well-formed, a view box, a piece per segment', (name) => {
    const grammar = join(galleryDir, name);
    const read = readSvg(exportWithCli(grammar, join(dir, `${name}.svg`)).toString('utf8'));
    expect(read.viewBox).toHaveLength(4);
    expect(read.viewBox[2]).toBeGreaterThan(0);
    expect(read.viewBox[3]).toBeGreaterThan(0);
    expect(read.pieces).toBe(statsOf(grammar).segments);
  });

  it.each(goldenNames())('golden %s.svg', (name) => {
    const read = readSvg(readFileSync(join(goldenDir, `${name}.svg`), 'utf8'));
    expect(read.pieces).toBeGreaterThan(0);
    if (name === 'leafy-3d') expect([read.polygons, read.circles]).toEqual([4, 1]);
  });

  it('the parse can fail: an element left open', () => {
    const good = readFileSync(join(goldenDir, 'flat-koch.svg'), 'utf8');
    expect(() => readSvg(good.replace('</g>', ''))).toThrow(/not well-formed XML/);
  });
});
