// The growth directives of a grammar's text (#lifetime #speed #shape #shape_width #sun #gravity
// #wind #apex, docs/LANGUAGE.md "Growth: particle attributes"), read and rewritten for the studio's
// Growth panel: one directive per line, its arguments separated by spaces (expressions are written
// without spaces), a `//` comment after them kept.

/** One argument of a directive, as the panel edits it. */
export interface GrowthField {
  name: string;
  /** `number`: a number; `expression`: a number or an expression of NumIt, MaxIt and #defines; `season`; `names`: module names. */
  kind: 'number' | 'expression' | 'season' | 'names';
  /** Omitted arguments at the end take the core's defaults (shown as placeholders). */
  optional?: boolean;
  /** The core's default, for an optional argument. */
  placeholder?: string;
  title: string;
}

/** A growth attribute: its directive, its arguments, and what enabling it writes. */
export interface GrowthAttribute {
  directive: string;
  label: string;
  fields: GrowthField[];
  /** The arguments written when the attribute is switched on. */
  defaults: string[];
}

export const SEASONS = ['summer', 'spring', 'autumn', 'winter'] as const;

export const GROWTH_ATTRIBUTES: readonly GrowthAttribute[] = [
  {
    directive: 'lifetime',
    label: 'Lifetime',
    defaults: ['34', '32'],
    fields: [
      { name: 'MB', kind: 'expression', title: 'Apices that keep growing at each step, at least' },
      { name: 'VB', kind: 'expression', title: 'plus Round(Rand() × VB) more' },
      { name: 'upper', kind: 'number', optional: true, placeholder: '0.6', title: 'Share of the upper third' },
      { name: 'middle', kind: 'number', optional: true, placeholder: '0.3', title: 'Share of the middle third' },
      { name: 'lower', kind: 'number', optional: true, placeholder: '0.1', title: 'Share of the lower third' },
    ],
  },
  {
    directive: 'speed',
    label: 'Speed',
    defaults: ['0', '1'],
    fields: [
      { name: 'SM', kind: 'expression', title: 'Rewritings per step added to the positional factor' },
      { name: 'VR', kind: 'expression', title: 'plus Round(Rand() × VR)' },
      { name: 'PF upper', kind: 'number', optional: true, placeholder: '2', title: 'Positional factor of the upper third' },
      { name: 'PF middle', kind: 'number', optional: true, placeholder: '1', title: 'Positional factor of the middle third' },
      { name: 'PF lower', kind: 'number', optional: true, placeholder: '1', title: 'Positional factor of the lower third' },
    ],
  },
  {
    directive: 'shape',
    label: 'Length by age',
    defaults: ['1.5', '3'],
    fields: [
      { name: 'GR', kind: 'number', title: 'Growth rate: a segment of age i is GR^i long up to maturity' },
      { name: 'm', kind: 'number', title: 'Maturity (steps), then logarithmic growth' },
      { name: 'VR', kind: 'number', optional: true, placeholder: '0', title: 'Random variation, ± Round(Rand() × VR)' },
    ],
  },
  {
    directive: 'shape_width',
    label: 'Width by age',
    defaults: ['1'],
    fields: [
      { name: 'VR', kind: 'number', optional: true, placeholder: '0', title: 'Random variation, Round(Rand() × VR)' },
      { name: 'PF upper', kind: 'number', optional: true, placeholder: '2', title: 'Positional factor of the upper third' },
      { name: 'PF middle', kind: 'number', optional: true, placeholder: '1', title: 'Positional factor of the middle third' },
      { name: 'PF lower', kind: 'number', optional: true, placeholder: '0', title: 'Positional factor of the lower third' },
    ],
  },
  {
    directive: 'sun',
    label: 'Sun',
    defaults: ['38', 'summer', '2'],
    fields: [
      { name: 'latitude', kind: 'number', title: 'Latitude in degrees (negative: south)' },
      { name: 'season', kind: 'season', title: 'Season: the sun’s noon altitude' },
      { name: 'angle', kind: 'number', title: 'Degrees per step the upper and middle segments turn to the sun' },
    ],
  },
  {
    directive: 'gravity',
    label: 'Gravity',
    defaults: ['5', '3'],
    fields: [
      { name: 'angle', kind: 'number', title: 'Degrees per step every segment turns down' },
      { name: 'variation', kind: 'number', optional: true, placeholder: '0', title: 'plus Round(Rand() × variation)' },
    ],
  },
  {
    directive: 'wind',
    label: 'Wind',
    defaults: ['1', '0', '2'],
    fields: [
      { name: 'x', kind: 'number', title: 'Wind direction, x' },
      { name: 'z', kind: 'number', title: 'Wind direction, z' },
      { name: 'angle', kind: 'number', title: 'Degrees per step every segment turns with the wind' },
      { name: 'variation', kind: 'number', optional: true, placeholder: '0', title: 'plus Round(Rand() × variation)' },
    ],
  },
  {
    directive: 'apex',
    label: 'Apices',
    defaults: ['A'],
    fields: [{ name: 'modules', kind: 'names', title: 'The modules that are branch apices (default: those with productions that the turtle does not draw)' }],
  },
];

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

/** A text change: replace `from`..`to` by `insert`. */
export interface TextChange {
  from: number;
  to: number;
  insert: string;
}

/** Where a new directive line goes: after the last directive line before the axiom, else before the axiom, else at the end. */
function insertionPoint(text: string): number {
  const axiom = /^[ \t]*axiom\s*:/im.exec(text);
  const head = axiom ? text.slice(0, axiom.index) : text;
  let at = -1;
  const directive = /^[ \t]*#\w+[^\n]*(\n|$)/gm;
  for (let m = directive.exec(head); m; m = directive.exec(head)) at = m.index + m[0].length;
  if (at >= 0) return at;
  return axiom ? axiom.index : text.length;
}

/** The change that switches `attribute` on (with its defaults) or off (its line removed); null when nothing changes. */
export function toggleAttribute(text: string, attribute: GrowthAttribute, on: boolean): TextChange | null {
  const found = findDirective(text, attribute.directive);
  if (on === (found !== null)) return null;
  if (found) return { from: found.lineFrom, to: found.lineTo, insert: '' };
  const at = insertionPoint(text);
  const line = `#${attribute.directive} ${attribute.defaults.join(' ')}`;
  const before = at > 0 && text[at - 1] !== '\n' ? '\n' : '';
  return { from: at, to: at, insert: `${before}${line}\n` };
}

/** Whether `value` may stand as argument `field` (no spaces; numbers finite; a season; names). */
export function validArgument(field: GrowthField, value: string): boolean {
  const v = value.trim();
  if (v === '') return field.optional === true;
  switch (field.kind) {
    case 'number':
      return /^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(v) && Number.isFinite(Number(v));
    case 'expression':
      return /^[\w.+\-*/^()<>=!&|?:,]+$/.test(v);
    case 'season':
      return [...SEASONS, 'equinox', 'fall'].includes(v.toLowerCase());
    case 'names':
      return /^[A-Za-z][\w]*([ \t]+[A-Za-z][\w]*)*$/.test(v);
  }
}

/**
 * The change that sets the arguments of `attribute`'s directive to `values` (one per field; empty
 * optional ones at the end are left out); null when a value is invalid, an optional value is empty
 * before a given one, or nothing changes.
 */
export function setArguments(text: string, attribute: GrowthAttribute, values: string[]): TextChange | null {
  const found = findDirective(text, attribute.directive);
  if (!found) return null;
  const fields = attribute.fields;
  if (values.length !== fields.length || !fields.every((f, i) => validArgument(f, values[i]))) return null;
  const trimmed = values.map((v) => v.trim().replace(/[ \t]+/g, ' '));
  let last = trimmed.length;
  while (last > 0 && trimmed[last - 1] === '') last--;
  if (trimmed.slice(0, last).some((v) => v === '')) return null; // a gap before a given value
  const insert = trimmed.slice(0, last).join(' ');
  if (insert === text.slice(found.from, found.to)) return null;
  return { from: found.from, to: found.to, insert };
}

/** The values of the fields as written (missing ones empty); `names` takes every remaining argument. */
export function argumentValues(attribute: GrowthAttribute, found: FoundDirective): string[] {
  return attribute.fields.map((f, i) => (f.kind === 'names' ? found.args.slice(i).join(' ') : (found.args[i] ?? '')));
}
