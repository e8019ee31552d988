import { expect, it } from 'vitest';
import { languageVocabulary } from '../core';
import { commandHoverText, directiveHoverText, tokenClass } from './hover';
import { grammarLanguage } from './language';

const vocabulary = languageVocabulary();
const module = (name: string) => vocabulary.modules.find((m) => m.name === name)!;

it('describes a command with its parameters and their defaults', () => {
  expect(commandHoverText({ name: 'X', params: [], doc: 'Move forward.' })).toBe('X — Move forward.');
  expect(commandHoverText(module('F'))).toBe('F(l = #step) — Move forward by l and draw a segment.');
  expect(commandHoverText(module('!'))).toBe('!(w) — Set the width to w; without w, decrease it by #width_step.');
});

it('finds commands by the syntax node names the grammar language produces', async () => {
  const tree = grammarLanguage(vocabulary).parser.parse('X -> F[+X]');
  const names: string[] = [];
  tree.iterate({ enter: (node) => void names.push(node.name) });
  expect(names).toEqual(expect.arrayContaining(['turtleCommand', 'squareBracket', 'arrow', 'module']));
});

it('describes a directive with its arguments, optional ones in brackets', () => {
  const directive = (name: string) => vocabulary.directives.find((d) => d.name === name)!;
  expect(directiveHoverText(directive('tropism'))).toBe(
    '#tropism x y z e — The tropism vector T and susceptibility e (ABOP 2.3; default 0 -1 0 0).',
  );
  expect(directiveHoverText(directive('lifetime'))).toMatch(/^#lifetime MB VB \[pu pm pl\] — /);
  expect(directiveHoverText(directive('shape_width'))).toMatch(/^#shape_width \[VR \[PFu PFm PFl\]\] — /);
  expect(directiveHoverText(directive('color'))).toMatch(/^#color index r g b \| first last r g b r g b — /);
});

it('finds a command in a predecessor, whose node also names the production part', async () => {
  const tree = grammarLanguage(vocabulary).parser.parse('axiom: F\nF < F -> FF');
  const names: string[] = [];
  tree.iterate({ enter: (node) => void names.push(node.name) });
  expect(names).toEqual(expect.arrayContaining(['turtleCommand_leftContext', 'turtleCommand_predecessor']));
  expect(names.map(tokenClass)).toEqual(expect.arrayContaining(['turtleCommand', 'directive'].slice(0, 1)));
});
