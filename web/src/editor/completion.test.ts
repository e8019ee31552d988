import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { CompletionContext, type CompletionResult } from '@codemirror/autocomplete';
import { EditorState } from '@codemirror/state';
import { grammarDirectives, initCore, turtleCommands } from '../core';
import { grammarCompletionSource } from './completion';

// The real tables from the core, so the test follows the Rust tables.
await initCore(readFileSync(new URL('../../../crate/pkg/meristem_bg.wasm', import.meta.url)));
const source = grammarCompletionSource(turtleCommands(), grammarDirectives());

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
    expect(labels(complete('A -> F~|'))).toEqual(['~l', '~p']);
    const queries = complete('A -> ?|');
    expect(labels(queries)).toEqual(['?P', '?H', '?U', '?L']);
    expect(queries?.options[0].detail).toBe('(x, y, z)');
  });

  it('lists every turtle command on request, and section keywords at a line start', () => {
    expect(labels(complete('axiom: |', true))).toEqual(expect.arrayContaining(['F', '+', '[', '!', '~l', '%']));
    expect(labels(complete('axiom: F\nhom|'))).toEqual(['homomorphism:']);
  });

  it('stays quiet in comments and while typing modules', () => {
    expect(complete('// see #ang|')).toBeNull();
    expect(complete('axiom: F\nX -> F[+X]|')).toBeNull();
  });
});
