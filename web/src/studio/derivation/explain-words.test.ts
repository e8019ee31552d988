// The explanations in words, on the core's real answers: ABOP's signal (section 1.8) and eq. 1.7.
import { afterAll, describe, expect, it } from 'vitest';
import { inspectPlant, type PlantInspector } from '../../core';
import { descendants, firstChildren, originInWords } from './derivation-view';
import { copiedInWords, countsInWords, describeProduction, lineOf, madeInWords, reportInWords } from './explain-words';

const SIGNAL = '#iterations 4\naxiom: baaaaaaaa\nb < a -> b\nb -> a\n';
const EQ_1_7 = [
  '#iterations 4',
  'axiom: B(2)A(4,4)',
  'A(x,y): y<=3 -> A(x*2,x+y)',
  'A(x,y): y>3 -> B(x)A(x/y,0)',
  'B(x): x<1 -> C',
  'B(x): x>=1 -> B(x-1)',
  '',
].join('\n');

const inspectors: PlantInspector[] = [];
function inspect(source: string, iterations?: number) {
  const plant = inspectPlant(source, { iterations });
  inspectors.push(plant.inspector);
  return plant;
}
afterAll(() => inspectors.forEach((i) => i.free()));

describe('productions in words', () => {
  it('names a production by its rule number, line and text', () => {
    const { build } = inspect(SIGNAL);
    expect(describeProduction(SIGNAL, build.productions[0])).toBe('rule 1 (line 3: b < a -> b)');
    expect(lineOf(SIGNAL, SIGNAL.indexOf('b ->'))).toBe(4);
  });

  it('says what a production did in the last step, with its condition', async () => {
    const { build, inspector } = inspect(EQ_1_7);
    // The last step read CB(2)A(4,3): B(2) is the only B.
    expect(countsInWords(EQ_1_7, build.productions[3], (await inspector.explain(3))!)).toBe(
      'rule 4 (line 6: B(x): x>=1 -> B(x-1)) fired 1 time in the last step: 1 module matched its predecessor; the condition x>=1 held.',
    );
    expect(countsInWords(EQ_1_7, build.productions[2], (await inspector.explain(2))!)).toBe(
      'rule 3 (line 5: B(x): x<1 -> C) fired 0 times in the last step: 1 module matched its predecessor; the condition x<1 was false at 1 of them.',
    );
  });
});

describe('why a production fired or not at a module', () => {
  it('reports the left context found instead of the one expected', async () => {
    // After 4 steps: aaaabaaaa. Module 6 (an a) came from the a at 6 of aaabaaaaa, whose left neighbour is a, not b.
    const { build, inspector } = inspect(SIGNAL);
    const report = (await inspector.matchReport(0, 6))!;
    const words = reportInWords(SIGNAL, build.productions[0], report);
    expect(words).toBe('rule 1 (line 3: b < a -> b) at a (module 6 of the string before the last step): left context b expected, found a at 5 — so it did not fire there.');
  });

  it('reports the context that matched where it fired', async () => {
    const { build, inspector } = inspect(SIGNAL);
    const report = (await inspector.matchReport(0, 4))!;
    expect(reportInWords(SIGNAL, build.productions[0], report)).toBe(
      'rule 1 (line 3: b < a -> b) at a (module 4 of the string before the last step): left context matched at 3 — so it fired there.',
    );
    const explanation = (await inspector.explainModule(4))!;
    expect(madeInWords(SIGNAL, build.productions[0], explanation, report, 4, 'b')).toBe(
      'This b (module 4 of the derived string) was written by rule 1 (line 3: b < a -> b) from a (module 4 of the step before): left context matched at 3. That production fired 1 time in the last step.',
    );
  });

  it('says when a module was copied, its numbers as the string panel writes them', () => {
    expect(copiedInWords(3, 'F(0.016796159999999997)')).toBe('This F(0.0167962) (module 3 of the derived string) was copied: no production rewrote it in the last step.');
  });

  it('says when the module is not the predecessor, and when another production won', async () => {
    const { build, inspector } = inspect(EQ_1_7, 1);
    // Step 1: B(1)B(4)A(1,0). Module 0 comes from B(2): rule 1 (A(x,y) …) cannot rewrite it.
    const notPredecessor = (await inspector.matchReport(0, 0))!;
    expect(reportInWords(EQ_1_7, build.productions[0], notPredecessor)).toMatch(/cannot rewrite B\(2\) .*it is not the production's predecessor\.$/);
    // Module 1 comes from A(4,4): rule 1's condition y<=3 was false; rule 2 rewrote it.
    const failed = (await inspector.matchReport(0, 1))!;
    expect(reportInWords(EQ_1_7, build.productions[0], failed)).toMatch(/at A\(4,4\) .*: y<=3 was false — so it did not fire there\.$/);
  });
});

describe('the derivation step by step', () => {
  it("links each module of eq. 1.7's first step to what it became", async () => {
    const { inspector } = inspect(EQ_1_7);
    const steps = (await inspector.sequence(1000))!;
    expect(steps.map((s) => s.texts.join(''))).toEqual(['B(2)A(4,4)', 'B(1)B(4)A(1,0)', 'B(0)B(3)A(2,1)', 'CB(2)A(4,3)', 'CB(1)A(8,7)']);
    expect(steps[1].parent).toEqual([0, 1, 1]);
    expect(steps[1].origin).toEqual([3, 1, 1]);
    const host = { describeProduction: (i: number) => `rule ${i + 1}`, conditionOf: (i: number) => ['y<=3', 'y>3', 'x<1', 'x>=1'][i] };
    expect(originInWords(steps, 1, 0, host)).toBe('Step 1: B(1) is what B(2) became, by rule 4; x>=1 held.');
    expect(originInWords(steps, 1, 2, host)).toBe('Step 1: A(1,0) is one of the 2 modules A(4,4) became, by rule 2; y>3 held.');
    expect(originInWords(steps, 0, 1, host)).toBe('A(4,4) is part of the axiom (step 0).');
    expect(descendants(steps, 0, 1).sort()).toEqual([1, 2]);
    expect(descendants(steps, 0, 0), 'B(2) ⇒ B(1) ⇒ B(0) ⇒ C ⇒ C').toEqual([0]);
  });

  it('finds the first child of each module from the parents', () => {
    expect([...firstChildren([0, 1, 1, 3], 4)]).toEqual([0, 1, 3, 3, 4]);
  });
});
