// Autosave: the editor's text is kept in the browser on every change, shortly after typing stops,
// and at once when the page goes away: in localStorage, else (when that is full or switched off) in
// IndexedDB; if neither can keep it, the notice says so (once, until one can).
import type { GrammarStore, KeptTexts } from '../../share';
import type { Notice } from '../page';

/** How long after the last change the text is saved (ms). */
export const AUTOSAVE_DELAY = 300;

/** The text's autosave. */
export class Autosave {
  private timer: ReturnType<typeof setTimeout> | undefined;
  /** The text of the last change, while its save waits for the timer. */
  private pending = '';
  private failed = false;
  /** Counts saves, so that only the newest one's outcome is reported. */
  private saves = 0;

  constructor(
    private readonly store: GrammarStore,
    private readonly kept: KeptTexts,
    private readonly notice: Notice,
  ) {
    window.addEventListener('pagehide', () => this.flush());
    document.addEventListener('visibilitychange', () => document.visibilityState === 'hidden' && this.flush());
  }

  /** The text changed to `text`: it is saved shortly. */
  changed(text: string): void {
    clearTimeout(this.timer);
    this.pending = text;
    this.timer = setTimeout(() => void this.save(this.pending), AUTOSAVE_DELAY);
  }

  /** Saves a change still waiting for its timer now (e.g. when the page goes away). */
  flush(): void {
    if (this.timer !== undefined) void this.save(this.pending);
  }

  /** Saves `text` now, as the work in progress; settles whether some storage kept it. */
  async save(text: string): Promise<boolean> {
    clearTimeout(this.timer);
    this.timer = undefined;
    const save = ++this.saves;
    const ok = this.store.autosave(text) || (await this.kept.autosave(text));
    if (save !== this.saves) return ok; // a newer save reports
    if (!ok && !this.failed) {
      this.notice.show('error', 'Your text cannot be saved in this browser (its storage is full or switched off): save it as a file or share it.');
    }
    this.failed = !ok;
    return ok;
  }
}
