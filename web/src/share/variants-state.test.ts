import { describe, expect, it } from 'vitest';
import { deflateRawSync } from 'node:zlib';
import { decodeState, encodeState, type SharedState } from './codec';
import { checkVariants, MAX_CAPTION, MAX_SHARED_VARIANTS } from './variants-state';
import { MAX_TEXT } from './codec-loader';

const fragmentOf = (json: unknown) => `#s=1.${Buffer.from(deflateRawSync(Buffer.from(JSON.stringify(json)))).toString('base64url')}`;
const PLANT = '#define a 20\naxiom: F\nF -> F[+F]F\n';

describe('variants in a share link', () => {
  it('round-trip with their texts, seeds, iterations and captions', async () => {
    const state: SharedState = {
      text: PLANT,
      variants: [
        { text: PLANT, caption: 'a = 20' },
        { text: PLANT.replace('20', '25'), caption: 'a = 25', seed: 7 },
        { text: 'axiom: F', iterations: 3 },
      ],
    };
    expect(await decodeState(await encodeState(state))).toEqual({ ok: true, state });
  });

  it('refuse a link with too few or too many plants, politely', async () => {
    const one = await decodeState(fragmentOf({ v: 1, text: PLANT, variants: [{ text: PLANT }] }));
    expect(one).toEqual({ ok: false, error: 'the link’s variants are 1 plants; a link holds 2 to 6' });
    const many = Array.from({ length: 1000 }, () => ({ text: 'F' }));
    const decoded = await decodeState(fragmentOf({ v: 1, text: PLANT, variants: many }));
    expect(decoded.ok).toBe(false);
    expect(!decoded.ok && decoded.error).toContain(`2 to ${MAX_SHARED_VARIANTS}`);
  });

  it('say which plant is wrong and how', () => {
    const error = (variants: unknown) => {
      const checked = checkVariants(variants);
      return checked.ok ? 'accepted' : checked.error;
    };
    expect(error({ length: 3 })).toBe('the link’s variants are not a list');
    expect(error([{ text: 'F' }, 'F'])).toBe('the link’s variants are malformed (plant 2)');
    expect(error([{ text: 'F' }, { text: 3 }])).toBe('the link’s variants hold no grammar text (plant 2)');
    expect(error([{ text: 'F', seed: -1 }, { text: 'F' }])).toContain('seed');
    expect(error([{ text: 'F', seed: 1.5 }, { text: 'F' }])).toContain('(plant 1)');
    expect(error([{ text: 'F' }, { text: 'F', iterations: 'many' }])).toContain('iterations');
    expect(error([{ text: 'F' }, { text: 'F', caption: 'x'.repeat(MAX_CAPTION + 1) }])).toContain('caption');
    expect(error([{ text: 'F' }, { text: 'F', caption: { toString: 1 } }])).toContain('caption');
    expect(error([{ text: 'F' }, { text: 'x'.repeat(MAX_TEXT + 1) }])).toContain('too long (plant 2)');
  });

  it('keep only the known fields, and treat hostile text as text', () => {
    const checked = checkVariants([
      { text: '<img src=x onerror=alert(1)>', caption: '<script>', __proto__: { polluted: true }, extra: 1 },
      { text: 'F', constructor: 'x' },
    ]);
    expect(checked).toEqual({ ok: true, variants: [{ text: '<img src=x onerror=alert(1)>', caption: '<script>' }, { text: 'F' }] });
    expect(({} as Record<string, unknown>).polluted).toBeUndefined();
  });
});
