// Syntax highlighting of the grammar language as a CodeMirror StreamLanguage, driven by the core's
// turtle command table (so a command added in Rust is highlighted without touching this file).
import { HighlightStyle, StreamLanguage, syntaxHighlighting, type StringStream } from '@codemirror/language';
import type { Extension } from '@codemirror/state';
import { Tag, tags } from '@lezer/highlight';
import type { TurtleCommand } from '../core';

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
};

/** Tokenizer state; the flags are reset at every line start. */
interface LineState {
  /** Inside a `#directive` line: the rest is arguments. */
  directive: boolean;
  /** No token has been read on this line yet. */
  atLineStart: boolean;
}

const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]*/;

/** The tokenizer for a given command table: names sorted longest first so the longest wins. */
function tokenizer(commands: readonly TurtleCommand[]) {
  const names = commands.map((c) => c.name).sort((a, b) => b.length - a.length);
  const category = new Map(commands.map((c) => [c.name, c.category]));

  return (stream: StringStream, state: LineState): string | null => {
    if (stream.sol()) {
      state.directive = false;
      state.atLineStart = true;
    }
    if (stream.eatSpace()) return null;
    const first = state.atLineStart;
    state.atLineStart = false;

    if (stream.match('//')) {
      stream.skipToEnd();
      return 'comment';
    }
    if (first && stream.match(/^#[A-Za-z_]\w*/)) {
      state.directive = true;
      return 'directive';
    }
    if (stream.match(state.directive ? /^-?\d+(\.\d+)?/ : /^\d+(\.\d+)?/)) return 'number';
    if (state.directive) {
      if (!stream.match(/^[^\s/]+/)) stream.next();
      return 'string';
    }
    if (first) {
      // `axiom:` and production labels (`p1:`) stand at the start of a line, before a colon.
      const word = stream.match(IDENTIFIER, false) as RegExpMatchArray | null;
      if (word && stream.string.slice(stream.pos + word[0].length).trimStart().startsWith(':')) {
        stream.match(IDENTIFIER);
        return word[0] === 'axiom' ? 'keyword' : 'labelName';
      }
    }
    if (stream.match('-->') || stream.match('->') || stream.match('→')) return 'arrow';
    if (stream.match(':')) return 'punctuation';
    if (stream.match('(') || stream.match(')')) return 'paren';
    const command = names.find((name) => stream.match(name));
    if (command !== undefined) return category.get(command) === 'branch' ? 'squareBracket' : 'turtleCommand';
    stream.next();
    return 'module';
  };
}

/** The grammar language (`.lsys`) for CodeMirror, with `//` line comments, for a command table. */
export function grammarLanguage(commands: readonly TurtleCommand[]): StreamLanguage<LineState> {
  return StreamLanguage.define<LineState>({
    name: 'lsystem',
    startState: () => ({ directive: false, atLineStart: true }),
    copyState: (state) => ({ ...state }),
    token: tokenizer(commands),
    tokenTable: {
      turtleCommand: grammarTags.turtleCommand,
      module: grammarTags.module,
      arrow: grammarTags.arrow,
      directive: grammarTags.directive,
    },
    languageData: { commentTokens: { line: '//' } },
  });
}

/** Colours of the grammar's tokens; CSS variables (see style.css) so light and dark both work. */
export const grammarHighlightStyle = HighlightStyle.define([
  { tag: tags.comment, color: 'var(--tok-comment)', fontStyle: 'italic' },
  { tag: grammarTags.directive, color: 'var(--tok-directive)', fontWeight: '600' },
  { tag: tags.string, color: 'var(--tok-string)' },
  { tag: tags.keyword, color: 'var(--tok-keyword)', fontWeight: '600' },
  { tag: tags.labelName, color: 'var(--tok-label)' },
  { tag: grammarTags.arrow, color: 'var(--tok-arrow)', fontWeight: '600' },
  { tag: tags.number, color: 'var(--tok-number)' },
  { tag: tags.squareBracket, color: 'var(--tok-bracket)', fontWeight: '600' },
  { tag: grammarTags.turtleCommand, color: 'var(--tok-turtle)' },
  { tag: grammarTags.module, color: 'var(--tok-module)', fontWeight: '600' },
]);

/** The language plus its highlighting, as one editor extension. */
export function grammarSupport(commands: readonly TurtleCommand[]): Extension {
  return [grammarLanguage(commands), syntaxHighlighting(grammarHighlightStyle)];
}
