// "My grammars": the grammars saved in this browser (GrammarStore), in a dialog to save the
// editor's text under a name, open, rename, duplicate and delete. Names are shown as text only.
import { titleOf, type GrammarStore, type StoredGrammar } from '../share/storage';

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
  /** Opens a saved grammar in the editor (the host asks before replacing changed text). */
  open(entry: StoredGrammar): void;
}

const when = new Intl.DateTimeFormat('en-GB', { dateStyle: 'medium', timeStyle: 'short' });

export class LibraryDialog {
  constructor(
    private readonly els: LibraryElements,
    private readonly store: GrammarStore,
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
    this.render();
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
    this.render();
  }

  /** Lists the saved grammars, newest first, each with its actions. */
  render(): void {
    const entries = this.store.list();
    this.els.empty.hidden = entries.length > 0;
    this.els.list.replaceChildren(...entries.map((entry) => this.item(entry)));
  }

  private item(entry: StoredGrammar): HTMLLIElement {
    const li = document.createElement('li');
    li.className = 'library-item';
    li.dataset.id = entry.id;
    const name = Object.assign(document.createElement('span'), { className: 'library-name', textContent: entry.name });
    const date = Object.assign(document.createElement('span'), { className: 'library-date', textContent: when.format(entry.updated) });
    const actions = document.createElement('span');
    actions.className = 'library-actions';
    const button = (label: string, testid: string, action: () => void, className = 'quiet') => {
      const b = Object.assign(document.createElement('button'), { type: 'button', textContent: label, className });
      b.dataset.testid = testid;
      b.addEventListener('click', action);
      return b;
    };
    const open = button('Open', 'library-open', () => {
      this.els.dialog.close();
      this.host.open(entry);
    }, '');
    const rename = button('Rename', 'library-rename', () => this.startRename(li, entry));
    const duplicate = button('Duplicate', 'library-duplicate', () => {
      if (!this.store.duplicate(entry.id)) this.say('Could not duplicate: storage is full or switched off.', 'error');
      this.render();
    });
    const remove = button('Delete', 'library-delete', () => {
      // Two steps: the first click asks, the second deletes.
      if (remove.dataset.armed !== 'true') {
        remove.dataset.armed = 'true';
        remove.textContent = 'Delete for good';
        remove.classList.add('danger');
        return;
      }
      this.store.remove(entry.id);
      this.say(`Deleted “${entry.name}”.`);
      this.render();
    });
    actions.append(open, rename, duplicate, remove);
    li.append(name, date, actions);
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
      this.render();
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
