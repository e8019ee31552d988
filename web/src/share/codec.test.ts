import { describe, expect, it } from 'vitest';
import { deflateRawSync } from 'node:zlib';
import { decodeState, encodeState, hasSharedState, MAX_FRAGMENT, type SharedState } from './codec';

const base64url = (bytes: Uint8Array) => Buffer.from(bytes).toString('base64url');
/** A fragment carrying arbitrary bytes, compressed as the studio would. */
const fragmentOf = (payload: string | Uint8Array, version = 1) =>
  `#s=${version}.${base64url(deflateRawSync(typeof payload === 'string' ? Buffer.from(payload) : payload))}`;

const GRAMMAR = '#angle 22.5\naxiom: b<a>a\nb < a -> b // contexts are not HTML\nA<B>C -> D';

describe('share links', () => {
  it('round-trips the whole state', async () => {
    const state: SharedState = {
      text: GRAMMAR + '\n// ünïcödé ✓ 🌱',
      iterations: 7,
      seed: 2 ** 40,
      sliders: { r: 0.75, theta: 22.5 },
      view: { sides: 12, smoothAll: true, byProduction: false, grid: true, lighting: false, projection: 'orthographic', render: 'lines', lineWidth: 1.5 },
      camera: { position: [1.5, 2, -3], target: [0, 1, 0], zoom: 2.5 },
      edits: { version: 1, edits: [{ path: [0, 2, 1], handles: [[0, 0.1, 0], [0, 0, 0], [0.2, -0.1, 0.05]] }] },
    };
    const fragment = await encodeState(state);
    expect(fragment).toMatch(/^#s=1\.[A-Za-z0-9_-]+$/);
    expect(hasSharedState(fragment)).toBe(true);
    expect(await decodeState(fragment)).toEqual({ ok: true, state });
  });

  it('keeps a link short for a typical grammar', async () => {
    const fragment = await encodeState({ text: GRAMMAR.repeat(20) });
    expect(fragment.length).toBeLessThan(300);
  });

  it('reads links of format 1 written by hand (old links keep working)', async () => {
    const decoded = await decodeState(fragmentOf(JSON.stringify({ v: 1, text: 'axiom: F' })));
    expect(decoded).toEqual({ ok: true, state: { text: 'axiom: F' } });
  });

  // Every hostile fragment is rejected with a message, and none throws.
  const bomb = new Uint8Array(20 * 1024 * 1024); // 20 MiB of zeros deflate to ~20 KiB
  const hostile: [string, string | (() => string), RegExp][] = [
    ['too long', '#s=1.' + 'A'.repeat(MAX_FRAGMENT), /too long/],
    ['no state at all', '#hello', /no Meristem state/],
    ['another key', '#x=1.abc', /no Meristem state/],
    ['no version', '#s=abc', /no format version/],
    ['version zero', '#s=0.abc', /no format version/],
    ['a future version', () => fragmentOf('{}', 99), /newer Meristem/],
    ['characters outside base64url', '#s=1.ab$cd', /base64url/],
    ['truncated base64url', '#s=1.abcde', /base64url/],
    ['not compressed data', '#s=1.' + base64url(new Uint8Array([0xff, 0xfe, 0xfd, 0xfc, 0x00, 0x12])), /compressed/],
    ['a decompression bomb', () => fragmentOf(bomb), /inflates to more than/],
    ['invalid UTF-8', () => fragmentOf(new Uint8Array([0x7b, 0xff, 0xfe, 0x7d])), /JSON/],
    ['not JSON', () => fragmentOf('text: axiom F'), /JSON/],
    ['JSON that is not an object', () => fragmentOf('[1,2,3]'), /state object/],
    ['no grammar text', () => fragmentOf('{"v":1,"iterations":3}'), /no grammar text/],
    ['a grammar that is too long', () => fragmentOf(JSON.stringify({ text: 'F'.repeat(300_000) })), /too long/],
    ['a script tag', () => fragmentOf(JSON.stringify({ text: 'axiom: F\n<script>alert(1)</script>' })), /HTML or script/],
    ['an image with an onerror handler', () => fragmentOf(JSON.stringify({ text: '<img src=x onerror=alert(1)>' })), /HTML or script/],
    ['a javascript: URL', () => fragmentOf(JSON.stringify({ text: 'axiom: F // javascript:alert(1)' })), /HTML or script/],
    ['negative iterations', () => fragmentOf(JSON.stringify({ text: 'axiom: F', iterations: -1 })), /iterations/],
    ['absurd iterations', () => fragmentOf(JSON.stringify({ text: 'axiom: F', iterations: 1e9 })), /iterations/],
    ['a seed that is text', () => fragmentOf(JSON.stringify({ text: 'axiom: F', seed: '42' })), /seed/],
    ['an infinite camera', () => fragmentOf('{"text":"axiom: F","camera":{"position":[1e400,0,0],"target":[0,0,0]}}'), /camera/],
    ['a slider named __proto__', () => fragmentOf('{"text":"axiom: F","sliders":{"__proto__":1}}'), /sliders/],
    ['a thousand sides', () => fragmentOf(JSON.stringify({ text: 'axiom: F', view: { sides: 1000 } })), /sides/],
    ['an unknown projection', () => fragmentOf(JSON.stringify({ text: 'axiom: F', view: { projection: 'fisheye' } })), /projection/],
    ['an unknown render mode', () => fragmentOf(JSON.stringify({ text: 'axiom: F', view: { render: 'dots' } })), /render mode/],
    ['a line width out of range', () => fragmentOf(JSON.stringify({ text: 'axiom: F', view: { lineWidth: 1e9 } })), /line width/],
    ['a zero zoom', () => fragmentOf(JSON.stringify({ text: 'axiom: F', camera: { position: [0, 0, 1], target: [0, 0, 0], zoom: 0 } })), /zoom/],
    ['branch edits without a version', () => fragmentOf(JSON.stringify({ text: 'axiom: F', edits: { edits: [] } })), /branch edits/],
    ['branch edits with a path of text', () => fragmentOf(JSON.stringify({ text: 'axiom: F', edits: { version: 1, edits: [{ path: ['x'], handles: [[0, 0, 0], [0, 0, 0], [0, 0, 0]] }] } })), /branch edits/],
    ['a view option that is not boolean', () => fragmentOf(JSON.stringify({ text: 'axiom: F', view: { grid: 'yes' } })), /grid/],
  ];

  it.each(hostile)('rejects %s politely', async (_name, fragment, message) => {
    const decoded = await decodeState(typeof fragment === 'function' ? fragment() : fragment);
    expect(decoded.ok).toBe(false);
    if (!decoded.ok) expect(decoded.error).toMatch(message);
  });

  it('has at least 15 hostile cases', () => {
    expect(hostile.length).toBeGreaterThanOrEqual(15);
  });
});
