// The notice bar above the studio: a message the user should read (a share link that could not be
// opened, what an import could not translate, where earlier work was kept), with an optional list
// and a Dismiss button. Text only: never HTML.

/** The notice bar's elements (see index.html). */
export interface NoticeElements {
  root: HTMLElement;
  text: HTMLElement;
  list: HTMLElement;
  close: HTMLButtonElement;
}

export type NoticeKind = 'error' | 'info';

export class Notice {
  constructor(private readonly els: NoticeElements) {
    els.close.addEventListener('click', () => this.hide());
  }

  /** Shows `message` (and `items`, one list entry each), replacing any notice shown. */
  show(kind: NoticeKind, message: string, items: readonly string[] = []): void {
    const { root, text, list } = this.els;
    root.dataset.kind = kind;
    root.setAttribute('role', kind === 'error' ? 'alert' : 'status');
    text.textContent = message;
    list.replaceChildren(...items.map((item) => Object.assign(document.createElement('li'), { textContent: item })));
    list.hidden = items.length === 0;
    root.hidden = false;
  }

  hide(): void {
    this.els.root.hidden = true;
  }

  get shown(): boolean {
    return !this.els.root.hidden;
  }
}
