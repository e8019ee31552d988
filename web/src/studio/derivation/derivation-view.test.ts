import { describe, expect, it } from 'vitest';
import { NOT_REWRITTEN, type DerivationStep } from '../../core';
import { originInWords, sequenceCaption, stepLabel } from './derivation-view';

const N = NOT_REWRITTEN;
/**
 * ABOP 6.1's timed Anabaena traced to t = 2.5 (as crate/tests/explain.rs checks it): rounds at
 * t = 1 and 2, then the string at 2.5, every cell half a unit older and none replaced.
 */
const ANABAENA: DerivationStep[] = [
  { texts: ['a_r(0)'], parent: [], origin: [N], time: 0 },
  { texts: ['a_l(0)', 'b_r(0)'], parent: [0, 0], origin: [0, 0], time: 1 },
  { texts: ['b_l(0)', 'a_r(0)', 'a_r(0)'], parent: [0, 0, 1], origin: [1, 1, 2], time: 2 },
  { texts: ['b_l(0.5)', 'a_r(0.5)', 'a_r(0.5)'], parent: [0, 1, 2], origin: [N, N, N], time: 2.5 },
];
const host = { describeProduction: (i: number) => `rule ${i + 1}`, conditionOf: () => null };

describe('the derivation view of a timed grammar', () => {
  it('labels each row by its time: the axiom, the rounds, and the string at t', () => {
    expect(ANABAENA.map((s, k) => stepLabel(s, k)[0])).toEqual(['ω', '⇒ t 1', '⇒ t 2', 't 2.5']);
    expect(stepLabel(ANABAENA[3], 3)[1]).toMatch(/^The string at t = 2\.5: nothing replaced/);
  });

  it('says in its caption that the rows are rounds up to t, and the last the string at t', () => {
    expect(sequenceCaption(ANABAENA)).toMatch(/^The timed derivation up to t = 2\.5: a row per round of replacements, at its time, and last the string at t = 2\.5 \(every module older since\)\./);
    expect(sequenceCaption(ANABAENA.slice(0, 3)), 'at a round’s own time no row of ageing').toMatch(/^The timed derivation up to t = 2: a row per round of replacements, at its time\. Each band/);
  });

  it('says where a module comes from at the time of its row', () => {
    expect(originInWords(ANABAENA, 3, 0, host)).toBe('At t = 2.5: b_l(0.5) is b_l(0) of t = 2, older (not replaced: it had not reached its terminal age, or no production matched it).');
    expect(originInWords(ANABAENA, 1, 1, host)).toBe('At t = 1: b_r(0) is one of the 2 modules a_r(0) became, at its terminal age (a_r(0) is its age at t = 0), by rule 1.');
    expect(originInWords(ANABAENA, 0, 0, host)).toBe('a_r(0) is part of the axiom (t = 0).');
  });

  it('leaves other grammars as they were: steps, no times', () => {
    const steps: DerivationStep[] = [
      { texts: ['A'], parent: [], origin: [N] },
      { texts: ['A', 'B'], parent: [0, 0], origin: [0, 0] },
    ];
    expect(steps.map((s, k) => stepLabel(s, k))).toEqual([['ω', 'Step 0: the axiom'], ['⇒ 1', 'Step 1']]);
    expect(sequenceCaption(steps)).toMatch(/^The derivation, step 0 to 1:/);
    expect(originInWords(steps, 1, 1, host)).toBe('Step 1: B is one of the 2 modules A became, by rule 1.');
    expect(originInWords(steps, 0, 0, host)).toBe('A is part of the axiom (step 0).');
  });
});
