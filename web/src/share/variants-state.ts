// The Variants view's plants in a share link (`SharedState.variants`): two to six grammars, each
// with its seed, iterations and caption. Checked like the rest of a link, as hostile: a list of
// the wrong length, a text too long, a caption that is not short text, a number out of range
// refuses the link with a message that says which variant and what; only known fields are kept.
// Loaded with the first link that has variants (not with the page).
import { MAX_TEXT } from './codec-loader';

/** One plant of the Variants view. */
export interface SharedVariant {
  /** Its grammar. */
  text: string;
  /** The seed override; absent = the grammar's `#seed`. */
  seed?: number;
  /** The iterations override; absent = the grammar's own. */
  iterations?: number;
  /** What sets it apart, shown under it (e.g. `angle = 25`). */
  caption?: string;
}

/** Fewest and most variants a link may hold. */
export const MIN_SHARED_VARIANTS = 2;
export const MAX_SHARED_VARIANTS = 6;
/** Longest caption (characters). */
export const MAX_CAPTION = 120;
/** Most iterations a variant may ask for (as a link's own). */
const MAX_ITERATIONS = 2 ** 32 - 1;

export type CheckedVariants = { ok: true; variants: SharedVariant[] } | { ok: false; error: string };

const isRecord = (value: unknown): value is Record<string, unknown> => typeof value === 'object' && value !== null && !Array.isArray(value);
const isWhole = (value: unknown, max: number): value is number => typeof value === 'number' && Number.isInteger(value) && value >= 0 && value <= max;

/** The variants of a link, checked, or what is wrong with them. */
export function checkVariants(json: unknown): CheckedVariants {
  const fail = (error: string): CheckedVariants => ({ ok: false, error: `the link’s variants ${error}` });
  if (!Array.isArray(json)) return fail('are not a list');
  if (json.length < MIN_SHARED_VARIANTS || json.length > MAX_SHARED_VARIANTS) {
    return fail(`are ${json.length} plants; a link holds ${MIN_SHARED_VARIANTS} to ${MAX_SHARED_VARIANTS}`);
  }
  const variants: SharedVariant[] = [];
  for (const [i, item] of json.entries()) {
    const which = `(plant ${i + 1})`;
    if (!isRecord(item)) return fail(`are malformed ${which}`);
    const { text, seed, iterations, caption } = item;
    if (typeof text !== 'string') return fail(`hold no grammar text ${which}`);
    if (text.length > MAX_TEXT) return fail(`hold a grammar too long ${which}: ${text.length} characters; at most ${MAX_TEXT}`);
    const variant: SharedVariant = { text };
    if (seed !== undefined) {
      if (!isWhole(seed, Number.MAX_SAFE_INTEGER)) return fail(`hold a seed that is not a whole number ${which}`);
      variant.seed = seed;
    }
    if (iterations !== undefined) {
      if (!isWhole(iterations, MAX_ITERATIONS)) return fail(`hold iterations that are not a whole number from 0 to ${MAX_ITERATIONS} ${which}`);
      variant.iterations = iterations;
    }
    if (caption !== undefined) {
      if (typeof caption !== 'string' || caption.length > MAX_CAPTION) return fail(`hold a caption that is not text of at most ${MAX_CAPTION} characters ${which}`);
      variant.caption = caption;
    }
    variants.push(variant);
  }
  return { ok: true, variants };
}
