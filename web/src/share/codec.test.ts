import { describe, expect, it } from 'vitest';
import { readdirSync, readFileSync } from 'node:fs';
import { deflateRawSync } from 'node:zlib';
import { decodeState, encodeState, MAX_ITERATIONS, type SharedState } from './codec';
import { hasSharedState, MAX_FRAGMENT } from './codec-loader';

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
    ['invalid UTF-8', () => fragmentOf(new Uint8Array([0x7b, 0xff, 0xfe, 0x7d])), /UTF-8/],
    ['not JSON', () => fragmentOf('text: axiom F'), /JSON/],
    ['JSON that is not an object', () => fragmentOf('[1,2,3]'), /state object/],
    ['no grammar text', () => fragmentOf('{"v":1,"iterations":3}'), /no grammar text/],
    ['a grammar that is too long', () => fragmentOf(JSON.stringify({ text: 'F'.repeat(300_000) })), /too long/],
    ['negative iterations', () => fragmentOf(JSON.stringify({ text: 'axiom: F', iterations: -1 })), /iterations/],
    ['absurd iterations', () => fragmentOf(JSON.stringify({ text: 'axiom: F', iterations: MAX_ITERATIONS + 1 })), /iterations/],
    ['fractional iterations', () => fragmentOf(JSON.stringify({ text: 'axiom: F', iterations: 2.5 })), /iterations/],
    ['a seed that is text', () => fragmentOf(JSON.stringify({ text: 'axiom: F', seed: '42' })), /seed/],
    ['an infinite camera', () => fragmentOf('{"text":"axiom: F","camera":{"position":[1e400,0,0],"target":[0,0,0]}}'), /camera/],
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

  it('drops slider values it cannot use (they are in the text), never reaching a prototype', async () => {
    const decoded = await decodeState(fragmentOf('{"text":"axiom: F","sliders":{"__proto__":{"polluted":1},"constructor":2,"ok":0.5,"bad name":1,"nan":"x"}}'));
    expect(decoded).toEqual({ ok: true, state: { text: 'axiom: F', sliders: { ok: 0.5 } } });
    expect(({} as Record<string, unknown>).polluted).toBeUndefined();
    const none = await decodeState(fragmentOf('{"text":"axiom: F","sliders":{"__proto__":1}}'));
    expect(none).toEqual({ ok: true, state: { text: 'axiom: F' } });
  });
});

/** Grammars (and grammar-like text) a link must carry: none is HTML that could run. */
const LEGAL: [string, string][] = [
  ['a #define named on…', '#define onset = 2\naxiom: F(onset)'],
  ['#define onclick without spaces', '#define onclick=3\naxiom: A(onclick)\nA(x) -> F(x)'],
  ['javascript: in a comment', 'axiom: F // see javascript:void(0) for nothing\nF -> FF'],
  ['javascript: in a block comment', '/* javascript:alert(1) is text here */\naxiom: F'],
  ['a #module span', '#module span\naxiom: span\nspan -> F span'],
  ['#module script', '#module script iframe\naxiom: script iframe\nscript -> F script'],
  ['a context b<a>a', '#angle 22.5\naxiom: b<a>a\nb < a -> b'],
  ['contexts without spaces', 'axiom: ABC\nA<B>C -> D\nA<B -> E\nB>C -> F'],
  ['a context of many modules', 'axiom: img\ni<m>g -> F'],
  ['a one-letter context like a tag', 'axiom: a\nb<a>a -> F\nx<img>y -> G'],
  ['an onerror-like define in a context line', '#define onerror = 1\naxiom: A\nB<A>C -> F(onerror)'],
  ['on…= in a comment', '// onload = when it loads\naxiom: F'],
  ['an unclosed script word in a comment', '// <script is just a word here\naxiom: F'],
  ['a tag-like context across lines', 'axiom: b<a\n#define onset = 2\nA>B -> C'],
  ['a script context without an end tag', 'axiom: X\nX<script>Y -> Z'],
  ['HTML words in a comment', '// iframe, object, embed, svg, style, template\naxiom: F'],
  ['an email-like and URL-like comment', '// mail me: <me@example.org> or https://example.org/?on=1\naxiom: F'],
  ['a less-than in an expression', '#define n = 3\naxiom: A(1)\nA(x) : x<n -> A(x+1)F\nA(x) : x>=n -> F'],
  ['comparisons around names', 'axiom: A(1,2)\nA(a,b) : a<b && b>a -> F(a)'],
  ['unicode and emoji', '// 🌱 ünïcödé <α>\naxiom: F'],
];

/**
 * Text holding HTML that would run if it were ever rendered as HTML. The studio never renders a
 * grammar as HTML (only as text), so these are grammars like any other: in comments they are legal,
 * and a link carries them unchanged (they were refused once, which refused legal grammars; issue 19).
 */
const HTML_LIKE: [string, string][] = [
  ['a script element', '<script>alert(1)</script>'],
  ['a script element across lines', 'axiom: F\n<script>\nalert(1)\n</script>'],
  ['a script element in capitals', '<SCRIPT>alert(1)</SCRIPT >'],
  ['a script with attributes', '<script type="module">import("x")</script>'],
  ['a script with a source', '<script src="https://evil.example/x.js">'],
  ['an image with onerror', '<img src=x onerror=alert(1)>'],
  ['an image with onerror after a slash', '<img/src=x/onerror=alert(1)>'],
  ['an svg with onload', 'axiom: F // <svg onload="alert(1)">'],
  ['a body with onload', '<body onload=alert(1)>'],
  ['a handler in capitals', '<IMG SRC=x OnError=alert(1)>'],
  ['a javascript: link', '<a href="javascript:alert(1)">x</a>'],
  ['a javascript: link with spaces', "<a href = ' javascript :alert(1)'>x</a>"],
  ['a javascript: link with a tab', '<a href="java\tscript:alert(1)">x</a>'],
  ['an entity-encoded javascript: link', '<a href="&#106;avascript&#58;alert(1)">x</a>'],
  ['a hex-entity javascript: link', '<a href="&#x6A;avascript&colon;alert(1)">x</a>'],
  ['a vbscript: link', '<a href="vbscript:msgbox(1)">x</a>'],
  ['a data:text/html iframe', '<iframe src="data:text/html,<script>alert(1)</script>">'],
  ['an iframe with a source', '<iframe src="https://evil.example">'],
  ['an iframe with srcdoc', '<iframe srcdoc="&lt;script&gt;alert(1)&lt;/script&gt;">'],
  ['an object with data', '<object data="evil.swf">'],
  ['an embed with a source', '<embed src="evil.swf">'],
  ['a form action in javascript:', '<form action="javascript:alert(1)"><button>go</button></form>'],
  ['a math xlink', '<math><maction xlink:href="javascript:alert(1)">x</maction></math>'],
  ['a handler hidden in a grammar', '#angle 20\naxiom: X\nX -> F[+X]F // <div onmouseover="alert(1)">hover</div>'],
];

describe('grammar text in links', () => {
  it.each(LEGAL)('opens a link with %s', async (_name, text) => {
    const decoded = await decodeState(await encodeState({ text }));
    expect(decoded).toEqual({ ok: true, state: { text } });
  });

  it.each(HTML_LIKE)('opens a link with %s, unchanged', async (_name, text) => {
    const decoded = await decodeState(await encodeState({ text }));
    expect(decoded).toEqual({ ok: true, state: { text } });
  });

  it.each(HTML_LIKE)('opens a link with %s in a comment of a grammar', async (_name, html) => {
    const text = `// ${html.replace(/\n/g, '\n// ')}\n/* ${html.replace(/\*\//g, '* /')} */\n#angle 20\naxiom: X\nX -> F[+X]F[-X]X`;
    const decoded = await decodeState(await encodeState({ text, iterations: 3 }));
    expect(decoded).toEqual({ ok: true, state: { text, iterations: 3 } });
  });

  it('opens the link of every gallery example', async () => {
    const folder = new URL('../../../public/examples/', import.meta.url);
    const names = readdirSync(folder).filter((name) => name.endsWith('.lsys'));
    expect(names.length).toBeGreaterThan(20);
    for (const name of names) {
      const text = readFileSync(new URL(name, folder), 'utf8');
      const fragment = await encodeState({ text, iterations: 5, seed: 1 });
      expect(fragment.length, name).toBeLessThanOrEqual(MAX_FRAGMENT);
      expect(await decodeState(fragment), name).toEqual({ ok: true, state: { text, iterations: 5, seed: 1 } });
    }
  });
});
