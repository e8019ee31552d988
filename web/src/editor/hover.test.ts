import { readFileSync } from 'node:fs';
import { expect, it } from 'vitest';
import { initCore, turtleCommands } from '../core';
import { commandHoverText, directiveHoverText, tokenClass } from './hover';
import { grammarLanguage } from './language';

it('describes a command with its parameters', () => {
  expect(commandHoverText({ name: 'F', params: [], doc: 'Move forward.', category: 'move' })).toBe('F — Move forward.');
  expect(commandHoverText({ name: '!', params: ['w'], doc: 'Set the width.', category: 'width' })).toBe(
    '!(w) — Set the width.',
  );
});

it('finds commands by the syntax node names the grammar language produces', async () => {
  await initCore(readFileSync(new URL('../../../crate/pkg/meristem_bg.wasm', import.meta.url)));
  const tree = grammarLanguage(turtleCommands()).parser.parse('X -> F[+X]');
  const names: string[] = [];
  tree.iterate({ enter: (node) => void names.push(node.name) });
  expect(names).toEqual(expect.arrayContaining(['turtleCommand', 'squareBracket', 'arrow', 'module']));
});

it('describes a directive with its arguments', () => {
  expect(directiveHoverText({ name: 'tropism', args: 'x y z e', doc: 'The tropism vector.' })).toBe(
    '#tropism x y z e — The tropism vector.',
  );
});

it('finds a command in a predecessor, whose node also names the production part', async () => {
  await initCore(readFileSync(new URL('../../../crate/pkg/meristem_bg.wasm', import.meta.url)));
  const tree = grammarLanguage(turtleCommands()).parser.parse('axiom: F\nF < F -> FF');
  const names: string[] = [];
  tree.iterate({ enter: (node) => void names.push(node.name) });
  expect(names).toEqual(expect.arrayContaining(['turtleCommand_leftContext', 'turtleCommand_predecessor']));
  expect(names.map(tokenClass)).toEqual(expect.arrayContaining(['turtleCommand', 'directive'].slice(0, 1)));
});
