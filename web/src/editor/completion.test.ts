import { describe, expect, it } from 'vitest';
import { CompletionContext, type CompletionResult } from '@codemirror/autocomplete';
import { EditorState } from '@codemirror/state';
import { languageVocabulary } from '../core';
import { grammarCompletionSource } from './completion';

// The real vocabulary from the core, so the test follows the Rust tables.
const source = grammarCompletionSource(languageVocabulary());

/** Completions at the `|` in `text`. */
function complete(text: string, explicit = false): CompletionResult | null {
  const pos = text.indexOf('|');
  const doc = text.replace('|', '');
  const state = EditorState.create({ doc });
  return source(new CompletionContext(state, pos, explicit)) as CompletionResult | null;
}

const labels = (result: CompletionResult | null) => result?.options.map((o) => o.label) ?? [];

describe('grammar completion', () => {
  it('offers the core’s directives after # at the start of a line, with their arguments', () => {
    const result = complete('axiom: F\n#tro|');
    expect(result?.from).toBe('axiom: F\n'.length);
    expect(labels(result)).toContain('#tropism');
    expect(labels(result)).toContain('#color');
    const tropism = result!.options.find((o) => o.label === '#tropism');
    expect(tropism?.detail).toBe('x y z e');
    expect(String(tropism?.info)).toMatch(/tropism vector/i);
  });

  it('offers multi-character turtle commands after @, ~ and ?', () => {
    expect(labels(complete('axiom: F@|'))).toEqual(expect.arrayContaining(['@O', '@M', '@Gc', '@Ge', '@Tp', '@Ts']));
    expect(labels(complete('axiom: F@|'))).not.toContain('F');
    expect(labels(complete('A -> F~|'))).toEqual(['~l', '~p', '~X']);
    const queries = complete('A -> ?|');
    expect(labels(queries)).toEqual(['?P', '?H', '?U', '?L', '?E']);
    expect(queries?.options[0].detail).toBe('(x, y, z)');
  });

  it('lists every turtle command on request, and section keywords at a line start', () => {
    expect(labels(complete('axiom: |', true))).toEqual(expect.arrayContaining(['F', '+', '[', '!', '~l', '%']));
    expect(labels(complete('axiom: F\nhom|'))).toEqual(['homomorphism:']);
  });

  it('offers the document’s #define names inside expressions', () => {
    const grammar = '#define lr 1.109\n#define vr 1.732 // [1, 2]\n#define q lr*2\naxiom: A\n';
    expect(labels(complete(`${grammar}A -> F(l|`))).toEqual(['lr', 'vr', 'q']);
    const inParens = complete(`${grammar}A -> !(v|)`);
    expect(inParens?.from).toBe(`${grammar}A -> !(`.length);
    expect(inParens?.options.find((o) => o.label === 'vr')?.detail).toBe('= 1.732');
    expect(labels(complete(`${grammar}A(l) : l > l|`))).toContain('lr');
    expect(labels(complete(`${grammar}#define w v|`))).toEqual(['lr', 'vr', 'q']);
    expect(labels(complete(`${grammar}#define w |`, true))).toContain('q');
    // Not its own name, not outside expressions, not after the arrow's parameters close.
    expect(labels(complete(`#define a 2\n#define b a|`))).toEqual(['a']);
    expect(complete(`${grammar}A -> F(1) l|`)).toBeNull();
    expect(complete(`${grammar}A(l) : l > 1 -> F l|`)).toBeNull();
  });

  it('stays quiet in comments and while typing modules', () => {
    expect(complete('// see #ang|')).toBeNull();
    expect(complete('axiom: F\nX -> F[+X]|')).toBeNull();
  });
});
