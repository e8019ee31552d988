// OpenInventor 2.1: every gallery example and the golden grammars, exported by the command-line
// tool, are read by SGI Open Inventor's own `ivcat` with nothing on stderr, and pass a structural
// check: the header, balanced braces, one shared point and normal list of the plant's vertices,
// and face sets whose triangles (or lines) name points that exist.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { exportWithCli, galleryDir, galleryExamples, goldenDir, goldenNames, runTool, removeScratch, scratchDir, statsOf } from './tools';

const dir = scratchDir('inventor');
afterAll(() => removeScratch(dir));

/** What the structural check found. */
interface InventorCheck {
  points: number;
  normals: number;
  faces: number;
  problems: string[];
}

/** The numbers between the `[` after `from` and the `]` that closes it. */
function listAfter(text: string, from: number): { values: number[]; end: number } {
  const open = text.indexOf('[', from);
  const close = text.indexOf(']', open);
  const body = text.slice(open + 1, close).trim();
  return { values: body === '' ? [] : body.split(/[\s,]+/).filter((t) => t !== '').map(Number), end: close };
}

/** Checks an Inventor file's structure; `arity` is 3 for face sets, 2 for line sets. */
function checkInventor(text: string, arity: number): InventorCheck {
  const problems: string[] = [];
  if (!text.startsWith('#Inventor V2.1 ascii\n')) problems.push('missing the "#Inventor V2.1 ascii" header');
  const code = text.replace(/#[^\n]*/g, ''); // comments, the header included
  let depth = 0;
  for (const char of code) {
    if (char === '{') depth++;
    if (char === '}' && --depth < 0) break;
  }
  if (depth !== 0) problems.push(`braces do not balance (depth ${depth} at the end)`);
  const coordinate = code.indexOf('Coordinate3 {');
  const points = coordinate < 0 ? 0 : listAfter(code, coordinate).values.length / 3;
  const normal = code.indexOf('Normal {');
  const normals = normal < 0 ? 0 : listAfter(code, normal).values.length / 3;
  let faces = 0;
  let at = code.indexOf('coordIndex [');
  while (at >= 0) {
    const { values, end } = listAfter(code, at);
    let corners = 0;
    for (const value of values) {
      if (value === -1) {
        if (corners !== arity) problems.push(`a face of ${corners} indices`);
        corners = 0;
        faces++;
      } else if (!Number.isInteger(value) || value < 0 || value >= points) {
        problems.push(`index ${value} out of range (${points} points)`);
      } else corners++;
    }
    at = code.indexOf('coordIndex [', end);
  }
  return { points, normals, faces, problems };
}

function ivcat(path: string): { status: number | null; stderr: string } {
  return runTool('ivcat', [path], { discardStdout: true });
}

describe('Inventor from the command-line tool', () => {
  it.each(galleryExamples())('%s: ivcat reads it; shared points and normals, faces in range', (name) => {
    const grammar = join(galleryDir, name);
    const path = join(dir, `${name}.iv`);
    const text = exportWithCli(grammar, path).toString('utf8');
    const stats = statsOf(grammar);
    const check = checkInventor(text, 3);
    expect(check.problems.slice(0, 5)).toEqual([]);
    expect([check.points, check.normals, check.faces]).toEqual([stats.vertices, stats.vertices, stats.triangles]);
    expect(ivcat(path)).toMatchObject({ status: 0, stderr: '' });
  });

  it.each(goldenNames())('golden %s.iv', (name) => {
    const path = join(goldenDir, `${name}.iv`);
    const check = checkInventor(readFileSync(path, 'utf8'), name.endsWith('-lines') ? 2 : 3);
    expect(check.problems).toEqual([]);
    expect(check.faces).toBeGreaterThan(0);
    expect(ivcat(path)).toMatchObject({ status: 0, stderr: '' });
  });

  it('the checks can fail: a lost brace, an index out of range, an unknown node', () => {
    const good = readFileSync(join(goldenDir, 'leafy-3d.iv'), 'utf8');
    expect(checkInventor(good.replace('DirectionalLight {', 'DirectionalLight'), 3).problems).toContain(
      'braces do not balance (depth -1 at the end)',
    );
    expect(checkInventor(good.replace(/coordIndex \[\n\s+(\d+)/, 'coordIndex [\n      99999'), 3).problems[0]).toMatch(
      /^index 99999 out of range/,
    );
    const path = join(dir, 'unknown-node.iv');
    writeFileSync(path, good.replace('DirectionalLight {', 'DirectionalLamp {'));
    const read = ivcat(path);
    expect(read.stderr).toContain('Unknown class "DirectionalLamp"');
  });
});
