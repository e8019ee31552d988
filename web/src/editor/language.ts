// Syntax highlighting of the grammar language as a CodeMirror StreamLanguage, driven by the core's
// vocabulary (so a command added in Rust is highlighted without touching this file).
import { HighlightStyle, StreamLanguage, syntaxHighlighting, type StringStream, type TagStyle } from '@codemirror/language';
import type { Extension } from '@codemirror/state';
import { Tag, tags } from '@lezer/highlight';
import type { Vocabulary } from '../core';

/** Highlight tags of the grammar language beyond the standard ones. */
export const grammarTags = {
  /** A turtle command such as `F` or `+`. */
  turtleCommand: Tag.define(tags.operatorKeyword),
  /** Any other module (`X`, `A`, …): rewritten by productions, ignored by the turtle. */
  module: Tag.define(tags.variableName),
  /** A production arrow: `->`, `-->`, `→`. */
  arrow: Tag.define(tags.definitionOperator),
  /** A directive such as `#angle`. */
  directive: Tag.define(tags.meta),
  /** The parts of a production before its arrow: left context, strict predecessor, right context, condition. */
  leftContext: Tag.define(),
  predecessor: Tag.define(),
  rightContext: Tag.define(),
  condition: Tag.define(),
  /** A stochastic production's weight, `(0.33)` after the arrow. */
  weight: Tag.define(),
};

/** Where the parts of a production's left-hand side lie in its line (offsets into the line). */
export interface ProductionParts {
  /** The `<` ending the left context, or -1. */
  less: number;
  /** The `>` starting the right context, or -1. */
  greater: number;
  /** The `:` starting the condition, or -1. */
  colon: number;
  /** Where the arrow starts. */
  arrow: number;
  /** Where the left-hand side starts (after a label). */
  start: number;
}

const ARROW = /-->|->|→/;

/**
 * Splits a production line into its parts: `left < pred > right : condition -> successor`, with
 * a leading `label:` skipped (unless it is one of `keywords`, e.g. `axiom`). Only `<`, `>` and `:`
 * outside parentheses count. Null when the line has no arrow (not a production).
 */
export function productionParts(line: string, keywords: ReadonlySet<string> = new Set()): ProductionParts | null {
  const arrowMatch = ARROW.exec(line);
  if (!arrowMatch) return null;
  const comment = line.indexOf('//');
  if (comment >= 0 && comment < arrowMatch.index) return null;
  const arrow = arrowMatch.index;
  const label = /^\s*[A-Za-z_]\w*\s*:/.exec(line);
  const isKeyword = label !== null && keywords.has(label[0].replace(':', '').trim().toLowerCase());
  const start = label && !isKeyword && label[0].length <= arrow ? label[0].length : 0;
  let less = -1;
  let greater = -1;
  let colon = -1;
  let depth = 0;
  for (let i = start; i < arrow; i++) {
    const c = line[i];
    if (c === '(') depth++;
    else if (c === ')') depth = Math.max(0, depth - 1);
    else if (depth === 0 && colon < 0) {
      if (c === ':') colon = i;
      else if (c === '<' && less < 0 && greater < 0) less = i;
      else if (c === '>' && greater < 0) greater = i;
    }
  }
  return { less, greater, colon, arrow, start };
}

/** Tokenizer state; the flags are reset at every line start. */
interface LineState {
  /** Inside a `#directive` line: the rest is arguments. */
  directive: boolean;
  /** No token has been read on this line yet. */
  atLineStart: boolean;
  /** The parts of the production on this line, if it is one. */
  parts: ProductionParts | null;
  /** Parenthesis depth: inside parentheses are expressions (parameters, weights). */
  depth: number;
  /** The arrow has been read and nothing else yet: a `(` now opens the production's weight. */
  afterArrow: boolean;
  /** Inside the weight's parentheses. */
  weight: boolean;
}

/** Operators of expressions (LANGUAGE.md section 4), longest first. */
const OPERATOR = /^(&&|\|\||==|!=|<=|>=|[-+*/^<>!?%,:=])/;

/** The part of the production a token at `pos` belongs to (a tag name of the token table), if any. */
function partAt(parts: ProductionParts | null, pos: number): string | null {
  if (!parts || pos >= parts.arrow || pos < parts.start) return null;
  if (pos === parts.less || pos === parts.greater || pos === parts.colon) return null;
  if (parts.colon >= 0 && pos > parts.colon) return 'condition';
  if (parts.less >= 0 && pos < parts.less) return 'leftContext';
  if (parts.greater >= 0 && pos > parts.greater) return 'rightContext';
  return 'predecessor';
}

const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]*/;

/** The tokenizer for a vocabulary: module names sorted longest first so the longest wins. */
function tokenizer(vocabulary: Vocabulary) {
  const modules = vocabulary.modules;
  const names = modules.map((c) => c.name).sort((a, b) => b.length - a.length);
  const category = new Map(modules.map((c) => [c.name, c.category]));
  // Keywords with a colon stand at the start of a line, like production labels.
  const keywords = new Set(vocabulary.keywords.filter((k) => k.colon).flatMap((k) => [k.name, ...(k.aliases ?? [])]));

  const token = (stream: StringStream, state: LineState): string | null => {
    if (stream.sol()) {
      state.directive = false;
      state.atLineStart = true;
      const text = stream.string;
      state.parts = /^\s*(#|\/\/)/.test(text) ? null : productionParts(text, keywords);
      state.depth = 0;
      state.afterArrow = false;
      state.weight = false;
    }
    if (stream.eatSpace()) return null;
    const first = state.atLineStart;
    state.atLineStart = false;
    const afterArrow = state.afterArrow;
    state.afterArrow = false;

    if (stream.match('//')) {
      stream.skipToEnd();
      return 'comment';
    }
    if (first && stream.match(/^#[A-Za-z_]\w*/)) {
      state.directive = true;
      return 'directive';
    }
    if (stream.match(state.directive ? /^-?\d+(\.\d+)?/ : /^\d+(\.\d+)?/)) return state.weight ? 'number weight' : 'number';
    if (state.directive) {
      if (!stream.match(/^[^\s/]+/)) stream.next();
      return 'string';
    }
    if (first) {
      // `axiom:` and production labels (`p1:`) stand at the start of a line, before a colon.
      const word = stream.match(IDENTIFIER, false) as RegExpMatchArray | null;
      if (word && stream.string.slice(stream.pos + word[0].length).trimStart().startsWith(':')) {
        stream.match(IDENTIFIER);
        return keywords.has(word[0].toLowerCase()) ? 'keyword' : 'labelName';
      }
    }
    if (state.depth === 0 && (stream.match('-->') || stream.match('->') || stream.match('→'))) {
      state.afterArrow = true;
      return 'arrow';
    }
    if (stream.match('(')) {
      if (afterArrow && state.depth === 0) state.weight = true;
      state.depth++;
      return state.weight ? 'paren weight' : 'paren';
    }
    if (stream.match(')')) {
      const weight = state.weight;
      state.depth = Math.max(0, state.depth - 1);
      if (state.depth === 0) state.weight = false;
      return weight ? 'paren weight' : 'paren';
    }
    // Expressions: parameters and weights inside parentheses, and the condition.
    const inCondition = state.parts !== null && state.parts.colon >= 0 && stream.pos > state.parts.colon && stream.pos < state.parts.arrow;
    if (state.depth > 0 || inCondition) {
      const weight = state.weight ? ' weight' : '';
      if (stream.match(/^\d*\.?\d+([eE][-+]?\d+)?/)) return `number${weight}`;
      if (stream.match(IDENTIFIER)) return `variableName${weight}`;
      if (stream.match(OPERATOR)) return `operator${weight}`;
    }
    if (stream.match(':')) return 'punctuation';
    const command = names.find((name) => stream.match(name));
    if (command !== undefined) return category.get(command) === 'branch' ? 'squareBracket' : 'turtleCommand';
    stream.next();
    return 'module';
  };
  // Each token before the arrow also carries the part of the production it is in.
  return (stream: StringStream, state: LineState): string | null => {
    const start = stream.pos;
    const style = token(stream, state);
    const part = partAt(state.parts, start);
    if (!part || !style || style === 'comment') return style;
    return `${style} ${part}`;
  };
}

/** The grammar language (`.lsys`) for CodeMirror, with `//` line comments, for a vocabulary. */
export function grammarLanguage(vocabulary: Vocabulary): StreamLanguage<LineState> {
  return StreamLanguage.define<LineState>({
    name: 'lsystem',
    startState: () => ({ directive: false, atLineStart: true, parts: null, depth: 0, afterArrow: false, weight: false }),
    copyState: (state) => ({ ...state }),
    token: tokenizer(vocabulary),
    tokenTable: {
      turtleCommand: grammarTags.turtleCommand,
      module: grammarTags.module,
      arrow: grammarTags.arrow,
      directive: grammarTags.directive,
      leftContext: grammarTags.leftContext,
      predecessor: grammarTags.predecessor,
      rightContext: grammarTags.rightContext,
      condition: grammarTags.condition,
      weight: grammarTags.weight,
    },
    languageData: { commentTokens: { line: '//' } },
  });
}

/** A token in its colour, the CSS variable `--tok-<colour>` (styles/page.css), with any other style. */
function coloured(tag: Tag, colour: string, style: Omit<TagStyle, 'tag'> = {}): TagStyle {
  return { tag, color: `var(--tok-${colour})`, ...style };
}

/** A part of a context-sensitive production: a band of its side's highlight colour, underlined. */
function contextBand(tag: Tag, side: 'left' | 'right'): TagStyle {
  return {
    tag,
    backgroundColor: `color-mix(in srgb, var(--hl-${side}) 22%, transparent)`,
    borderBottom: `2px solid var(--hl-${side})`,
  };
}

const bold = { fontWeight: '600' };
const italic = { fontStyle: 'italic' };

/** Colours of the grammar's tokens; CSS variables (see styles/page.css) so light and dark both work. */
export const grammarHighlightStyle = HighlightStyle.define([
  coloured(tags.comment, 'comment', italic),
  coloured(grammarTags.directive, 'directive', bold),
  coloured(tags.string, 'string'),
  coloured(tags.keyword, 'keyword', bold),
  coloured(tags.labelName, 'label'),
  coloured(grammarTags.arrow, 'arrow', bold),
  coloured(tags.number, 'number'),
  coloured(tags.squareBracket, 'bracket', bold),
  coloured(grammarTags.turtleCommand, 'turtle'),
  coloured(grammarTags.module, 'module', bold),
  // The parts of a context-sensitive production, in the colours the 3D view and the panel use.
  contextBand(grammarTags.leftContext, 'left'),
  contextBand(grammarTags.rightContext, 'right'),
  { tag: grammarTags.predecessor, textDecoration: 'underline 2px var(--hl-produced)' },
  coloured(tags.variableName, 'variable', italic),
  coloured(tags.operator, 'operator'),
  { tag: grammarTags.weight, backgroundColor: 'color-mix(in srgb, var(--tok-number) 14%, transparent)', borderRadius: '3px' },
  { tag: grammarTags.condition, ...italic, backgroundColor: 'color-mix(in srgb, var(--muted) 12%, transparent)' },
]);

/** The language plus its highlighting, as one editor extension. */
export function grammarSupport(vocabulary: Vocabulary): Extension {
  return [grammarLanguage(vocabulary), syntaxHighlighting(grammarHighlightStyle)];
}
