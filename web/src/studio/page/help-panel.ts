// The Help panel: the language reference (docs/LANGUAGE.md, rendered to HTML when the site is
// built) in a side panel beside the studio, so the grammar stays editable while it is open. It is
// loaded when it first opens; the toolbar's Help button and F1 open it, hover docs open it at the
// row of a module or directive, Escape or Close closes it and gives the focus back.
import './help-panel.css';
import { REFERENCE_PATH } from '../../editor/reference';
import { focusableCode } from './focusable-code';

/** The panel's elements (see index.html). */
export interface HelpPanelElements {
  /** The toolbar button that opens it. */
  opener: HTMLButtonElement;
  panel: HTMLDialogElement;
  /** Where the reference goes. */
  content: HTMLElement;
  close: HTMLButtonElement;
}

/** The rendered reference, from the site. */
export async function fetchReference(): Promise<string> {
  const response = await fetch(REFERENCE_PATH);
  if (!response.ok) throw new Error(`HTTP ${response.status}`);
  return response.text();
}

/** Class of the row (or heading) the panel was opened at. */
const TARGET_CLASS = 'reference-target';

export class HelpPanel {
  private loading: Promise<boolean> | undefined;
  /** What had the focus when the panel opened. */
  private returnFocus: HTMLElement | null = null;

  /** `load` gives the reference's HTML (replaceable for tests). */
  constructor(
    private readonly els: HelpPanelElements,
    private readonly load: () => Promise<string> = fetchReference,
  ) {
    els.opener.addEventListener('click', () => void this.open());
    els.close.addEventListener('click', () => this.close());
    els.panel.addEventListener('keydown', (event) => {
      if (event.key !== 'Escape') return;
      event.preventDefault();
      this.close();
    });
    // Links inside the reference move within it; the page's own fragment (share links) stays.
    els.content.addEventListener('click', (event) => {
      const href = (event.target as Element).closest('a')?.getAttribute('href');
      if (!href?.startsWith('#')) return;
      event.preventDefault();
      this.goTo(decodeURIComponent(href.slice(1)));
    });
  }

  get isOpen(): boolean {
    return this.els.panel.open;
  }

  /** Opens the panel (loading the reference the first time), at the element `anchor` if given. */
  async open(anchor?: string): Promise<void> {
    if (!this.isOpen) {
      this.returnFocus = document.activeElement instanceof HTMLElement ? document.activeElement : null;
      this.els.panel.show();
      this.els.opener.setAttribute('aria-expanded', 'true');
    }
    if (!(await this.loaded())) return;
    if (anchor === undefined || !this.goTo(anchor)) this.els.content.focus();
  }

  /** Closes the panel; the focus goes back where it was. */
  close(): void {
    if (!this.isOpen) return;
    this.els.panel.close();
    this.els.opener.setAttribute('aria-expanded', 'false');
    this.returnFocus?.focus();
    this.returnFocus = null;
  }

  private loaded(): Promise<boolean> {
    this.loading ??= this.load().then(
      (html) => {
        // Our own document, rendered from docs/LANGUAGE.md when the site was built (the plugin
        // escapes any raw HTML in it): nothing from users, links or files ever goes in this way.
        this.els.content.innerHTML = html;
        focusableCode(this.els.content);
        return true;
      },
      (error: unknown) => {
        this.loading = undefined; // the next opening tries again
        const message = Object.assign(document.createElement('p'), { className: 'hint', textContent: `Could not load the reference: ${String(error)}` });
        this.els.content.replaceChildren(message);
        return false;
      },
    );
    return this.loading;
  }

  /** Scrolls to the reference's element `id` (a row is marked and focused); false when there is none. */
  private goTo(id: string): boolean {
    const element = document.getElementById(id);
    if (!element || !this.els.content.contains(element)) return false;
    const target = element.closest<HTMLElement>('tr') ?? element;
    for (const old of this.els.content.querySelectorAll(`.${TARGET_CLASS}`)) old.classList.remove(TARGET_CLASS);
    target.classList.add(TARGET_CLASS);
    target.tabIndex = -1;
    target.focus({ preventScroll: true });
    target.scrollIntoView({ block: target === element ? 'start' : 'center' });
    return true;
  }
}
