import { describe, expect, it } from 'vitest';
import { highlightTree, tagHighlighter, tags, type Highlighter } from '@lezer/highlight';
import { languageVocabulary } from '../core';
import { grammarLanguage, grammarTags, productionParts } from './language';

// The real vocabulary from the core, so the test follows the Rust table.
const vocabulary = languageVocabulary();

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
  { tag: tags.variableName, class: 'var' },
  { tag: tags.operator, class: 'op' },
  { tag: tags.paren, class: 'paren' },
  { tag: grammarTags.weight, class: 'weight' },
]);

/** The highlighted ranges of `text` under a highlighter, in order. */
function spans(text: string, highlighter: Highlighter): { from: number; to: number; classes: string }[] {
  const tree = grammarLanguage(vocabulary).parser.parse(text);
  const out: { from: number; to: number; classes: string }[] = [];
  highlightTree(tree, highlighter, (from, to, classes) => out.push({ from, to, classes }));
  return out;
}

/** The highlighted tokens of `text` as `class:text` strings, in order. */
function tokens(text: string): string[] {
  return spans(text, names).map(({ from, to, classes }) => `${classes}:${text.slice(from, to)}`);
}

describe('grammar highlighting', () => {
  // [what, text, its tokens]
  it.each<[string, string, string[]]>([
    [
      'classifies every part of a grammar',
      '// Fig 1.24d\n#angle 20\naxiom: X\np1: X -> F[+X]-X\nF --> FF\nA → B',
      // adjacent tokens of one class form one highlighted range: turtle:FF
      ['comment:// Fig 1.24d', 'directive:#angle', 'number:20', 'keyword:axiom', 'module:X', 'label:p1', 'module:X', 'arrow:->', 'turtle:F', 'bracket:[', 'turtle:+', 'module:X', 'bracket:]', 'turtle:-', 'module:X', 'turtle:F', 'arrow:-->', 'turtle:FF', 'module:A', 'arrow:→', 'module:B'],
    ],
    [
      'tells turtle commands from other modules',
      'f & ^ \\ / | G A',
      ['turtle:f', 'turtle:&', 'turtle:^', 'turtle:\\', 'turtle:/', 'turtle:|', 'turtle:G', 'module:A'],
    ],
    ['tells the turtle modules from the others', '~l @O @Gc ?P X', ['turtle:~l', 'turtle:@O', 'turtle:@Gc', 'turtle:?P', 'module:X']],
    [
      'reads parameters and conditions as expressions',
      'A(x,y) : x >= 2*y -> F(x*0.5)+(30)A(-x)',
      ['module:A', 'paren:(', 'var:x', 'op:,', 'var:y', 'paren:)', 'var:x', 'op:>=', 'number:2', 'op:*', 'var:y', 'arrow:->', 'turtle:F', 'paren:(', 'var:x', 'op:*', 'number:0.5', 'paren:)', 'turtle:+', 'paren:(', 'number:30', 'paren:)', 'module:A', 'paren:(', 'op:-', 'var:x', 'paren:)'],
    ],
    [
      'reads a weight as an expression',
      'F -> (0.25) F[+F]',
      ['turtle:F', 'arrow:->', 'paren weight:(', 'number weight:0.25', 'paren weight:)', 'turtle:F', 'bracket:[', 'turtle:+F', 'bracket:]'],
    ],
    ['ends a production at a trailing comment', 'X -> F // grow', ['module:X', 'arrow:->', 'turtle:F', 'comment:// grow']],
  ])('%s', (_, text, expected) => {
    expect(tokens(text)).toEqual(expected);
  });
});

/** A highlighter that names only the production parts. */
const parts = tagHighlighter([
  { tag: grammarTags.leftContext, class: 'L' },
  { tag: grammarTags.predecessor, class: 'P' },
  { tag: grammarTags.rightContext, class: 'R' },
  { tag: grammarTags.condition, class: 'C' },
]);

/** The production parts of `text` as `part:text` strings; adjacent tokens of one part are joined: the part is one highlighted run. */
function partTokens(text: string): string[] {
  const out: string[] = [];
  let last = { classes: '', to: -1 };
  for (const { from, to, classes } of spans(text, parts)) {
    if (classes === last.classes && from === last.to) out[out.length - 1] += text.slice(from, to);
    else out.push(`${classes}:${text.slice(from, to)}`);
    last = { classes, to };
  }
  return out;
}

describe('the parts of a context-sensitive production', () => {
  it('splits left context, strict predecessor, right context and condition, outside parentheses', () => {
    expect(productionParts('A(x) < B(y) > C : x > y -> D')).toEqual({ less: 5, greater: 12, colon: 16, arrow: 24, start: 0 });
    expect(productionParts('p2: b < a -> b')).toMatchObject({ less: 6, greater: -1, colon: -1, start: 3 });
    expect(productionParts('axiom: F')).toBeNull();
    expect(productionParts('// a -> b')).toBeNull();
  });

  it('gives each part its own highlight, and leaves the successor alone', () => {
    expect(partTokens('axiom: A\nA(x) < B(y) > [C]D : x > y -> D(x)')).toEqual([
      'L:A(x)',
      'P:B(y)',
      'R:[C]D',
      'C:x',
      'C:>', // an operator inside the condition is still condition
      'C:y',
    ]);
    expect(partTokens('axiom: A\nb < a -> b')).toEqual(['L:b', 'P:a']);
    expect(partTokens('axiom: A\nF -> FF')).toEqual(['P:F']);
  });
});
