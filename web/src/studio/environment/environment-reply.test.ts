import { describe, expect, it } from 'vitest';
import { branchQuery, replyInWords } from './environment-reply';

const NAMES = { query: '?E', open: '[', close: ']' };
// F [ + F ?E(…) A ] [ - F ?E(…) A ] as the inspector gives the module texts.
const TEXTS = ['F', '[', '+', 'F', '?E(0.42,0.1,0.9,0.4)', 'A', ']', '[', '-', 'F', '?E(0.8,-0.2,0.97,0)', 'A', ']'];

describe("a picked segment's ?E", () => {
  it('is the first after it on its branch, skipping nested branches', () => {
    expect(branchQuery(TEXTS, 0, 3, NAMES)).toEqual({ module: 4, text: '?E(0.42,0.1,0.9,0.4)', values: [0.42, 0.1, 0.9, 0.4] });
    expect(branchQuery(TEXTS, 0, 9, NAMES)?.module).toBe(10);
    // With the texts from module 100 on, the indices are the string's.
    expect(branchQuery(TEXTS, 100, 103, NAMES)?.module).toBe(104);
  });

  it('else the last before it on its branch; none for the trunk, whose ?E are its branches\'', () => {
    expect(branchQuery(TEXTS, 0, 5, NAMES)?.module).toBe(4);
    expect(branchQuery(TEXTS, 0, 0, NAMES)).toBeNull();
    // The F in a branch of its own: the ?E before the branch is its parent's, not its own.
    expect(branchQuery(['F', '?E(1)', '[', 'F', ']'], 0, 3, NAMES)).toBeNull();
  });

  it('names its values by the programs\' reply words, a direction as one', () => {
    const light = { module: 4, text: '', values: [0.42, 0.1, 0.9, 0.4] };
    expect(replyInWords(light, ['exposure', 'dx', 'dy', 'dz'], '?E')).toBe('?E(0.42, 0.1, 0.9, 0.4): exposure 0.42, towards (0.1, 0.9, 0.4)');
    const both = { module: 4, text: '', values: [0.85548, -0.171, 0.985, 0, 1, 1.92262] };
    expect(replyInWords(both, ['exposure', 'dx', 'dy', 'dz', 'free', 'distance'], '?E')).toBe(
      '?E(0.855, -0.171, 0.985, 0, 1, 1.923): exposure 0.855, towards (-0.171, 0.985, 0), free 1, distance 1.923',
    );
    const short = { module: 4, text: '', values: [1, 0.5] };
    expect(replyInWords(short, ['exposure', 'dx', 'dy', 'dz'], '?E')).toBe('?E(1, 0.5): exposure 1, dx 0.5, (dy dz not kept: the module has 2 parameters)');
    expect(replyInWords({ module: 0, text: '', values: [] }, [], '?E')).toBe('?E(): no reply (no program answers)');
  });
});
