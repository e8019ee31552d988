// The Problems panel under the text: how many problems there are, and the list of every one, of
// which only the rows in view exist in the page (a text with 100,000 problems opens it at once and
// scrolls freely; CodeMirror's own lint panel made an element per problem and blocked the page for
// 11 s: issue 50, finding 11). A row shows where (line:column), the message and its code; a cut
// message is whole in its tooltip and in the line over the list, which shows the chosen problem.
// Keys in the list as in CodeMirror's: arrows, Page Up/Down, Home/End, Enter (to the text), Escape.
import type { ProblemList } from './problem-list';
import type { EditorView, Panel, ViewUpdate } from '@codemirror/view';
import { closeProblems, count, goToProblem, problemRange, problemsField, type Problems } from './problems-state';
import './problems-panel.css';

/** Height of a row in pixels (keep in step with `.cm-problem` in problems-panel.css). */
export const ROW_HEIGHT = 28;
/** Rows made above and below the visible ones. */
const OVERSCAN = 4;
/** The tallest the list's scrolled content is made (browsers cap an element's height at about 33 million pixels). */
export const MAX_LIST_HEIGHT = 4_000_000;

/** The rows `first .. last` (exclusive) to make for a list scrolled to `scrollTop`, and where the first goes. */
export interface RowsInView {
  first: number;
  last: number;
  /** Pixels from the top of the scrolled content to the first row's top. */
  top: number;
  /** The scrolled content's height. */
  height: number;
}

/**
 * The rows in view of a list of `count` rows in a viewport `view` pixels high. Up to
 * {@link MAX_LIST_HEIGHT} each row has its place; past it (a million problems) the scroll position
 * is a fraction of the list and the rows at that fraction are drawn where the viewport is.
 */
export function rowsInView(scrollTop: number, view: number, rows: number): RowsInView {
  const full = rows * ROW_HEIGHT;
  const visible = Math.max(1, Math.ceil(view / ROW_HEIGHT));
  if (full <= MAX_LIST_HEIGHT) {
    const first = Math.max(0, Math.floor(scrollTop / ROW_HEIGHT) - OVERSCAN);
    const last = Math.min(rows, Math.ceil((scrollTop + view) / ROW_HEIGHT) + OVERSCAN);
    return { first, last: Math.max(first, last), top: first * ROW_HEIGHT, height: full };
  }
  const height = MAX_LIST_HEIGHT;
  const fraction = Math.min(1, Math.max(0, scrollTop / Math.max(1, height - view)));
  const first = Math.round(fraction * (rows - visible));
  const top = Math.min(Math.max(0, scrollTop), height - visible * ROW_HEIGHT);
  return { first, last: Math.min(rows, first + visible + 1), top, height };
}

/** The scroll position that shows row `row`, from `scrollTop` (unchanged when it is in view already). */
export function scrollFor(row: number, scrollTop: number, view: number, rows: number): number {
  const full = rows * ROW_HEIGHT;
  if (full > MAX_LIST_HEIGHT) {
    const visible = Math.max(1, Math.ceil(view / ROW_HEIGHT));
    return (Math.min(row, rows - visible) / Math.max(1, rows - visible)) * (MAX_LIST_HEIGHT - view);
  }
  const top = row * ROW_HEIGHT;
  if (top < scrollTop) return top;
  if (top + ROW_HEIGHT > scrollTop + view) return top + ROW_HEIGHT - view;
  return scrollTop;
}

let panels = 0;

class ProblemsPanel implements Panel {
  readonly dom: HTMLElement;
  readonly top = false;
  private readonly heading: HTMLElement;
  private readonly chosen: HTMLElement;
  private readonly list: HTMLElement;
  private readonly sizer: HTMLElement;
  private readonly idPrefix = `cm-problem-${++panels}-`;
  private queued = false;
  private readonly resizing = new ResizeObserver(() => this.queueRender());
  /** A row to scroll into view at the next render. */
  private reveal = -1;

  constructor(private readonly view: EditorView) {
    this.heading = element('div', 'cm-problems-count');
    this.heading.setAttribute('role', 'status');
    this.chosen = element('div', 'cm-problems-chosen');
    this.list = element('div', 'cm-problems-list');
    this.list.tabIndex = 0;
    this.list.setAttribute('role', 'listbox');
    this.list.setAttribute('aria-label', 'Problems');
    this.sizer = element('div', 'cm-problems-sizer');
    this.list.append(this.sizer);
    const close = element('button', 'cm-problems-close');
    close.setAttribute('type', 'button');
    close.setAttribute('aria-label', 'Close the list of problems');
    close.textContent = '×';
    close.addEventListener('click', () => {
      closeProblems(this.view);
      this.view.focus();
    });
    this.dom = element('div', 'cm-problems');
    this.dom.dataset.testid = 'problems';
    this.dom.append(this.heading, close, this.chosen, this.list);
    this.list.addEventListener('scroll', () => this.queueRender());
    this.list.addEventListener('keydown', (event) => this.onKey(event));
    this.list.addEventListener('click', (event) => {
      const row = (event.target as HTMLElement).closest<HTMLElement>('[data-problem]');
      if (row) goToProblem(this.view, Number(row.dataset.problem));
    });
    this.resizing.observe(this.list);
  }

  destroy(): void {
    this.resizing.disconnect();
  }

  mount(): void {
    this.reveal = this.problems.selected;
    this.queueRender();
  }

  update(update: ViewUpdate): void {
    const before = update.startState.field(problemsField);
    const now = this.problems;
    if (before.selected !== now.selected && now.selected >= 0) this.reveal = now.selected;
    if (before !== now || update.docChanged) this.queueRender();
  }

  private get problems(): Problems {
    return this.view.state.field(problemsField);
  }

  private onKey(event: KeyboardEvent): void {
    if (event.ctrlKey || event.altKey || event.metaKey) return;
    const { list, selected } = this.problems;
    const n = list.length;
    const page = Math.max(1, Math.floor(this.list.clientHeight / ROW_HEIGHT) - 1);
    const moves: Record<string, () => number> = {
      ArrowDown: () => (selected + 1) % n,
      ArrowUp: () => (selected - 1 + n) % n,
      PageDown: () => Math.min(n - 1, selected + page),
      PageUp: () => Math.max(0, selected - page),
      Home: () => 0,
      End: () => n - 1,
    };
    if (event.key === 'Escape') {
      closeProblems(this.view);
      this.view.focus();
    } else if (event.key === 'Enter') this.view.focus();
    else if (moves[event.key] && n > 0) goToProblem(this.view, moves[event.key]());
    else return;
    event.preventDefault();
  }

  private queueRender(): void {
    if (this.queued) return;
    this.queued = true;
    requestAnimationFrame(() => {
      this.queued = false;
      this.render();
    });
  }

  private render(): void {
    const problems = this.problems;
    const n = problems.list.length;
    // (Written only when it changes: it is a live region, read out when its text is replaced.)
    const heading = n === 0 ? 'No problems' : `${count(n, 'problem')}${severities(problems.list)}`;
    if (this.heading.textContent !== heading) this.heading.textContent = heading;
    // As tall as its rows, up to six (and 30% of the window, 20% of a short one: problems-panel.css).
    this.list.style.height = `${Math.max(1, Math.min(n, 6)) * ROW_HEIGHT}px`;
    const view = this.list.clientHeight;
    if (this.reveal >= 0 && this.reveal < n) this.list.scrollTop = scrollFor(this.reveal, this.list.scrollTop, view, n);
    this.reveal = -1;
    const { first, last, top, height } = rowsInView(this.list.scrollTop, view, n);
    this.sizer.style.height = `${height}px`;
    const rows = document.createDocumentFragment();
    for (let i = first; i < last; i++) rows.append(this.row(problems, i, top + (i - first) * ROW_HEIGHT));
    this.sizer.replaceChildren(rows);
    const selected = problems.selected >= 0 && problems.selected < n ? problems.selected : -1;
    if (selected >= first && selected < last) this.list.setAttribute('aria-activedescendant', this.idPrefix + selected);
    else this.list.removeAttribute('aria-activedescendant');
    // Always there, of one height: a panel growing under the text would hide what the text just scrolled to.
    const chosen = selected >= 0 ? this.describe(problems, selected) : n > 0 ? 'Choose a problem to go to it in the text; F8 goes to the next one.' : '';
    if (this.chosen.textContent !== chosen) this.chosen.textContent = chosen;
  }

  private row(problems: Problems, i: number, top: number): HTMLElement {
    const diagnostic = problems.list.at(i);
    const row = element('div', `cm-problem cm-problem-${diagnostic.severity}`);
    row.id = this.idPrefix + i;
    row.dataset.problem = String(i);
    row.setAttribute('role', 'option');
    row.setAttribute('aria-posinset', String(i + 1));
    row.setAttribute('aria-setsize', String(problems.list.length));
    row.setAttribute('aria-selected', String(i === problems.selected));
    row.style.top = `${top}px`;
    row.title = this.describe(problems, i);
    const at = element('span', 'cm-problem-at');
    at.textContent = this.where(problems, i);
    const message = element('span', 'cm-diagnosticText');
    message.textContent = diagnostic.message;
    row.append(at, message);
    if (diagnostic.source) {
      const code = element('span', 'cm-diagnosticSource');
      code.textContent = diagnostic.source;
      row.append(code);
    }
    return row;
  }

  /** "12:5" (line:column, counted from 1) of problem `i`. */
  private where(problems: Problems, i: number): string {
    const { doc } = this.view.state;
    const from = Math.min(problemRange(problems, i).from, doc.length);
    const line = doc.lineAt(from);
    return `${line.number}:${from - line.from + 1}`;
  }

  private describe(problems: Problems, i: number): string {
    const { message, source } = problems.list.at(i);
    return `${this.where(problems, i)} ${message}${source ? ` (${source})` : ''}`;
  }
}

/** ": 99,998 errors, 2 warnings" when some problems are errors and some not; else "". */
function severities(list: ProblemList): string {
  const { errors } = list;
  const others = list.length - errors;
  return errors > 0 && others > 0 ? `: ${count(errors, 'error')}, ${count(others, 'warning')}` : '';
}

function element(tag: string, className: string): HTMLElement {
  const made = document.createElement(tag);
  made.className = className;
  return made;
}

/** The panel's constructor, for CodeMirror's `showPanel`. */
export function createProblemsPanel(view: EditorView): Panel {
  return new ProblemsPanel(view);
}
