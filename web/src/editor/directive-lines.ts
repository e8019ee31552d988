// A directive's line in the grammar text: where it is and its arguments. Small and on its own:
// the derivation controls read `#iterations` with the first plant; the Growth panel, which edits
// the growth directives (growth-directives.ts), loads after it.

/** A directive found in the text: where its line is and its arguments. */
export interface FoundDirective {
  /** UTF-16 range of the arguments (from after the name to before a `//` comment or the line's end, trimmed). */
  from: number;
  to: number;
  /** The whole line, its end of line included (for removal). */
  lineFrom: number;
  lineTo: number;
  args: string[];
}

/** The first line `#directive …` of `text`, or null. */
export function findDirective(text: string, directive: string): FoundDirective | null {
  const pattern = new RegExp(`^([ \\t]*#${directive})(?=[ \\t]|$|//)([^\\n]*)$`, 'm');
  const match = pattern.exec(text);
  if (!match) return null;
  const lineFrom = match.index;
  const rest = match[2];
  const comment = rest.indexOf('//');
  const body = comment >= 0 ? rest.slice(0, comment) : rest;
  const lead = body.length - body.trimStart().length;
  const from = lineFrom + match[1].length + lead;
  const trimmed = body.trim();
  const end = lineFrom + match[0].length;
  return {
    from,
    to: from + trimmed.length,
    lineFrom,
    lineTo: text[end] === '\n' ? end + 1 : end,
    args: trimmed === '' ? [] : trimmed.split(/[ \t]+/),
  };
}
