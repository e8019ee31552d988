// Where the studio keeps the user's work in this browser (the autosave and My grammars).
import type { KeyValueStorage } from '../share/storage';

/** `localStorage`, or nothing where the browser refuses it (private modes, sandboxed frames). */
export function browserStorage(): KeyValueStorage | undefined {
  try {
    return window.localStorage;
  } catch {
    return undefined;
  }
}
