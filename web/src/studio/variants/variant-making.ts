// The variants a lecturer makes in a few clicks: the same grammar with one `#define` constant at
// several values (`angle 20, 25, 30`), or grown with several seeds; and a list of values as typed.
// Pure text work on the grammar, tested without a browser.
import { defineConstants } from '../../editor/defines';
import type { SharedVariant } from '../../share';
import { MAX_SHARED_VARIANTS as MAX_VARIANTS } from '../../share/variants-state';

/**
 * The numbers of a list as typed (`20, 25, 30`, `20 25 30` or `20; 25; 30`), or what is wrong with
 * it: at most {@link MAX_VARIANTS} values, each a finite number.
 */
export function parseValues(typed: string): number[] | string {
  const words = typed.split(/[\s,;]+/).filter((w) => w !== '');
  if (words.length === 0) return 'Type the values, e.g. 20, 25, 30.';
  if (words.length > MAX_VARIANTS) return `At most ${MAX_VARIANTS} values (${words.length} given).`;
  const values: number[] = [];
  for (const word of words) {
    const value = Number(word);
    if (!Number.isFinite(value) || !/^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i.test(word)) return `“${word}” is not a number.`;
    values.push(value);
  }
  return values;
}

/** The `#define` constants of `text` whose value is a plain number, with it (the first of each name). */
export function numericConstants(text: string): { name: string; value: number }[] {
  const seen = new Set<string>();
  return defineConstants(text).flatMap(({ name, value }) => (seen.has(name) ? [] : (seen.add(name), [{ name, value }])));
}

/** Three values around `value` for a first row: three quarters, itself, five quarters (or ±1 about 0). */
export function valuesAround(value: number): number[] {
  return value === 0 ? [-1, 0, 1] : [0.75, 1, 1.25].map((k) => Number((value * k).toPrecision(3)));
}

/**
 * `text` with the plain-number constant `name` set to each of `values` (its other lines as they
 * are), captioned `name = value`; or why not.
 */
export function defineVariants(text: string, name: string, values: readonly number[], seed?: number): SharedVariant[] | string {
  const constant = defineConstants(text).find((c) => c.name === name);
  if (!constant) return `The grammar has no constant ${name} with a number for its value.`;
  return values.map((value) => ({
    text: text.slice(0, constant.from) + String(value) + text.slice(constant.to),
    caption: `${name} = ${value}`,
    ...(seed === undefined ? {} : { seed }),
  }));
}

/** `text` grown with each of `seeds` (a row of specimens, ABOP Fig. 1.27), captioned `seed s`. */
export function seedVariants(text: string, seeds: readonly number[]): SharedVariant[] | string {
  const bad = seeds.find((s) => !Number.isSafeInteger(s) || s < 0);
  if (bad !== undefined) return `A seed is a whole number from 0 (${bad} is not).`;
  return seeds.map((seed) => ({ text, seed, caption: `seed ${seed}` }));
}
