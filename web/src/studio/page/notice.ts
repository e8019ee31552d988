// The notice bar above the studio: a message the user should read (a share link that could not be
// opened, what an import could not translate, where earlier work was kept), with an optional list,
// optional action buttons (Cancel an import) and a Dismiss button. Text only: never HTML.

/** The notice bar's elements (see index.html). */
export interface NoticeElements {
  root: HTMLElement;
  text: HTMLElement;
  list: HTMLElement;
  close: HTMLButtonElement;
}

export type NoticeKind = 'error' | 'info';

/** A button in the notice, beside Dismiss. */
export interface NoticeAction {
  label: string;
  /** Its `data-testid`. */
  testid: string;
  run(): void;
}

export class Notice {
  /** What the notice shown is about, if its teller said (see `hide`). */
  private topic: string | undefined;
  /** The action buttons, before Dismiss. */
  private readonly actions = document.createElement('span');

  constructor(private readonly els: NoticeElements) {
    els.close.addEventListener('click', () => this.hide());
    this.actions.className = 'notice-actions';
    els.close.before(this.actions);
  }

  /**
   * Shows `message` (and `items`, one list entry each, and `actions`, one button each), replacing
   * any notice shown; `topic` names what it is about, so that its teller can take it back without
   * hiding someone else's.
   */
  show(kind: NoticeKind, message: string, items: readonly string[] = [], topic?: string, actions: readonly NoticeAction[] = []): void {
    const { root, text, list } = this.els;
    this.topic = topic;
    this.actions.replaceChildren(
      ...actions.map((action) => {
        const button = Object.assign(document.createElement('button'), { type: 'button', textContent: action.label });
        button.dataset.testid = action.testid;
        button.addEventListener('click', () => action.run());
        return button;
      }),
    );
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
