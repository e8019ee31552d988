// Completion from the core's vocabulary: `#` directives at the start of a line, keywords, and
// the turtle commands with multi-character names (`@O`, `~l`, `?P`, …), each with its parameters
// and its one-line doc. Ctrl-Space anywhere in a rule lists every turtle command. Inside an
// expression (parameters, conditions, a `#define`'s value) the document's `#define` names.
import { autocompletion, type Completion, type CompletionContext, type CompletionResult } from '@codemirror/autocomplete';
import type { Extension } from '@codemirror/state';
import { argumentsText, paramsText, writtenDirective, writtenKeyword, type Vocabulary } from '../core';
import { defineDirective, defineNames } from './defines';

/** The completion options for the vocabulary, built once per editor. */
export function completionOptions(vocabulary: Vocabulary) {
  const directive: Completion[] = vocabulary.directives.map((d) => ({
    label: writtenDirective(d),
    detail: argumentsText(d),
    info: d.doc,
    type: 'keyword',
    apply: `${writtenDirective(d)} `,
  }));
  const command: Completion[] = vocabulary.modules.map((c) => ({
    label: c.name,
    detail: c.params.length > 0 ? `(${paramsText(c.params)})` : undefined,
    info: c.doc,
    type: 'function',
  }));
  const keyword: Completion[] = vocabulary.keywords.map((k) => ({
    label: writtenKeyword(k),
    info: k.doc,
    type: 'keyword',
    apply: `${writtenKeyword(k)} `,
  }));
  return { directive, command, keyword };
}

/**
 * True when the text before the cursor on its line ends inside an expression: within parentheses
 * (a module's parameters), in a condition (after `) :` and before the arrow), or in a `#define`'s
 * value.
 */
export function inExpression(before: string): boolean {
  const define = defineDirective();
  const afterDefine = before.trimStart();
  if (afterDefine.startsWith(define) && /^\s+\w+\s+/.test(afterDefine.slice(define.length))) return true;
  if (/^\s*#/.test(before)) return false;
  let depth = 0;
  for (const char of before) depth += char === '(' ? 1 : char === ')' ? -1 : 0;
  if (depth > 0) return true;
  return /\)\s*:/.test(before) && !/->|→/.test(before);
}

/** The `#define` names of the document as completions (the value as detail). */
function defineCompletions(text: string, exceptLine: number): Completion[] {
  const seen = new Set<string>();
  const options: Completion[] = [];
  for (const d of defineNames(text)) {
    if (d.line === exceptLine || seen.has(d.name)) continue;
    seen.add(d.name);
    options.push({ label: d.name, detail: `= ${d.value}`, info: `${defineDirective()} ${d.name} ${d.value} (line ${d.line})`, type: 'constant' });
  }
  return options;
}

/** The completion source of the grammar language. */
export function grammarCompletionSource(vocabulary: Vocabulary) {
  const options = completionOptions(vocabulary);
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
    if (inExpression(before)) {
      const word = context.matchBefore(/[A-Za-z_]\w*$/);
      if (!word && !context.explicit) return null;
      const options = defineCompletions(context.state.doc.toString(), line.number);
      if (options.length === 0) return null;
      return { from: word?.from ?? context.pos, options, validFor: /^[A-Za-z_]\w*$/ };
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
export function grammarCompletion(vocabulary: Vocabulary): Extension {
  return autocompletion({ override: [grammarCompletionSource(vocabulary)] });
}
