// Texts kept in the browser's IndexedDB, the second place the studio keeps the user's work when
// localStorage (GrammarStore) is full or switched off: the autosave, and the texts kept before
// something replaced them. IndexedDB has a quota of its own, far larger than localStorage's. Every
// operation settles, within a time limit, with a result or a failure (a blocked or missing database
// is a failure, never a hang or a throw). idb-keyval does the IndexedDB plumbing.
import { createStore, del, entries, get, set, type UseStore } from 'idb-keyval';
import type { Autosave } from './storage';

/** A text kept before something replaced it. */
export interface KeptText {
  id: string;
  name: string;
  text: string;
  /** Milliseconds since the epoch when it was kept. */
  kept: number;
}

/** The database and its one object store; the keys are `autosave` and `kept/ID`. */
const DATABASE = 'meristem';
const STORE = 'texts';
const AUTOSAVE_KEY = 'autosave';
const KEPT_PREFIX = 'kept/';

/** Longest an operation may take before it counts as failed (ms): a blocked database never hangs the studio. */
export const KEPT_TEXTS_TIMEOUT = 3000;

/** The IndexedDB operations used (idb-keyval's, over a store), replaceable in tests. */
export interface KeyValueDatabase {
  get(key: string): Promise<unknown>;
  set(key: string, value: unknown): Promise<void>;
  del(key: string): Promise<void>;
  entries(): Promise<[IDBValidKey, unknown][]>;
}

/** The browser's IndexedDB through idb-keyval (opened on first use). */
export function indexedDatabase(): KeyValueDatabase {
  let store: UseStore | undefined;
  const open = () => (store ??= createStore(DATABASE, STORE));
  return {
    get: async (key) => get(key, open()),
    set: async (key, value) => set(key, value, open()),
    del: async (key) => del(key, open()),
    entries: async () => entries(open()),
  };
}

function isKeptText(value: unknown): value is KeptText {
  if (typeof value !== 'object' || value === null) return false;
  const { id, name, text, kept } = value as Record<string, unknown>;
  return typeof id === 'string' && typeof name === 'string' && typeof text === 'string' && typeof kept === 'number';
}

export class KeptTexts {
  constructor(
    private readonly database: KeyValueDatabase | undefined,
    private readonly now: () => number = Date.now,
    private readonly timeout = KEPT_TEXTS_TIMEOUT,
  ) {}

  /** Keeps `text` under `name`; the entry, or null when the database refused or is missing. */
  async keep(name: string, text: string): Promise<KeptText | null> {
    const entry: KeptText = { id: `k${this.now().toString(36)}${Math.floor(Math.random() * 1e6).toString(36)}`, name, text, kept: this.now() };
    return (await this.run((db) => db.set(KEPT_PREFIX + entry.id, entry), false)) === false ? null : entry;
  }

  /** The kept texts, most recent first ([] when the database cannot be read). */
  async list(): Promise<KeptText[]> {
    const all = await this.run((db) => db.entries(), []);
    return all
      .filter(([key, value]) => typeof key === 'string' && key.startsWith(KEPT_PREFIX) && isKeptText(value))
      .map(([, value]) => value as KeptText)
      .sort((a, b) => b.kept - a.kept);
  }

  /** Deletes the kept text `id`; false when the database refused. */
  async remove(id: string): Promise<boolean> {
    return (await this.run((db) => db.del(KEPT_PREFIX + id), false)) !== false;
  }

  /** Saves the editor's text as the autosave; false when the database refused. */
  async autosave(text: string): Promise<boolean> {
    return (await this.run((db) => db.set(AUTOSAVE_KEY, { text, saved: this.now() } satisfies Autosave), false)) !== false;
  }

  /** The text autosaved here, if any. */
  async restore(): Promise<Autosave | null> {
    const value = await this.run((db) => db.get(AUTOSAVE_KEY), null);
    if (typeof value !== 'object' || value === null) return null;
    const { text, saved } = value as Record<string, unknown>;
    return typeof text === 'string' && typeof saved === 'number' ? { text, saved } : null;
  }

  /** Runs `operation`, settling with `failed` if it throws, rejects or takes longer than the time limit. */
  private async run<T, F>(operation: (db: KeyValueDatabase) => Promise<T>, failed: F): Promise<T | F> {
    const database = this.database;
    if (!database) return failed;
    let timer: ReturnType<typeof setTimeout> | undefined;
    const late = new Promise<F>((resolve) => (timer = setTimeout(() => resolve(failed), this.timeout)));
    try {
      return await Promise.race([operation(database), late]);
    } catch {
      return failed;
    } finally {
      clearTimeout(timer);
    }
  }
}
