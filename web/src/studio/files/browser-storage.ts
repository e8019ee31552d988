// Where the studio keeps the user's work in this browser: localStorage (the autosave and My
// grammars) and, when that is full or switched off, IndexedDB (KeptTexts).
import { indexedDatabase, type KeyValueDatabase, type KeyValueStorage } from '../../share';

/** `localStorage`, or nothing where the browser refuses it (private modes, sandboxed frames). */
export function browserStorage(): KeyValueStorage | undefined {
  try {
    return window.localStorage;
  } catch {
    return undefined;
  }
}

/** IndexedDB, or nothing where the browser has none or refuses it. */
export function browserDatabase(): KeyValueDatabase | undefined {
  try {
    return typeof indexedDB === 'undefined' ? undefined : indexedDatabase();
  } catch {
    return undefined;
  }
}
