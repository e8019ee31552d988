// The seed a grammar's text writes with its seed directive (`#seed 4`), for lesson checks: the
// Seed box of the toolbar overrides it, so a check that asks for the seed *in the text* compares
// this with the seed the plant on screen was derived with. The directive's spelling is the
// caller's (read from the core's vocabulary), so this file spells no name of the language.

/**
 * The number of the last line `directive N` of `source` (a later one replaces an earlier one, as
 * the core reads directives), outside comments; undefined when the text writes none.
 */
export function writtenSeed(source: string, directive: string): number | undefined {
  let seed: number | undefined;
  for (const raw of source.split('\n')) {
    const line = raw.replace(/\/\/.*$/, '').trim();
    if (!line.startsWith(directive)) continue;
    const rest = line.slice(directive.length);
    if (rest !== '' && !/^\s/.test(rest)) continue; // `#seedling` is another word
    const value = Number(rest.trim());
    if (rest.trim() !== '' && Number.isInteger(value) && value >= 0) seed = value;
  }
  return seed;
}
