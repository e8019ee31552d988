// How the string panel writes a module: the core's canonical text (`F(0.016796159999999997)`,
// docs/LANGUAGE.md "Derived string text") with each number cut to 6 significant digits
// (`F(0.0167962)`), the exact text kept for the tooltip. Only the panel's display: the canonical
// string of the command line and the hashes stay exact.

/** Significant digits the panel shows. */
export const SHOWN_DIGITS = 6;

/**
 * `text`, a number as the core writes it, with at most 6 significant digits; unchanged when it has
 * no more than that already, or when the short form is not shorter.
 */
export function shortNumber(text: string): string {
  const value = Number(text);
  if (text.trim() === '' || !Number.isFinite(value)) return text;
  const digits = text.replace(/^[-+]?[0.]*/, '').replace('.', '').length;
  if (digits <= SHOWN_DIGITS) return text;
  const short = String(Number(value.toPrecision(SHOWN_DIGITS)));
  return short.length < text.length ? short : text;
}

/** A module's text with its parameters shortened (`F(0.016796159999999997)` → `F(0.0167962)`). */
export function shortModuleText(text: string): string {
  const open = text.indexOf('(');
  if (open < 0 || !text.endsWith(')')) return text;
  const params = text.slice(open + 1, -1).split(',');
  return `${text.slice(0, open + 1)}${params.map(shortNumber).join(',')})`;
}
