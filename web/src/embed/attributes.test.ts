import { describe, expect, it } from 'vitest';
import { growingMessage, wholeAttribute } from './embed-plant';

describe('<meristem-plant> iterations and seed attributes (issue 50, finding 9c)', () => {
  it('takes whole numbers up to what the core accepts', () => {
    expect(wholeAttribute('iterations', null)).toEqual({});
    expect(wholeAttribute('iterations', '4')).toEqual({ value: 4 });
    expect(wholeAttribute('iterations', '4294967295')).toEqual({ value: 4294967295 });
    expect(wholeAttribute('seed', '9007199254740991')).toEqual({ value: 9007199254740991 });
  });

  it('says what is wrong with any other value, rather than handing the core what it refuses', () => {
    expect(wholeAttribute('iterations', '4294967296')).toEqual({
      problem: 'iterations="4294967296" is not a whole number from 0 to 4294967295: the grammar’s own value is used.',
    });
    for (const bad of ['-1', '2.5', 'five', '', '1e400']) expect(wholeAttribute('iterations', bad).problem).toContain(`iterations="${bad}"`);
    expect(wholeAttribute('seed', '9007199254740992').problem).toContain('seed="9007199254740992" is not a whole number');
    expect(wholeAttribute('seed', 'x'.repeat(1000)).problem!.length).toBeLessThan(200);
  });
});

describe('growingMessage', () => {
  it('says the plant waits, then grows, with the derivation step when known', () => {
    expect(growingMessage(undefined)).toBe('Waiting to grow…');
    expect(growingMessage({ stage: 'parsing', step: 0, steps: 0 })).toBe('Growing…');
    expect(growingMessage({ stage: 'deriving', step: 3, steps: 10 })).toBe('Growing… step 3 of 10');
    expect(growingMessage({ stage: 'meshing', step: 0, steps: 0 })).toBe('Growing…');
  });
});
