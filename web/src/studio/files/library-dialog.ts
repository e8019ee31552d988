// "My grammars": the grammars saved in this browser (GrammarStore), in a dialog to save the
// editor's text under a name, open, rename, duplicate and delete; with them, the texts kept in the
// browser's database when its other storage was full (KeptTexts), to open, download and delete.
// Names are shown as text only.
import { type GrammarStore, type KeptText, type KeptTexts, type StoredGrammar, titleOf } from '../../share';
import { saveGrammarFile } from './grammar-files';
import './library-dialog.css';

/** The dialog's elements (see index.html). */
export interface LibraryElements {
  dialog: HTMLDialogElement;
  name: HTMLInputElement;
  save: HTMLButtonElement;
  list: HTMLElement;
  empty: HTMLElement;
  status: HTMLElement;
}

/** What the dialog does to the page. */
export interface LibraryHost {
  /** The editor's text now. */
  text(): string;
  /**
   * Opens a saved grammar in the editor (the host asks before replacing changed text); `key` names
   * it (`saved/ID`, or `kept/ID` for a text kept in the database).
   */
  open(entry: StoredGrammar, key: string): void;
}

const when = new Intl.DateTimeFormat('en-GB', { dateStyle: 'medium', timeStyle: 'short' });

export class LibraryDialog {
  constructor(
    private readonly els: LibraryElements,
    private readonly store: GrammarStore,
    private readonly kept: KeptTexts,
    private readonly host: LibraryHost,
  ) {
    els.save.addEventListener('click', () => this.saveCurrent());
    els.name.addEventListener('keydown', (event) => {
      if (event.key === 'Enter') {
        event.preventDefault();
        this.saveCurrent();
      }
    });
  }

  /** Opens the dialog, its name field suggesting the grammar's own title. */
  open(): void {
    this.els.name.value = titleOf(this.host.text());
    this.say('');
    void this.render();
    if (!this.els.dialog.open) this.els.dialog.showModal();
    this.els.name.focus();
    this.els.name.select();
  }

  private say(text: string, state: 'ok' | 'error' = 'ok'): void {
    this.els.status.textContent = text;
    this.els.status.dataset.state = state;
  }

  private saveCurrent(): void {
    const saved = this.store.save(this.els.name.value, this.host.text());
    if (saved) this.say(`Saved “${saved.name}”.`);
    else this.say('Could not save: this browser’s storage is full or switched off.', 'error');
    void this.render();
  }

  /** Counts renders, so that a slow read of the database never lists over a newer render. */
  private renders = 0;

  /**
   * Lists the saved grammars and the texts kept in the database, newest first, each with its
   * actions; settles once the database's are listed too.
   */
  async render(): Promise<void> {
    const render = ++this.renders;
    const saved = this.store.list();
    this.show(saved, []);
    const kept = await this.kept.list();
    if (render === this.renders && kept.length > 0) this.show(saved, kept);
  }

  private show(saved: StoredGrammar[], kept: KeptText[]): void {
    const items = [
      ...saved.map((entry) => ({ time: entry.updated, li: this.item(entry) })),
      ...kept.map((entry) => ({ time: entry.kept, li: this.keptItem(entry) })),
    ].sort((a, b) => b.time - a.time);
    this.els.empty.hidden = items.length > 0;
    this.els.list.replaceChildren(...items.map((i) => i.li));
  }

  /** A list item: its name, date and action buttons (`Open` first). */
  private row(id: string, name: string, time: number, open: () => void): { li: HTMLLIElement; actions: HTMLElement } {
    const li = document.createElement('li');
    li.className = 'library-item';
    li.dataset.id = id;
    const label = Object.assign(document.createElement('span'), { className: 'library-name', textContent: name });
    const date = Object.assign(document.createElement('span'), { className: 'library-date', textContent: when.format(time) });
    const actions = document.createElement('span');
    actions.className = 'library-actions';
    actions.append(
      button('Open', 'library-open', () => {
        this.els.dialog.close();
        open();
      }, ''),
    );
    li.append(label, date, actions);
    return { li, actions };
  }

  /** A Delete button that asks first (the first click arms it) and then runs `remove`. */
  private deleteButton(remove: () => void): HTMLButtonElement {
    const b = button('Delete', 'library-delete', () => {
      if (b.dataset.armed !== 'true') {
        b.dataset.armed = 'true';
        b.textContent = 'Delete for good';
        b.classList.add('danger');
        return;
      }
      remove();
    });
    return b;
  }

  private item(entry: StoredGrammar): HTMLLIElement {
    const { li, actions } = this.row(entry.id, entry.name, entry.updated, () => this.host.open(entry, `saved/${entry.id}`));
    const rename = button('Rename', 'library-rename', () => this.startRename(li, entry));
    const duplicate = button('Duplicate', 'library-duplicate', () => {
      if (!this.store.duplicate(entry.id)) this.say('Could not duplicate: storage is full or switched off.', 'error');
      void this.render();
    });
    const remove = this.deleteButton(() => {
      this.store.remove(entry.id);
      this.say(`Deleted “${entry.name}”.`);
      void this.render();
    });
    actions.append(rename, duplicate, remove);
    return li;
  }

  /** A text kept in the database: open, download or delete it (its storage cannot rename). */
  private keptItem(entry: KeptText): HTMLLIElement {
    const asSaved: StoredGrammar = { id: entry.id, name: entry.name, text: entry.text, updated: entry.kept };
    const { li, actions } = this.row(entry.id, entry.name, entry.kept, () => this.host.open(asSaved, `kept/${entry.id}`));
    li.dataset.kept = 'database';
    li.title = 'Kept in this browser’s database, because its other storage was full';
    const download = button('Download', 'library-download', () => saveGrammarFile(entry.text));
    const remove = this.deleteButton(() => {
      void this.kept.remove(entry.id).then((ok) => {
        this.say(ok ? `Deleted “${entry.name}”.` : 'Could not delete: this browser’s database refused.', ok ? 'ok' : 'error');
        void this.render();
      });
    });
    actions.append(download, remove);
    return li;
  }

  private startRename(li: HTMLLIElement, entry: StoredGrammar): void {
    const input = Object.assign(document.createElement('input'), { type: 'text', value: entry.name, maxLength: 80 });
    input.dataset.testid = 'library-rename-input';
    input.setAttribute('aria-label', `New name for ${entry.name}`);
    let done = false;
    const finish = (keep: boolean) => {
      if (done) return; // Enter or Escape, then the blur of the removed field
      done = true;
      if (keep && !this.store.rename(entry.id, input.value)) this.say('Could not rename: storage is full or switched off.', 'error');
      void this.render();
    };
    input.addEventListener('keydown', (event) => {
      if (event.key === 'Enter') {
        event.preventDefault();
        finish(true);
      } else if (event.key === 'Escape') {
        event.preventDefault();
        event.stopPropagation(); // closes the rename, not the dialog
        finish(false);
      }
    });
    input.addEventListener('blur', () => finish(true));
    li.querySelector('.library-name')?.replaceWith(input);
    input.focus();
    input.select();
  }
}

/** A button of the list. */
function button(label: string, testid: string, action: () => void, className = 'quiet'): HTMLButtonElement {
  const b = Object.assign(document.createElement('button'), { type: 'button', textContent: label, className });
  b.dataset.testid = testid;
  b.addEventListener('click', action);
  return b;
}
