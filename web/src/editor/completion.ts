// Completion from the core's tables: `#` directives at the start of a line, section keywords, and
// the turtle commands with multi-character names (`@O`, `~l`, `?P`, …), each with its parameters
// and its one-line doc. Ctrl-Space anywhere in a rule lists every turtle command.
import { autocompletion, type Completion, type CompletionContext, type CompletionResult } from '@codemirror/autocomplete';
import type { Extension } from '@codemirror/state';
import type { GrammarDirective, TurtleCommand } from '../core';

/** Words that open a line of their own (docs/LANGUAGE.md). */
const KEYWORDS: readonly { label: string; info: string }[] = [
  { label: 'axiom:', info: 'The initial string ω (also written ω:).' },
  { label: 'homomorphism:', info: 'Start the rules that rewrite the string for the turtle only.' },
  { label: 'decomposition:', info: 'Start the rules applied after each step until nothing changes.' },
  { label: 'maximum depth:', info: 'The depth limit of the homomorphism or decomposition section above.' },
  { label: 'derivation length:', info: 'The number of derivation steps (as #iterations).' },
  { label: 'endlsystem', info: 'End of the grammar: later lines are ignored.' },
];

/** The completion options for the tables, built once per editor. */
export function completionOptions(commands: readonly TurtleCommand[], directives: readonly GrammarDirective[]) {
  const directive: Completion[] = directives.map((d) => ({
    label: `#${d.name}`,
    detail: d.args,
    info: d.doc,
    type: 'keyword',
    apply: `#${d.name} `,
  }));
  const command: Completion[] = commands.map((c) => ({
    label: c.name,
    detail: c.params.length > 0 ? `(${c.params.join(', ')})` : undefined,
    info: c.doc,
    type: 'function',
  }));
  const keyword: Completion[] = KEYWORDS.map((k) => ({ label: k.label, info: k.info, type: 'keyword', apply: `${k.label} ` }));
  return { directive, command, keyword };
}

/** The completion source of the grammar language. */
export function grammarCompletionSource(commands: readonly TurtleCommand[], directives: readonly GrammarDirective[]) {
  const options = completionOptions(commands, directives);
  return (context: CompletionContext): CompletionResult | null => {
    const line = context.state.doc.lineAt(context.pos);
    const before = line.text.slice(0, context.pos - line.from);
    if (before.includes('//')) return null;
    const directive = /^\s*(#\w*)$/.exec(before);
    if (directive) {
      return { from: context.pos - directive[1].length, options: options.directive, validFor: /^#\w*$/ };
    }
    const keyword = /^\s*([a-z][a-z ]*)$/.exec(before);
    if (keyword && (keyword[1].length >= 2 || context.explicit)) {
      const word = keyword[1];
      const matching = options.keyword.filter((k) => k.label.startsWith(word));
      if (matching.length > 0) return { from: context.pos - word.length, options: matching };
    }
    // A multi-character command starts with @, ~ or ?.
    const special = context.matchBefore(/[@~?][A-Za-z]*$/);
    if (special) {
      const prefix = special.text[0];
      return {
        from: special.from,
        options: options.command.filter((c) => c.label.startsWith(prefix) && c.label.length > 1),
        validFor: /^[@~?][A-Za-z]*$/,
      };
    }
    if (context.explicit) return { from: context.pos, options: options.command };
    return null;
  };
}

/** Completion as one editor extension. */
export function grammarCompletion(commands: readonly TurtleCommand[], directives: readonly GrammarDirective[]): Extension {
  return autocompletion({ override: [grammarCompletionSource(commands, directives)] });
}
