import { describe, expect, it } from 'vitest';
import { languageVocabulary } from '../core';
import { findDirective } from './directive-lines';
import { argumentValues, growthAttributes, setArguments, toggleAttribute, validArgument, type TextChange } from './growth-directives';

const attribute = (name: string) => growthAttributes(languageVocabulary()).find((a) => a.directive === name)!;
const apply = (text: string, change: TextChange | null) => (change ? text.slice(0, change.from) + change.insert + text.slice(change.to) : text);

const TREE = '// A tree\n#angle 30\n#iterations 5\naxiom: F A\nA -> F[+A][-A]\n';

describe('growth directives in the text', () => {
  it('switches an attribute on after the last directive before the axiom, and off again', () => {
    const on = apply(TREE, toggleAttribute(TREE, attribute('lifetime'), true));
    expect(on).toBe('// A tree\n#angle 30\n#iterations 5\n#lifetime 34 32\naxiom: F A\nA -> F[+A][-A]\n');
    expect(toggleAttribute(on, attribute('lifetime'), true)).toBeNull();
    expect(apply(on, toggleAttribute(on, attribute('lifetime'), false))).toBe(TREE);
    // No directive at all: before the axiom; no axiom: at the end.
    expect(apply('axiom: A\n', toggleAttribute('axiom: A\n', attribute('sun'), true))).toBe('#sun 38 summer 2\naxiom: A\n');
    expect(apply('// only a comment', toggleAttribute('// only a comment', attribute('gravity'), true))).toBe('// only a comment\n#gravity 5 3\n');
  });

  it('finds a directive with a comment and reads its arguments by field', () => {
    const text = '#lifetime   NumIt<3?64:34 32 0.5  // the paper\naxiom: A';
    const found = findDirective(text, 'lifetime')!;
    expect(found.args).toEqual(['NumIt<3?64:34', '32', '0.5']);
    expect(argumentValues(attribute('lifetime'), found)).toEqual(['NumIt<3?64:34', '32', '0.5', '', '']);
    expect(text.slice(found.from, found.to)).toBe('NumIt<3?64:34 32 0.5');
    // #shape is not #shape_width.
    expect(findDirective('#shape_width 1\n', 'shape')).toBeNull();
    expect(argumentValues(attribute('apex'), findDirective('#apex A B\n', 'apex')!)).toEqual(['A B']);
  });

  it('rewrites the arguments, keeping the comment, and refuses what the core would not read', () => {
    const text = '#shape 1.5 3 // Fig 4\naxiom: A';
    expect(apply(text, setArguments(text, attribute('shape'), ['1.35', '4', '1']))).toBe('#shape 1.35 4 1 // Fig 4\naxiom: A');
    expect(setArguments(text, attribute('shape'), ['1.5', '3', ''])).toBeNull(); // nothing changes
    expect(setArguments(text, attribute('shape'), ['x', '3', ''])).toBeNull();
    expect(setArguments(text, attribute('shape'), ['', '3', ''])).toBeNull();
    const lifetime = '#lifetime 34 32\n';
    expect(setArguments(lifetime, attribute('lifetime'), ['34', '32', '', '0.2', ''])).toBeNull(); // a gap
    expect(apply(lifetime, setArguments(lifetime, attribute('lifetime'), ['NumIt<3?64:34', '32', '0.5', '0.3', '0.2']))).toBe('#lifetime NumIt<3?64:34 32 0.5 0.3 0.2\n');
    expect(validArgument(attribute('sun').fields[1], 'Winter')).toBe(true);
    expect(validArgument(attribute('sun').fields[1], 'monsoon')).toBe(false);
    expect(validArgument(attribute('lifetime').fields[0], '34 32')).toBe(false);
  });
});
