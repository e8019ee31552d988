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
  /** What the notice shown is about, if its teller said (see `hide`). */
  private topic: string | undefined;

  constructor(private readonly els: NoticeElements) {
    els.close.addEventListener('click', () => this.hide());
  }

  /**
   * Shows `message` (and `items`, one list entry each), replacing any notice shown; `topic` names
   * what it is about, so that its teller can take it back without hiding someone else's.
   */
  show(kind: NoticeKind, message: string, items: readonly string[] = [], topic?: string): void {
    const { root, text, list } = this.els;
    this.topic = topic;
    root.dataset.kind = kind;
    root.setAttribute('role', kind === 'error' ? 'alert' : 'status');
    text.textContent = message;
    list.replaceChildren(...items.map((item) => Object.assign(document.createElement('li'), { textContent: item })));
    list.hidden = items.length === 0;
    root.hidden = false;
  }

  /** Hides the notice; with `topic`, only a notice shown about it. */
  hide(topic?: string): void {
    if (topic !== undefined && topic !== this.topic) return;
    this.els.root.hidden = true;
  }

  get shown(): boolean {
    return !this.els.root.hidden;
  }
}
