import { describe, expect, it } from 'vitest';
import type { ProductionInfo } from '../../core';
import { lineageText } from './lineage-list';

const production = (index: number, from: number, to: number): ProductionInfo => ({ index, from, to, label: null }) as ProductionInfo;

describe('lineageText', () => {
  it('writes a lineage as `meristem lineage` prints it (crate/tests/cli.rs), the last step first', () => {
    // 1.24d's text: X -> … is on line 7 (the file's 3 comment lines, #angle, #iterations, axiom).
    const source = '// a\n// b\n// c\n#angle 20\n#iterations 7\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF\n';
    const from = source.indexOf('X ->');
    const rows = [
      { step: 2, module: 7, text: 'X', production: 0, first: 7, last: 7 },
      { step: 1, module: 3, text: 'X', production: 0, first: 4, last: 15 },
      { step: 0, module: 0, text: 'X', first: 0, last: 40 },
    ];
    const productions = [production(0, from, from + 'X -> F[+X]F[-X]+X'.length)];
    expect(lineageText(rows, source, productions)).toBe(
      'step 2: X [7] <- 7:1 X -> F[+X]F[-X]+X\nstep 1: X [3] <- 7:1 X -> F[+X]F[-X]+X\nstep 0: X [0] <- axiom\n',
    );
  });

  it('says a copied module, a timed step and a column counted in characters, as the core does', () => {
    const source = 'axiom: a_r(0)\n  é a_r(t) -> a_l(0) b_r(0)\n';
    const from = source.indexOf('a_r(t)');
    const rows = [
      { step: 2, module: 1, text: 'a_l(0.5)', time: 2.5, first: 1, last: 1 },
      { step: 1, module: 0, text: 'a_l(0)', production: 0, time: 1, first: 0, last: 1 },
    ];
    expect(lineageText(rows, source, [production(0, from, source.length - 1)])).toBe(
      'step 2 (t = 2.5): a_l(0.5) [1] <- copied\nstep 1 (t = 1): a_l(0) [0] <- 2:5 a_r(t) -> a_l(0) b_r(0)\n',
    );
  });
});
