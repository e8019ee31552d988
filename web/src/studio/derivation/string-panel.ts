// The derived-string panel: the string of the last step, virtualised (only the rows in view exist
// in the page, so a million modules scroll freely), with the context-sensitivity highlights.
// Numbers show 6 significant digits, the exact text in the module's tooltip (module-text.ts).
import type { PlantInspector } from '../../core';
import { shortModuleText } from './module-text';
import './string-panel.css';

/** Modules per row of the panel. */
export const MODULES_PER_ROW = 40;
/** Height of a row in pixels (keep in step with `.string-row` in styles/inspector.css). */
export const ROW_HEIGHT = 22;
/** Rows rendered above and below the visible ones. */
const OVERSCAN = 4;

/** What a module is in the current highlight (CSS class `m-<role>`). */
export type ModuleRole = 'produced' | 'left' | 'right' | 'selected';

/** The rows `first .. last` (exclusive) that cover the visible part of a scroller. */
export function visibleRows(scrollTop: number, height: number, rows: number): { first: number; last: number } {
  const first = Math.max(0, Math.floor(scrollTop / ROW_HEIGHT) - OVERSCAN);
  const last = Math.min(rows, Math.ceil((scrollTop + height) / ROW_HEIGHT) + OVERSCAN);
  return { first, last: Math.max(first, last) };
}

export class StringPanel {
  private readonly scroller: HTMLElement;
  private readonly sizer: HTMLElement;
  private readonly window: HTMLElement;
  private inspector: PlantInspector | undefined;
  private count = 0;
  private roleOf: (module: number) => ModuleRole | null = () => null;
  private colourOf: ((module: number) => string | null) | null = null;
  /** Bumped on every render, so a late answer for an old view is dropped. */
  private ticket = 0;
  private renderQueued = false;

  /** `onModule` is called with the index of a module the user clicks. */
  constructor(
    root: HTMLElement,
    private readonly onModule: (module: number) => void,
  ) {
    this.scroller = document.createElement('div');
    this.scroller.className = 'string-scroller';
    this.scroller.tabIndex = 0;
    this.scroller.setAttribute('role', 'region');
    this.scroller.setAttribute('aria-label', 'Derived string');
    this.scroller.dataset.testid = 'string-panel';
    this.sizer = document.createElement('div');
    this.sizer.className = 'string-sizer';
    this.window = document.createElement('div');
    this.window.className = 'string-window';
    this.sizer.append(this.window);
    this.scroller.append(this.sizer);
    root.append(this.scroller);
    this.scroller.addEventListener('scroll', () => this.queueRender());
    this.scroller.addEventListener('click', (event) => {
      const target = (event.target as HTMLElement).closest<HTMLElement>('[data-i]');
      if (target) this.onModule(Number(target.dataset.i));
    });
    new ResizeObserver(() => this.queueRender()).observe(this.scroller);
  }

  /** Shows the derived string of a new build (`count` modules, texts from `inspector`). */
  show(count: number, inspector: PlantInspector | undefined): void {
    this.inspector = inspector;
    this.count = count;
    this.sizer.style.height = `${Math.ceil(count / MODULES_PER_ROW) * ROW_HEIGHT}px`;
    this.queueRender();
  }

  /** Renders the rows in view again, asking the inspector anew. */
  reload(): void {
    this.queueRender();
  }

  /** Sets the highlight: each module's role, and optionally a colour per module (colour by production). */
  highlight(roleOf: (module: number) => ModuleRole | null, colourOf: ((module: number) => string | null) | null = null): void {
    this.roleOf = roleOf;
    this.colourOf = colourOf;
    this.queueRender();
  }

  /** Scrolls so that module `module` is in view. */
  scrollToModule(module: number): void {
    const row = Math.floor(module / MODULES_PER_ROW);
    const top = row * ROW_HEIGHT;
    if (top < this.scroller.scrollTop || top + ROW_HEIGHT > this.scroller.scrollTop + this.scroller.clientHeight) {
      this.scroller.scrollTop = Math.max(0, top - this.scroller.clientHeight / 2);
    }
    this.queueRender();
  }

  private queueRender(): void {
    if (this.renderQueued) return;
    this.renderQueued = true;
    requestAnimationFrame(() => {
      this.renderQueued = false;
      void this.render();
    });
  }

  private async render(): Promise<void> {
    const ticket = ++this.ticket;
    // Hidden (the Derivation tab shown, the panels folded): nothing asked, nothing drawn; the
    // resize observer draws it when it shows (a timed grammar's builds arrive many times a second).
    if (this.scroller.getClientRects().length === 0) return;
    const rows = Math.ceil(this.count / MODULES_PER_ROW);
    const { first, last } = visibleRows(this.scroller.scrollTop, this.scroller.clientHeight || 200, rows);
    const start = first * MODULES_PER_ROW;
    const texts = this.inspector ? await this.inspector.moduleTexts(start, (last - first) * MODULES_PER_ROW) : [];
    if (ticket !== this.ticket) return;
    const fragment = document.createDocumentFragment();
    for (let row = first; row < last; row++) {
      const line = document.createElement('div');
      line.className = 'string-row';
      line.style.top = `${row * ROW_HEIGHT}px`;
      const number = document.createElement('span');
      number.className = 'string-index';
      number.textContent = String(row * MODULES_PER_ROW);
      line.append(number);
      for (let i = row * MODULES_PER_ROW; i < Math.min(this.count, (row + 1) * MODULES_PER_ROW); i++) {
        const text = texts[i - start];
        if (text === undefined) break;
        const span = document.createElement('span');
        span.className = 'm';
        span.dataset.i = String(i);
        span.textContent = shortModuleText(text);
        if (span.textContent !== text) span.title = text;
        const role = this.roleOf(i);
        if (role) span.classList.add(`m-${role}`);
        const colour = this.colourOf?.(i);
        if (colour) span.style.setProperty('--production-colour', colour);
        if (colour) span.classList.add('m-coloured');
        line.append(span);
      }
      fragment.append(line);
    }
    this.window.replaceChildren(fragment);
  }
}
