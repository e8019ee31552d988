// An in-memory KeyValueStorage that can be made to fail like a full localStorage: what the unit
// tests of the studio's storage run on.
import type { KeyValueStorage } from './storage';

/** The storage, its `full` switch (every write then throws QuotaExceededError) and its data. */
export function memoryStorage(): KeyValueStorage & { full: boolean; data: Map<string, string> } {
  const data = new Map<string, string>();
  return {
    data,
    full: false,
    getItem: (k) => data.get(k) ?? null,
    setItem(k, v) {
      if (this.full) throw new DOMException('quota', 'QuotaExceededError');
      data.set(k, v);
    },
    removeItem: (k) => void data.delete(k),
  };
}
