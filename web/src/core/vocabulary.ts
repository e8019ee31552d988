// The language's vocabulary, as the core declares it (crate/src/vocabulary): the one source of the
// names of modules, directives, keywords, functions and values, with their typed parameters, for
// highlighting, completion, hover docs and the Growth panel. Code refers to a row by its `kind`
// (the core's identifier, e.g. `Define`), never by its spelling, so a name lives in one place.
// It comes as a JSON file the build writes from the whole core (scripts/vocabulary-json.mjs,
// `vocabulary()` of crate/pkg): the first plant's core leaves it and its texts out (issue 22, the
// first load), and the studio loads it after the first plant (`loadVocabulary`).
import vocabularyUrl from '../../../crate/pkg-core/vocabulary.json?url';

/** What a parameter holds. */
export type ParamKind = 'number' | 'whole' | 'stepExpression' | 'expression' | 'season' | 'name' | 'modules' | 'points' | 'ages' | 'surface';

/** One parameter of a module or a directive. */
export interface Param {
  /** Its name in docs and fields (`l`, `MB`, `latitude`). */
  name: string;
  kind: ParamKind;
  /** The value when it is left out: a number, or a directive as written (`#step`). */
  default?: number | string;
  /** The values it may take, inclusive. */
  range?: [number, number];
  /** `degrees`, `steps`, … */
  unit?: string;
  /** A few plain words for a field (`at least` for `MB`); absent: the name says it. */
  label?: string;
  /** What it is or does, in plain words. */
  doc: string;
  /** For a season: the names it accepts. */
  choices?: string[];
}

/** The editor's colour groups of modules. */
export type ModuleCategory = 'move' | 'rotate' | 'branch' | 'polygon' | 'appearance' | 'surface' | 'tropism' | 'query' | 'derivation';

/** A module with a meaning (a turtle command, cut, a control module). */
export interface ModuleInfo {
  /** As written: `F`, `+`, `@O`, `?P`, `~l`. */
  name: string;
  /** The core's identifier of what it does: a turtle command (`Forward`, `Push`), `Cut`, or a control module (`Switch`). */
  meaning: string;
  params: Param[];
  doc: string;
  category: ModuleCategory;
}

/** A `#directive`. */
export interface DirectiveInfo {
  /** The name without `#`. */
  name: string;
  /** The core's identifier (`Lifetime`, `ShapeWidth`); two spellings of one directive share it. */
  kind: string;
  /** A few words for a field or switch (`Length by age`). */
  label: string;
  /** The argument lists it accepts, shortest first. */
  forms: Param[][];
  repeatable: boolean;
  group: 'turtle' | 'derivation' | 'names' | 'limits' | 'growth';
  /** The arguments the studio writes when it switches the directive on. */
  enable?: string[];
  doc: string;
}

/** A word that opens a line (`axiom:`, `homomorphism:`, `endlsystem`). */
export interface KeywordInfo {
  /** Lower case, without the colon. */
  name: string;
  /** The core's identifier (`Axiom`, `MaximumDepth`). */
  kind: string;
  aliases?: string[];
  /** False for `endlsystem`, which stands alone. */
  colon: boolean;
  doc: string;
}

/** A function of expressions. */
export interface FunctionInfo {
  name: string;
  params: string[];
  random: boolean;
  doc: string;
}

/** A value expressions read (`NumIt`, `MaxIt`). */
export interface ValueInfo {
  name: string;
  value: string;
  doc: string;
}

/** The whole vocabulary. */
export interface Vocabulary {
  modules: ModuleInfo[];
  directives: DirectiveInfo[];
  keywords: KeywordInfo[];
  functions: FunctionInfo[];
  values: ValueInfo[];
}

let cached: Vocabulary | undefined;
let loading: Promise<Vocabulary> | undefined;
const arrivals: (() => void)[] = [];

/** Calls `listener` once the vocabulary has arrived (at once if it has), without fetching it. */
export function onVocabulary(listener: () => void): void {
  if (cached) listener();
  else arrivals.push(listener);
}

function arrived(vocabulary: Vocabulary): Vocabulary {
  cached = vocabulary;
  for (const listener of arrivals.splice(0)) listener();
  return vocabulary;
}

/** The language's vocabulary, fetched once (browser); later calls return the same promise. */
export function loadVocabulary(): Promise<Vocabulary> {
  return (loading ??= fetch(vocabularyUrl)
    .then((response) => {
      if (!response.ok) throw new Error(`the vocabulary could not be fetched: HTTP ${response.status}`);
      return response.json() as Promise<Vocabulary>;
    })
    .then(arrived)
    .catch((error: unknown) => {
      loading = undefined; // tried again on the next call
      throw error;
    }));
}

/** Sets the vocabulary without fetching it (node: tests and scripts read it from crate/pkg). */
export function useVocabulary(vocabulary: Vocabulary): void {
  arrived(vocabulary);
  loading = Promise.resolve(vocabulary);
}

/** The vocabulary if it has arrived ({@link loadVocabulary}), else undefined. */
export function vocabularyIfLoaded(): Vocabulary | undefined {
  return cached;
}

/** The language's vocabulary. Requires {@link loadVocabulary} (or {@link useVocabulary}) to have finished. */
export function languageVocabulary(): Vocabulary {
  if (!cached) throw new Error('the vocabulary is used before loadVocabulary() finished');
  return cached;
}

/** The directive of `kind` (its first spelling), e.g. `directiveOfKind(v, 'Define')`. */
export function directiveOfKind(vocabulary: Vocabulary, kind: string): DirectiveInfo {
  const found = vocabulary.directives.find((d) => d.kind === kind);
  if (!found) throw new Error(`the core's vocabulary has no directive ${kind}`);
  return found;
}

/** A directive as written in a grammar: `#angle`. */
export function writtenDirective(directive: DirectiveInfo): string {
  return `#${directive.name}`;
}

/** A keyword as written at the start of a line: `axiom:`, `endlsystem`. */
export function writtenKeyword(keyword: KeywordInfo): string {
  return keyword.colon ? `${keyword.name}:` : keyword.name;
}

/** A module's parameters as docs write them: `l = #step`, `x, y, z`, or '' when it has none. */
export function paramsText(params: readonly Param[]): string {
  return params.map((p) => (p.default === undefined ? p.name : `${p.name} = ${p.default}`)).join(', ');
}

/**
 * A directive's arguments as docs write them: the longest form with its optional tail in brackets
 * (`MB VB [pu pm pl]`, `[VR [PFu PFm PFl]]`), or the forms separated by `|` when one is not the
 * start of the next (`index r g b | first last r g b r g b`).
 */
export function argumentsText(directive: DirectiveInfo): string {
  const names = (form: Param[]) => form.map((p) => p.name);
  const nested = directive.forms.every((form, k) => k === 0 || names(directive.forms[k - 1]).every((n, i) => form[i]?.name === n));
  if (!nested) return directive.forms.map((f) => names(f).join(' ')).join(' | ');
  let text = '';
  for (let k = directive.forms.length - 1; k >= 0; k--) {
    const start = k === 0 ? 0 : directive.forms[k - 1].length;
    const part = names(directive.forms[k]).slice(start).join(' ');
    text = k === 0 ? [part, text].filter(Boolean).join(' ') : `[${[part, text].filter(Boolean).join(' ')}]`;
  }
  return text;
}
