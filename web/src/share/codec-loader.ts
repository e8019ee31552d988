// The share link's codec (./codec.ts, with its checks) on first use, and what the page knows of a
// link before it has loaded: whether an address carries a state, and the link's limits (the Share
// button states them; the codec keeps to them). No first plant needs the codec unless the page was
// opened from a link, and then it is asked for at once (`loadCodec` in `startingText`), in
// parallel with the core: the one case it costs a request before the first plant. Making a link
// (the Share button, an embed's "open in the studio") loads it on the click.
import type * as Codec from './codec';
import type { Decoded, SharedState } from './codec';

/** The fragment's key: `#s=<version>.<payload>`. */
export const FRAGMENT_KEY = 's';
/** Longest fragment accepted (characters). */
export const MAX_FRAGMENT = 64 * 1024;
/** Longest grammar text accepted (characters). */
export const MAX_TEXT = 200_000;

/** True when a location fragment carries a shared state (it may still be invalid). */
export function hasSharedState(fragment: string): boolean {
  return fragment.replace(/^#/, '').startsWith(`${FRAGMENT_KEY}=`);
}

let codec: Promise<typeof Codec> | undefined;

/** The codec's module, loading it the first time (a failed load is tried again next time). */
export function loadCodec(): Promise<typeof Codec> {
  codec ??= import('./codec').catch((error: unknown) => {
    codec = undefined;
    throw error;
  });
  return codec;
}

/** Encodes a state as a URL fragment (with the leading `#`), loading the codec first. */
export async function encodeState(state: SharedState): Promise<string> {
  return (await loadCodec()).encodeState(state);
}

/**
 * Decodes a fragment (with or without `#`), loading the codec first; never throws: a codec (or
 * one of the checks it loads) that cannot be loaded, the network gone, is a message too.
 */
export async function decodeState(fragment: string): Promise<Decoded> {
  try {
    return await (await loadCodec()).decodeState(fragment);
  } catch {
    return { ok: false, error: 'the page could not load its link reader (check the connection, then reload)' };
  }
}
