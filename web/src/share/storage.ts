// Local saving: the editor's text autosaved on every change (it survives a reload and a crash of
// the core), and "My grammars", a named list to save, rename, duplicate and delete. Both live in
// the browser's localStorage under versioned keys; a full or unavailable storage is reported, never
// thrown, and malformed stored data is ignored.

/** One saved grammar. */
export interface StoredGrammar {
  id: string;
  name: string;
  text: string;
  /** Milliseconds since the epoch of the last save. */
  updated: number;
}

/** What autosave keeps. */
export interface Autosave {
  text: string;
  saved: number;
}

const AUTOSAVE_KEY = 'meristem.autosave.v1';
const LIBRARY_KEY = 'meristem.library.v1';

/** Where the data lives: `localStorage` in the page, a fake in tests. */
export type KeyValueStorage = Pick<Storage, 'getItem' | 'setItem' | 'removeItem'>;

export class GrammarStore {
  constructor(
    private readonly storage: KeyValueStorage | undefined,
    private readonly now: () => number = Date.now,
  ) {}

  /** Saves the editor text; false when the storage is full or unavailable. */
  autosave(text: string): boolean {
    return this.write(AUTOSAVE_KEY, { text, saved: this.now() } satisfies Autosave);
  }

  /** The last autosaved text, if any. */
  restore(): Autosave | null {
    const value = this.read(AUTOSAVE_KEY);
    if (typeof value !== 'object' || value === null) return null;
    const { text, saved } = value as Record<string, unknown>;
    return typeof text === 'string' && typeof saved === 'number' ? { text, saved } : null;
  }

  /** The saved grammars, most recently updated first. */
  list(): StoredGrammar[] {
    const value = this.read(LIBRARY_KEY);
    if (!Array.isArray(value)) return [];
    return value
      .filter(
        (g): g is StoredGrammar =>
          typeof g === 'object' &&
          g !== null &&
          typeof g.id === 'string' &&
          typeof g.name === 'string' &&
          typeof g.text === 'string' &&
          typeof g.updated === 'number',
      )
      .sort((a, b) => b.updated - a.updated);
  }

  get(id: string): StoredGrammar | undefined {
    return this.list().find((g) => g.id === id);
  }

  /** Saves `text` under `name`: a new entry, or the entry `id` replaced. Null when storage fails. */
  save(name: string, text: string, id?: string): StoredGrammar | null {
    const entry: StoredGrammar = { id: id ?? this.newId(), name: cleanName(name), text, updated: this.now() };
    const others = this.list().filter((g) => g.id !== entry.id);
    return this.write(LIBRARY_KEY, [entry, ...others]) ? entry : null;
  }

  rename(id: string, name: string): boolean {
    const entry = this.get(id);
    return entry ? this.save(name, entry.text, id) !== null : false;
  }

  /** A copy named "… (copy)". */
  duplicate(id: string): StoredGrammar | null {
    const entry = this.get(id);
    return entry ? this.save(`${entry.name} (copy)`, entry.text) : null;
  }

  remove(id: string): boolean {
    const list = this.list();
    const kept = list.filter((g) => g.id !== id);
    return kept.length !== list.length && this.write(LIBRARY_KEY, kept);
  }

  private newId(): string {
    const taken = new Set(this.list().map((g) => g.id));
    let id: string;
    do id = `g${this.now().toString(36)}${Math.floor(Math.random() * 1e6).toString(36)}`;
    while (taken.has(id));
    return id;
  }

  private read(key: string): unknown {
    try {
      const text = this.storage?.getItem(key);
      return text ? JSON.parse(text) : null;
    } catch {
      return null;
    }
  }

  private write(key: string, value: unknown): boolean {
    try {
      if (!this.storage) return false;
      this.storage.setItem(key, JSON.stringify(value));
      return true;
    } catch {
      return false;
    }
  }
}

/** A name fit for the list: trimmed, one line, at most 80 characters, never empty. */
export function cleanName(name: string): string {
  const line = name.replace(/\s+/g, ' ').trim().slice(0, 80);
  return line || 'Untitled grammar';
}

/** The name a grammar suggests for itself: its first comment line (`// Title`), else untitled. */
export function titleOf(text: string): string {
  const first = /^\s*\/\/\s*(.+)$/m.exec(text.split('\n').find((l) => l.trim() !== '') ?? '');
  return cleanName(first?.[1] ?? '');
}
