import { describe, expect, it } from 'vitest';
import { highlightTree, tagHighlighter, tags } from '@lezer/highlight';
import { readFileSync } from 'node:fs';
import { initCore, turtleCommands, type TurtleCommand } from '../core';
import { grammarLanguage, grammarTags } from './language';

// The real command table from the core, so the test follows the Rust table.
await initCore(readFileSync(new URL('../../../crate/pkg/meristem_bg.wasm', import.meta.url)));
const commands: TurtleCommand[] = turtleCommands();

/** A highlighter that names each token class, so tests read like the language. */
const names = tagHighlighter([
  { tag: tags.comment, class: 'comment' },
  { tag: grammarTags.directive, class: 'directive' },
  { tag: tags.keyword, class: 'keyword' },
  { tag: tags.labelName, class: 'label' },
  { tag: grammarTags.arrow, class: 'arrow' },
  { tag: tags.number, class: 'number' },
  { tag: tags.squareBracket, class: 'bracket' },
  { tag: grammarTags.turtleCommand, class: 'turtle' },
  { tag: grammarTags.module, class: 'module' },
  { tag: tags.string, class: 'string' },
]);

/** The highlighted tokens of `text` as `class:text` strings, in order. */
function tokens(text: string): string[] {
  const tree = grammarLanguage(commands).parser.parse(text);
  const out: string[] = [];
  highlightTree(tree, names, (from, to, classes) => out.push(`${classes}:${text.slice(from, to)}`));
  return out;
}

describe('grammar highlighting', () => {
  it('classifies every part of a grammar', () => {
    expect(tokens('// Fig 1.24d\n#angle 20\naxiom: X\np1: X -> F[+X]-X\nF --> FF\nA → B')).toEqual([
      'comment:// Fig 1.24d',
      'directive:#angle',
      'number:20',
      'keyword:axiom',
      'module:X',
      'label:p1',
      'module:X',
      'arrow:->',
      'turtle:F',
      'bracket:[',
      'turtle:+',
      'module:X',
      'bracket:]',
      'turtle:-',
      'module:X',
      'turtle:F',
      'arrow:-->',
      'turtle:FF', // adjacent tokens of one class form one highlighted range
      'module:A',
      'arrow:→',
      'module:B',
    ]);
  });

  it('tells turtle commands from other modules', () => {
    expect(tokens('f & ^ \\ / | G A')).toEqual([
      'turtle:f',
      'turtle:&',
      'turtle:^',
      'turtle:\\',
      'turtle:/',
      'turtle:|',
      'turtle:G',
      'module:A',
    ]);
    expect(tokens('~l @O @Gc ?P X')).toEqual(['turtle:~l', 'turtle:@O', 'turtle:@Gc', 'turtle:?P', 'module:X']);
  });

  it('ends a production at a trailing comment', () => {
    expect(tokens('X -> F // grow')).toEqual(['module:X', 'arrow:->', 'turtle:F', 'comment:// grow']);
  });
});
