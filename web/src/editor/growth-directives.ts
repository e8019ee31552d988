// The growth directives of a grammar's text (the vocabulary's growth group, docs/LANGUAGE.md
// "Growth: particle attributes"), read and rewritten for the studio's Growth panel: one directive
// per line, its arguments separated by spaces (expressions are written without spaces), a `//`
// comment after them kept. Their arguments, defaults and labels come from the core's vocabulary.
import { languageVocabulary, type Param, type Vocabulary } from '../core';
import { directiveHoverText } from './hover-text';
import { findDirective, type FoundDirective } from './directive-lines';

/** One argument of a directive, as the panel edits it. */
export interface GrowthField {
  /** The paper's name (`MB`, `PFu`). */
  name: string;
  /** A few plain words for it (`at least`, `upper third`). */
  label: string;
  /** `number`: a number; `expression`: a number or an expression of NumIt, MaxIt and #defines; `season`; `names`: module names. */
  kind: 'number' | 'expression' | 'season' | 'names';
  /** Omitted arguments at the end take the core's defaults (shown as placeholders). */
  optional?: boolean;
  /** The core's default, for an optional argument. */
  placeholder?: string;
  /** What it does, in a sentence (the field's tooltip). */
  title: string;
  /** For a season: the names the core accepts. */
  choices?: string[];
}

/** A growth attribute: its directive, its arguments, and what enabling it writes. */
export interface GrowthAttribute {
  /** The directive's name (without `#`). */
  directive: string;
  label: string;
  /** What switching it on does, in a sentence (the switch's tooltip). */
  title: string;
  fields: GrowthField[];
  /** The arguments written when the attribute is switched on. */
  defaults: string[];
}

/** The panel's kind of field for a parameter of the vocabulary. */
function fieldKind(param: Param): GrowthField['kind'] {
  switch (param.kind) {
    case 'stepExpression':
    case 'expression':
      return 'expression';
    case 'season':
      return 'season';
    case 'modules':
    case 'name':
      return 'names';
    default:
      return 'number';
  }
}

/** A field's tooltip: `MB: How many … at least. Default 0.6.` (with the unit, if any). */
function fieldTitle(param: Param): string {
  const unit = param.unit ? ` ${param.unit}` : '';
  const byDefault = param.default === undefined ? '' : ` Default ${param.default}${unit}.`;
  return `${param.name}: ${param.doc}${byDefault}`;
}

/**
 * The growth attributes, read off the core's vocabulary: its directives of the growth group, each
 * with the fields of its longest form (those beyond its shortest form optional, with the core's
 * defaults as placeholders) and the arguments the core suggests writing when it is switched on.
 */
export function growthAttributes(vocabulary: Vocabulary): GrowthAttribute[] {
  return vocabulary.directives
    .filter((d) => d.group === 'growth')
    .map((d) => {
      const shortest = Math.min(...d.forms.map((f) => f.length));
      const longest = d.forms.reduce((a, b) => (b.length > a.length ? b : a), [] as Param[]);
      return {
        directive: d.name,
        label: d.label,
        title: directiveHoverText(d),
        defaults: d.enable ?? [],
        fields: longest.map((p, k) => ({
          name: p.name,
          label: p.label ?? p.name,
          kind: fieldKind(p),
          optional: k >= shortest || undefined,
          placeholder: p.default === undefined ? undefined : String(p.default),
          title: fieldTitle(p),
          choices: p.choices,
        })),
      };
    });
}

/** A text change: replace `from`..`to` by `insert`. */
export interface TextChange {
  from: number;
  to: number;
  insert: string;
}

let axiomPattern: RegExp | undefined;

/** A line that starts with the axiom keyword (any of its spellings, any case). */
function axiomLine(): RegExp {
  const keyword = languageVocabulary().keywords.find((k) => k.kind === 'Axiom');
  const spellings = [keyword?.name ?? '', ...(keyword?.aliases ?? [])].filter(Boolean);
  axiomPattern ??= new RegExp(String.raw`^[ \t]*(?:${spellings.join('|')})\s*:`, 'im');
  return axiomPattern;
}

/** Where a new directive line goes: after the last directive line before the axiom, else before the axiom, else at the end. */
function insertionPoint(text: string): number {
  const axiom = axiomLine().exec(text);
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
      return (field.choices ?? []).includes(v.toLowerCase());
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
