// Share links: the studio's whole state in the URL fragment, compressed (deflate-raw + base64url)
// behind a format version, so a link made today still opens after the format grows. Decoding
// treats every fragment as hostile: length, encoding, inflated size, JSON shape and value ranges
// are all checked, and any failure is a message, never an exception. The grammar's text is never
// judged by what it says: it is only ever shown as text (the editor, text nodes, escaped SVG and
// snippets; nothing in `web/src` puts user text into innerHTML), so a comment holding
// `<script>…</script>` or `<img onerror=…>` is just a comment, and every legal grammar opens
// (`codec.test.ts`; the studio end to end in `tests/browser/share.test.ts`).
import type { EditsDocument } from '../core/branches';
import { FRAGMENT_KEY, MAX_FRAGMENT, MAX_TEXT } from './codec-loader';
import type { SharedGrowth } from './growth-state';

/** The format version written by this build; every version up to it can be read. */
export const SHARE_VERSION = 1;
/** Largest inflated payload accepted (bytes): a decompression bomb stops here. */
export const MAX_INFLATED = 512 * 1024;
/** Most iterations a link may ask for: the core's own limit on steps (`#max_steps`) is a `u32`. */
export const MAX_ITERATIONS = 2 ** 32 - 1;
/** Most slider values a link keeps (they are in the text already: others are dropped, not refused). */
export const MAX_SLIDERS = 200;

/** Everything a link restores. */
export interface SharedState {
  /** The grammar text. */
  text: string;
  /** The iterations override; absent = the grammar's own. */
  iterations?: number;
  /** The seed override; absent = the grammar's `#seed`. */
  seed?: number;
  /** Values of `#define` sliders by name (already in the text; kept for the record). */
  sliders?: Record<string, number>;
  /** View options. */
  view?: {
    sides?: number;
    smoothAll?: boolean;
    byProduction?: boolean;
    grid?: boolean;
    lighting?: boolean;
    /** The 2D/3D choice: `auto` (2D for flat plants) or fixed. */
    projection?: 'auto' | 'perspective' | 'orthographic';
    /** Branches as lines, tubes, or `auto` (lines for flat plants). */
    render?: 'auto' | 'lines' | 'tubes';
    /** The lines' width in CSS pixels (0.5 to 20). */
    lineWidth?: number;
  };
  /** The camera in use: eye position, the point looked at, and the orthographic zoom. */
  camera?: { position: [number, number, number]; target: [number, number, number]; zoom?: number };
  /** Branch edits (their Bézier handles moved), keyed by branch path. */
  edits?: EditsDocument;
  /** The growth timeline: time, speed, range (./growth-state.ts). */
  growth?: SharedGrowth;
}

export type Decoded = { ok: true; state: SharedState } | { ok: false; error: string };

/** Encodes a state as a URL fragment (with the leading `#`). */
export async function encodeState(state: SharedState): Promise<string> {
  return `#${FRAGMENT_KEY}=${SHARE_VERSION}.${await packText(JSON.stringify({ v: SHARE_VERSION, ...state }))}`;
}

/** Text as a link carries it: deflate-raw, then base64url (share links, assignments, submissions). */
export async function packText(text: string): Promise<string> {
  return toBase64Url(await pipe(new TextEncoder().encode(text), new CompressionStream('deflate-raw'), Infinity));
}

/**
 * The text {@link packText} packed, or why not (in words that follow "the link …"); never throws.
 * Inflates to at most {@link MAX_INFLATED} bytes.
 */
export async function unpackText(packed: string): Promise<{ ok: true; text: string } | { ok: false; error: string }> {
  const bytes = fromBase64Url(packed);
  if (!bytes) return { ok: false, error: 'the link is not valid base64url' };
  let inflated: Uint8Array;
  try {
    inflated = await pipe(bytes, new DecompressionStream('deflate-raw'), MAX_INFLATED);
  } catch (error) {
    return { ok: false, error: error instanceof TooLarge ? `the link inflates to more than ${MAX_INFLATED / 1024} KiB` : 'the link is not valid compressed data' };
  }
  try {
    return { ok: true, text: new TextDecoder('utf-8', { fatal: true }).decode(inflated) };
  } catch {
    return { ok: false, error: 'the link does not hold valid UTF-8 text' };
  }
}

/** Decodes a fragment (with or without `#`); never throws. */
export async function decodeState(fragment: string): Promise<Decoded> {
  const raw = fragment.replace(/^#/, '');
  if (raw.length > MAX_FRAGMENT) return fail(`the link is too long (${raw.length} characters; at most ${MAX_FRAGMENT})`);
  if (!raw.startsWith(`${FRAGMENT_KEY}=`)) return fail('the link holds no Meristem state');
  const body = raw.slice(FRAGMENT_KEY.length + 1);
  const dot = body.indexOf('.');
  const version = dot > 0 ? Number(body.slice(0, dot)) : NaN;
  if (!Number.isInteger(version) || version < 1) return fail('the link has no format version');
  if (version > SHARE_VERSION) return fail(`the link was made by a newer Meristem (format ${version}); this one reads up to ${SHARE_VERSION}`);
  const unpacked = await unpackText(body.slice(dot + 1));
  if (!unpacked.ok) return unpacked;
  let json: unknown;
  try {
    json = JSON.parse(unpacked.text);
  } catch {
    return fail('the link does not hold valid JSON text');
  }
  return validate(json);
}

function fail(error: string): Decoded {
  return { ok: false, error };
}

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

function isWhole(value: unknown, max: number): value is number {
  return typeof value === 'number' && Number.isInteger(value) && value >= 0 && value <= max;
}

/** Largest coordinate a camera may have: the plant's own are `f32`. */
const MAX_COORDINATE = 3.4e38;

function isPoint(value: unknown): value is [number, number, number] {
  return Array.isArray(value) && value.length === 3 && value.every((v) => typeof v === 'number' && Number.isFinite(v) && Math.abs(v) <= MAX_COORDINATE);
}

/** Names a slider may have in a link: a `#define` name, never one that would reach an object's prototype. */
function isSliderName(name: string): boolean {
  return /^[A-Za-z_]\w*$/.test(name) && name.length <= 256 && !['__proto__', 'constructor', 'prototype'].includes(name);
}

/**
 * The slider values worth keeping: well-named finite numbers, at most {@link MAX_SLIDERS}. They
 * repeat values the text holds, so anything else is dropped rather than the link refused.
 */
function cleanSliders(sliders: unknown): Record<string, number> | undefined {
  if (!isRecord(sliders)) return undefined;
  const clean: Record<string, number> = {};
  let kept = 0;
  for (const [name, value] of Object.entries(sliders)) {
    if (kept === MAX_SLIDERS) break;
    if (!isSliderName(name) || typeof value !== 'number' || !Number.isFinite(value)) continue;
    clean[name] = value;
    kept++;
  }
  return kept > 0 ? clean : undefined;
}

/** Checks the shape of a decoded state; copies only known fields. */
export async function validate(json: unknown): Promise<Decoded> {
  if (!isRecord(json)) return fail('the link does not hold a state object');
  const { text, iterations, seed, sliders, view, camera, edits, growth } = json;
  if (typeof text !== 'string') return fail('the link holds no grammar text');
  if (text.length > MAX_TEXT) return fail(`the grammar in the link is too long (${text.length} characters; at most ${MAX_TEXT})`);
  const state: SharedState = { text };
  if (iterations !== undefined) {
    if (!isWhole(iterations, MAX_ITERATIONS)) return fail(`the link’s iterations are not a whole number from 0 to ${MAX_ITERATIONS}`);
    state.iterations = iterations;
  }
  if (seed !== undefined) {
    if (!isWhole(seed, Number.MAX_SAFE_INTEGER)) return fail('the link’s seed is not a whole number');
    state.seed = seed;
  }
  const kept = cleanSliders(sliders);
  if (kept) state.sliders = kept;
  if (growth !== undefined) {
    // A timeline in a link: its checker loads with the first such link (not with the page).
    const timeline = (await import('./growth-state')).cleanGrowth(growth); // (clamped, or dropped: the link opens without it)
    if (timeline) state.growth = timeline;
  }
  if (view !== undefined) {
    if (!isRecord(view)) return fail('the link’s view options are malformed');
    const clean: NonNullable<SharedState['view']> = {};
    if (view.sides !== undefined) {
      if (!isWhole(view.sides, 64) || view.sides < 3) return fail('the link’s number of sides is not from 3 to 64');
      clean.sides = view.sides;
    }
    for (const key of ['smoothAll', 'byProduction', 'grid', 'lighting'] as const) {
      if (view[key] === undefined) continue;
      if (typeof view[key] !== 'boolean') return fail(`the link’s view option ${key} is not true or false`);
      clean[key] = view[key];
    }
    if (view.projection !== undefined) {
      if (view.projection !== 'auto' && view.projection !== 'perspective' && view.projection !== 'orthographic') {
        return fail('the link’s projection is not auto, perspective or orthographic');
      }
      clean.projection = view.projection;
    }
    if (view.render !== undefined) {
      if (view.render !== 'auto' && view.render !== 'lines' && view.render !== 'tubes') return fail('the link’s render mode is not auto, lines or tubes');
      clean.render = view.render;
    }
    if (view.lineWidth !== undefined) {
      if (typeof view.lineWidth !== 'number' || !(view.lineWidth >= 0.5 && view.lineWidth <= 20)) return fail('the link’s line width is not from 0.5 to 20 pixels');
      clean.lineWidth = view.lineWidth;
    }
    state.view = clean;
  }
  if (camera !== undefined) {
    if (!isRecord(camera) || !isPoint(camera.position) || !isPoint(camera.target)) return fail('the link’s camera is malformed');
    state.camera = { position: [...camera.position], target: [...camera.target] };
    if (camera.zoom !== undefined) {
      if (typeof camera.zoom !== 'number' || !(camera.zoom > 1e-6 && camera.zoom < 1e6)) return fail('the link’s camera zoom is malformed');
      state.camera.zoom = camera.zoom;
    }
  }
  if (edits !== undefined) {
    // Branch edits are rare in links: their checker loads with the first (not with the page).
    const { validateEdits } = await import('../core/edits-check');
    const checked = validateEdits(edits);
    if (!checked.ok) return fail(`the link’s branch edits are malformed (${checked.error})`);
    state.edits = checked.document;
  }
  return { ok: true, state };
}

class TooLarge extends Error {}

/** Runs bytes through a (de)compression stream, failing with TooLarge past `limit` output bytes. */
async function pipe(input: Uint8Array<ArrayBuffer>, stream: CompressionStream | DecompressionStream, limit: number): Promise<Uint8Array> {
  const writer = stream.writable.getWriter();
  const written = writer.write(input).then(() => writer.close());
  written.catch(() => {}); // the reader reports the error
  const reader = stream.readable.getReader();
  const chunks: Uint8Array[] = [];
  let total = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    total += value.length;
    if (total > limit) {
      await reader.cancel();
      throw new TooLarge();
    }
    chunks.push(value);
  }
  await written;
  const out = new Uint8Array(total);
  let offset = 0;
  for (const chunk of chunks) {
    out.set(chunk, offset);
    offset += chunk.length;
  }
  return out;
}

function toBase64Url(bytes: Uint8Array): string {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

function fromBase64Url(text: string): Uint8Array<ArrayBuffer> | null {
  if (!/^[A-Za-z0-9_-]*$/.test(text) || text.length % 4 === 1) return null;
  try {
    const binary = atob(text.replace(/-/g, '+').replace(/_/g, '/') + '='.repeat((4 - (text.length % 4)) % 4));
    return Uint8Array.from(binary, (c) => c.charCodeAt(0));
  } catch {
    return null;
  }
}
