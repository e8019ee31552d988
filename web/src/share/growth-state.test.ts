import { describe, expect, it } from 'vitest';
import { decodeState, encodeState, type SharedState } from './codec';
import { cleanGrowth, GROWTH_SPEED_MAX, GROWTH_SPEED_MIN, GROWTH_TIME_MAX } from './growth-state';
import { deflateRawSync } from 'node:zlib';

/** A fragment carrying `payload` as the studio compresses it. */
const fragmentOf = (payload: string) => `#s=1.${Buffer.from(deflateRawSync(Buffer.from(payload))).toString('base64url')}`;

describe('the growth timeline in a share link', () => {
  it('round-trips the time, speed, range and how it plays', async () => {
    const state: SharedState = { text: 'axiom: F\nF -> F[+F]F', growth: { t: 2.5, speed: 0.5, from: 1, to: 3.5, loop: true, camera: 'follow', turntable: true } };
    expect(await decodeState(await encodeState(state))).toEqual({ ok: true, state });
  });

  it('clamps hostile numbers and drops wrong types, and the link still opens', async () => {
    const payload = JSON.stringify({
      v: 1,
      text: 'axiom: F',
      growth: { t: 1e300, speed: -4, from: -2, to: 'NaN', loop: 'yes', camera: '<script>', turntable: 1, playing: 'true', __proto__: { x: 1 } },
    });
    const decoded = await decodeState(fragmentOf(payload));
    expect(decoded).toEqual({ ok: true, state: { text: 'axiom: F', growth: { t: GROWTH_TIME_MAX, speed: GROWTH_SPEED_MIN, from: 0, playing: true } } });
  });

  it('drops a growth state that is not an object, or holds nothing usable', async () => {
    for (const growth of [null, 3, 'fast', [1, 2], {}, { t: Infinity, speed: null }]) {
      const decoded = await decodeState(fragmentOf(JSON.stringify({ v: 1, text: 'axiom: F', growth })));
      expect(decoded, JSON.stringify(growth)).toEqual({ ok: true, state: { text: 'axiom: F' } });
    }
  });
});

describe('cleanGrowth (links and embed attributes)', () => {
  it('reads numeric text and true/false as attributes give them', () => {
    expect(cleanGrowth({ t: ' 3 ', speed: '400', loop: 'false', to: '2', from: '5' })).toEqual({ t: 3, speed: GROWTH_SPEED_MAX, loop: false, from: 5, to: 5 });
    expect(cleanGrowth({ t: '', speed: '1e999' })).toBeUndefined();
  });
});
