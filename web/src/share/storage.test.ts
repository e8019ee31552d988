import { describe, expect, it } from 'vitest';
import { memoryStorage } from './memory-storage';
import { cleanName, GrammarStore, titleOf } from './storage';

const memory = memoryStorage;

describe('autosave', () => {
  it('restores the last text', () => {
    const storage = memory();
    let t = 1000;
    const store = new GrammarStore(storage, () => t++);
    expect(store.restore()).toBeNull();
    expect(store.autosave('axiom: F')).toBe(true);
    expect(store.autosave('axiom: FF')).toBe(true);
    // A new page (a reload) reads the same storage.
    expect(new GrammarStore(storage).restore()).toEqual({ text: 'axiom: FF', saved: 1001 });
  });

  it('reports a full or missing storage and ignores malformed data', () => {
    const storage = memory();
    storage.full = true;
    expect(new GrammarStore(storage).autosave('x')).toBe(false);
    expect(new GrammarStore(undefined).autosave('x')).toBe(false);
    storage.full = false;
    storage.data.set('meristem.autosave.v1', '{not json');
    expect(new GrammarStore(storage).restore()).toBeNull();
    storage.data.set('meristem.autosave.v1', '{"text": 3}');
    expect(new GrammarStore(storage).restore()).toBeNull();
  });
});

describe('my grammars', () => {
  it('saves, renames, duplicates and deletes, most recent first', () => {
    let t = 0;
    const store = new GrammarStore(memory(), () => ++t);
    const bush = store.save('Bush', 'axiom: A')!;
    const tree = store.save('  Tree\nof life ', 'axiom: T')!;
    expect(tree.name).toBe('Tree of life');
    expect(store.list().map((g) => g.name)).toEqual(['Tree of life', 'Bush']);
    expect(store.rename(bush.id, 'Shrub')).toBe(true);
    expect(store.list().map((g) => g.name)).toEqual(['Shrub', 'Tree of life']);
    const copy = store.duplicate(tree.id)!;
    expect(copy.name).toBe('Tree of life (copy)');
    expect(copy.text).toBe('axiom: T');
    expect(copy.id).not.toBe(tree.id);
    expect(store.remove(tree.id)).toBe(true);
    expect(store.remove(tree.id)).toBe(false);
    expect(store.list().map((g) => g.name)).toEqual(['Tree of life (copy)', 'Shrub']);
    // Saving under an id replaces that entry.
    store.save('Shrub', 'axiom: AA', bush.id);
    expect(store.get(bush.id)?.text).toBe('axiom: AA');
    expect(store.list()).toHaveLength(2);
  });

  it('names grammars from their first comment line', () => {
    expect(titleOf('\n// ABOP Fig 1.24d: a plant\naxiom: X')).toBe('ABOP Fig 1.24d: a plant');
    expect(titleOf('axiom: X')).toBe('Untitled grammar');
    expect(cleanName('x'.repeat(200))).toHaveLength(80);
  });
});
