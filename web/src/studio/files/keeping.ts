// Keeping the user's text before anything replaces it (an example, a file, a lesson, a saved
// grammar, a shared link): in My grammars (localStorage), else in this browser's database
// (IndexedDB, when localStorage is full or switched off), which My grammars lists too. When neither
// can keep it, the text is not replaced unless the user downloads it first (confirm.ts).
import { type Autosave, cleanName, type GrammarStore, type KeptTexts, titleOf } from '../../share';

/** Where a text was kept: its name in My grammars, and which storage holds it. */
export interface KeptPlace {
  name: string;
  where: 'library' | 'database';
}

/** How keeping went: kept somewhere, `safe` (nothing to keep, or saved already), or null (nowhere could keep it). */
export type Keeping = KeptPlace | 'safe' | null;

/** Keeps texts before they are replaced. */
export class TextKeeper {
  constructor(
    private readonly store: GrammarStore,
    private readonly kept: KeptTexts,
  ) {}

  /**
   * Keeps `text` before `what` (`a shared link`, `“Fern”`) replaces it, named `Before WHAT: TITLE`:
   * in My grammars, else in this browser's database. Empty text, or text saved already in either,
   * is `safe`; null when neither storage could keep it.
   */
  async keep(text: string, what: string): Promise<Keeping> {
    if (text.trim() === '' || this.store.list().some((g) => g.text === text)) return 'safe';
    const name = cleanName(`Before ${what}: ${titleOf(text)}`);
    const saved = this.store.save(name, text);
    if (saved) return { name: saved.name, where: 'library' };
    if ((await this.kept.list()).some((k) => k.text === text)) return 'safe';
    const entry = await this.kept.keep(name, text);
    return entry ? { name: entry.name, where: 'database' } : null;
  }
}

/** The notice's sentence saying where the previous text went. */
export function keptSentence(place: KeptPlace): string {
  const database = place.where === 'database' ? ' (in this browser’s database: its other storage is full)' : '';
  return `Your previous text is kept in My grammars as “${place.name}”${database}.`;
}

/** The newest autosaved text: localStorage's or, when that was full, IndexedDB's. */
export async function restoreAutosave(store: GrammarStore, kept: KeptTexts): Promise<Autosave | null> {
  const local = store.restore();
  const database = await kept.restore();
  if (!local || !database) return local ?? database;
  return database.saved > local.saved ? database : local;
}
