import 'fake-indexeddb/auto';
import { describe, expect, it } from 'vitest';
import { GrammarStore, indexedDatabase, KeptTexts, type KeyValueDatabase, memoryStorage } from '../../share';
import { keptSentence, restoreAutosave, TextKeeper } from './keeping';

const memory = memoryStorage;

/** A database that refuses every write, or never answers. */
function broken(how: 'refuses' | 'hangs'): KeyValueDatabase {
  const fail = () => (how === 'hangs' ? new Promise<never>(() => {}) : Promise.reject(new DOMException('quota', 'QuotaExceededError')));
  return { get: fail, set: fail, del: fail, entries: fail };
}

describe('TextKeeper', () => {
  it('keeps a text in My grammars while localStorage has room', async () => {
    const store = new GrammarStore(memory());
    const keeper = new TextKeeper(store, new KeptTexts(indexedDatabase()));
    const kept = await keeper.keep('// Tree\naxiom: F', 'a shared link');
    expect(kept).toEqual({ name: 'Before a shared link: Tree', where: 'library' });
    expect(store.list().map((g) => g.text)).toEqual(['// Tree\naxiom: F']);
    expect(await keeper.keep('// Tree\naxiom: F', 'a shared link'), 'saved already').toBe('safe');
    expect(await keeper.keep('  \n', 'a shared link'), 'nothing to keep').toBe('safe');
  });

  it('keeps it in the database when localStorage is full, and finds it there again', async () => {
    const storage = memory();
    storage.full = true;
    const kept = new KeptTexts(indexedDatabase());
    const keeper = new TextKeeper(new GrammarStore(storage), kept);
    const place = await keeper.keep('// Bush\naxiom: X', '“Fern”');
    expect(place).toEqual({ name: 'Before “Fern”: Bush', where: 'database' });
    expect(keptSentence(place as Exclude<typeof place, 'safe' | null>)).toMatch(/kept in My grammars as “Before “Fern”: Bush” \(in this browser’s database/);
    const listed = await kept.list();
    expect(listed.some((k) => k.text === '// Bush\naxiom: X')).toBe(true);
    expect(await keeper.keep('// Bush\naxiom: X', 'a shared link'), 'kept already').toBe('safe');
    // A new page reads the same database.
    expect((await new KeptTexts(indexedDatabase()).list()).some((k) => k.name === 'Before “Fern”: Bush')).toBe(true);
  });

  it.each(['refuses', 'hangs'] as const)('says so (null) when localStorage is full and the database %s', async (how) => {
    const storage = memory();
    storage.full = true;
    const keeper = new TextKeeper(new GrammarStore(storage), new KeptTexts(broken(how), Date.now, 50));
    expect(await keeper.keep('axiom: F', 'a shared link')).toBeNull();
    expect(await new TextKeeper(new GrammarStore(undefined), new KeptTexts(undefined)).keep('axiom: F', 'x')).toBeNull();
  });
});

describe('restoreAutosave', () => {
  it('reads the newer of localStorage’s and the database’s autosave', async () => {
    let t = 1000;
    const storage = memory();
    const store = new GrammarStore(storage, () => t++);
    const kept = new KeptTexts(indexedDatabase(), () => t++);
    expect(store.autosave('older, in localStorage')).toBe(true);
    storage.full = true;
    expect(await kept.autosave('newer, in the database')).toBe(true);
    expect((await restoreAutosave(store, kept))?.text).toBe('newer, in the database');
    storage.full = false;
    expect(store.autosave('newest, in localStorage again')).toBe(true);
    expect((await restoreAutosave(store, kept))?.text).toBe('newest, in localStorage again');
    expect(await restoreAutosave(new GrammarStore(undefined), new KeptTexts(broken('hangs'), Date.now, 50))).toBeNull();
  });
});
