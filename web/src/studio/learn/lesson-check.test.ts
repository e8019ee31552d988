import { describe, expect, it } from 'vitest';
import type { PlantStats } from '../../core';
import { evaluateCheck, needsDerivedString, needsFlorets, parseCheck, spokenAnswer, spokenNumber, type CheckNode } from './lesson-check';
import { floretPositions, parastichyPair, type FloretMesh } from './parastichies';
import { writtenSeed } from './written-seed';

const stats: PlantStats = {
  modules: 12,
  segments: 5,
  vertices: 100,
  triangles: 80,
  lines: 0,
  iterations: 2,
  bounds: [
    [-1, 0, 0],
    [2, 6, 0.5],
  ],
};
/** F[+F][-F]F[+F[-A(1,2)]]A(3): two siblings at the first node, nesting 2. */
const modules = ['F', '[', '+', 'F', ']', '[', '-', 'F', ']', 'F', '[', '+', 'F', '[', '-', 'A(1,2)', ']', ']', 'A(3)'];

function read(source: string): CheckNode {
  const parsed = parseCheck(source);
  if (!parsed.ok) throw new Error(`${source}: ${parsed.error.message}`);
  return parsed.check;
}

/** The check's answer as the studio says it. */
function check(source: string): string {
  return spokenAnswer(evaluateCheck(read(source), { stats, modules }));
}

describe('checks: facts and functions', () => {
  it.each([
    ['segments == 5', true],
    ['modules > 12', false],
    ['iterations >= 2 and iterations <= 2', true],
    ['width == 3 and height == 6 and depth == 0.5', true],
    // bounds x -1 … 2: one to the left of the base, two to the right.
    ['left == 1 and right == 2 and right == 2 * left', true],
    ['vertices != 100', false],
    ['triangles < 81', true],
    ["count(\"F\") == 5", true],
    ['count("A") == 2', true],
    ['count("[") == count("]")', true],
    ['count("G") == 0', true],
    ['contains("F[+F][-F]")', true],
    ['contains("A(1,2)")', true],
    ['contains("F[-F][+F]")', false],
    ['not contains("G")', true],
    ['branch_order == 2', true],
    ['whorl == 2', true],
    ['count("F") == 2 * 2 + 1 and segments - 1 == 4 and -segments < 0 and segments / 2 == 2.5', true],
    ['(count("F") + 1) * 2 == 12', true],
    ['segments > 10 or count("F") == 5', true],
    ['segments > 10 or (count("F") == 3 or whorl == 2)', true],
    ['not (segments == 5 and whorl == 2)', false],
    ['segments == 5 and not whorl == 3', true],
  ])('%s is %s', (source, pass) => {
    expect(evaluateCheck(read(source), { stats, modules }).pass).toBe(pass);
  });

  it('binds and tighter than or', () => {
    expect(evaluateCheck(read('segments == 1 and segments == 2 or segments == 5'), { stats }).pass).toBe(true);
    expect(evaluateCheck(read('segments == 5 or segments == 1 and segments == 2'), { stats }).pass).toBe(true);
  });

  it('knows when it needs the derived string', () => {
    expect(needsDerivedString(read('segments > 3 and height < 2 * width'))).toBe(false);
    for (const source of ['count("F") > 1', 'not contains("F")', 'segments > 1 or whorl == 3', 'branch_order + 1 > 2']) {
      expect(needsDerivedString(read(source)), source).toBe(true);
    }
    expect(() => evaluateCheck(read('count("F") > 1'), { stats })).toThrow(/derived string/);
  });
});

describe('checks: the answer in words', () => {
  it('says what is wrong and what the task wants', () => {
    const answers = [
      ['count("[") == 8', 'Not yet: count("[") is 4, the task wants 8.'],
      ['segments >= 20 and whorl == 2', 'Not yet: segments is 5, the task wants at least 20.'],
      ['count("-") == count("+") + 1', 'Not yet: count("-") is 2, the task wants count("+") + 1 (3).'],
      ['contains("G[")', 'Not yet: the derived string does not contain G[.'],
      ['not contains("A(3)")', 'Not yet: the derived string contains A(3), the task wants it not to.'],
      ['segments < 2 or whorl > 2', 'Not yet: segments is 5, the task wants less than 2, or whorl is 2, the task wants more than 2.'],
      ['height / width > 3', 'Not yet: height / width is 2, the task wants more than 3.'],
    ];
    for (const [source, answer] of answers) expect(check(source), source).toBe(answer);
  });

  it('says the values that passed', () => {
    expect(check('count("F") == 5 and whorl >= 2')).toBe('Passed: count("F") is 5; whorl is 2.');
    expect(check('not contains("G")')).toBe('Passed: the derived string does not contain G.');
  });

  it('speaks numbers as a person reads them', () => {
    expect(spokenNumber(3)).toBe('3');
    expect(spokenNumber(2.0000000001)).toBe('2');
    expect(spokenNumber(1.1428571428571428)).toBe('1.143');
  });

  it('compares with a tolerance for floating-point bounds', () => {
    const near = { ...stats, bounds: [[0, 0, 0], [0.1 + 0.2, 1, 0]] as PlantStats['bounds'] };
    expect(evaluateCheck(read('width == 0.3'), { stats: near }).pass).toBe(true);
  });
});

describe('checks: malformed ones are refused with the place', () => {
  it.each([
    ['segments', 'is a number: compare it', 8],
    ['segments = 3', 'write == to compare', 9],
    ['segmnts > 3', '"segmnts" is not a fact or function of checks', 0],
    ['count(F) > 3', 'takes one text in double quotes', 6],
    ['count("F" > 3', 'expected )', 10],
    ['contains("F and segments > 1', 'no closing "', 9],
    ['1 < segments < 3', 'compare two things at a time', 13],
    ['segments > 3 segments < 5', 'was not expected here', 13],
    ['segments > 3 and', 'ends too early', 16],
    ['contains("F") > 1', 'was not expected here', 14],
    ['count("F") + contains("F") > 1', 'true or false, not a number', 13],
    ['eval("x") == 1', '"eval" is not a fact or function', 0],
    ['count("") == 0', 'names no module', 0],
    ['segments > 3 & whorl > 1', 'has no meaning', 13],
  ])('%s', (source, message, offset) => {
    const parsed = parseCheck(source);
    expect(parsed.ok).toBe(false);
    if (parsed.ok) return;
    expect(parsed.error.message).toContain(message);
    expect(parsed.error.offset).toBe(offset);
  });
});

describe('checks: position, seeds and parastichies', () => {
  it('finds where a module first stands, from 1', () => {
    const facts = { stats, modules };
    expect(evaluateCheck(read('position("F") == 1 and position("A") == 16 and position("G") == 0'), facts).pass).toBe(true);
    expect(evaluateCheck(read('position("]") == 5 and position("-") < position("A")'), facts).pass).toBe(true);
    expect(needsDerivedString(read('position("F") > 0'))).toBe(true);
  });

  it('compares the seed on screen with the one the text writes', () => {
    const check = read('text_seed == seed');
    expect(evaluateCheck(check, { stats, seed: 4, textSeed: 4 }).pass).toBe(true);
    expect(spokenAnswer(evaluateCheck(check, { stats, seed: 4, textSeed: 1 }))).toBe('Not yet: text_seed is 1, the task wants seed (4).');
    expect(evaluateCheck(read('text_seed == -1'), { stats, seed: 1 }).pass).toBe(true);
  });

  it('counts the parastichies of spheres placed by Vogel\'s formula', () => {
    // 600 florets at n·137.5°, r = √n, each a tetrahedron of a sphere's material (2) around its centre.
    const mesh = vogelMesh(600, 137.5);
    expect(floretPositions(mesh)).toHaveLength(600);
    expect(floretPositions(mesh)[10][0]).toBeCloseTo(Math.sqrt(10) * Math.cos((10 * 137.5 * Math.PI) / 180), 6);
    expect(parastichyPair(floretPositions(mesh))).toEqual([34, 55]);
    expect(evaluateCheck(read('parastichies_m == 34 and parastichies_n == 55'), { stats, florets: floretPositions(mesh) }).pass).toBe(true);
    expect(needsFlorets(read('segments > 1 and not (parastichies_n + 1 > 2)'))).toBe(true);
    expect(needsFlorets(read('segments > 1 or contains("D")'))).toBe(false);
    expect(parastichyPair(floretPositions(vogelMesh(600, 137.3)))).not.toEqual([34, 55]);
    expect(evaluateCheck(read('parastichies_m == 0'), { stats }).pass).toBe(true);
    expect(parastichyPair(floretPositions(vogelMesh(5, 137.5)))).toEqual([0, 0]);
  });
});

describe('checks: the trunk\'s proportion and the divergence angle', () => {
  it('reads the divergence off the florets and the trunk\'s ratio from the facts', () => {
    const florets = floretPositions(vogelMesh(600, 137.5));
    expect(needsFlorets(read('divergence > 137'))).toBe(true);
    expect(evaluateCheck(read('divergence > 137.45 and divergence < 137.55'), { stats, florets }).pass).toBe(true);
    const mirrored = floretPositions(vogelMesh(600, 222.5));
    expect(evaluateCheck(read('divergence > 137.45 and divergence < 137.55'), { stats, florets: mirrored }).pass).toBe(true);
    expect(spokenAnswer(evaluateCheck(read('divergence > 1'), { stats }))).toBe('Not yet: divergence is 0, the task wants more than 1.');
    expect(evaluateCheck(read('trunk_width_ratio > 0.04'), { stats, trunkWidthRatio: 0.0445 }).pass).toBe(true);
    expect(evaluateCheck(read('trunk_width_ratio > 0.05'), { stats, trunkWidthRatio: 0.0445 }).pass).toBe(false);
    expect(needsFlorets(read('trunk_width_ratio > 0.05'))).toBe(false);
  });
});

describe('the seed a text writes', () => {
  it.each([
    ['#seed 4\naxiom: F', 4],
    ['#seed 4\n#seed 7\n', 7],
    ['axiom: F // #seed 3', undefined],
    ['// #seed 3\naxiom: F', undefined],
    ['  #seed 12 // tall\n', 12],
    ['#seedling 3\n', undefined],
    ['#seed\n', undefined],
    ['#seed -2\n', undefined],
    ['axiom: F\n', undefined],
  ])('%j is %s', (text, seed) => {
    expect(writtenSeed(text, '#seed')).toBe(seed);
  });
});

/** A mesh of `count` florets at Vogel's positions: per floret 4 triangles of material 2 (plain), a stalk of material 0 first. */
function vogelMesh(count: number, angle: number): FloretMesh {
  const positions: number[] = [0, 0, 0, 0, 0, -1, 0.1, 0, -1];
  const indices: number[] = [0, 1, 2];
  const ranges: number[] = [0, 0];
  for (let n = 0; n < count; n++) {
    const a = (n * angle * Math.PI) / 180;
    const [x, y] = [Math.sqrt(n) * Math.cos(a), Math.sqrt(n) * Math.sin(a)];
    const v = positions.length / 3;
    const corners = [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]];
    for (const [dx, dy, dz] of corners) positions.push(x + 0.1 * dx, y + 0.1 * dy, 0.1 * dz);
    ranges.push(indices.length / 3, n + 1);
    for (const [i, j, k] of [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]) indices.push(v + i, v + j, v + k);
  }
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices), ranges: new Uint32Array(ranges), materialRanges: new Uint32Array([0, 0, 1, 2]) };
}
