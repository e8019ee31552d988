// The assignment panel: a lecturer's assignment file (docs/ASSIGNMENTS.md) shown as the lessons
// are, in the Learn panel's column. For the student: the text, the grammars (open in the editor),
// each task with a Check of their grammar as written (built in the assignment's own worker, so it
// says what the lecturer will see), and Submit…, which gives the submission link. For the
// lecturer: the file's problems with line and field (read, then built), a link for students, and
// a submission opened from its link: the student's grammar and its verdicts, computed here.
// The solution is in the file but never shown (hidden, not secret: docs/ASSIGNMENTS.md says so).
import './learn-panel.css';
import './assignment-panel.css';
import type { PlantBuild } from '../../core';
import { focusableCode } from '../page/focusable-code';
import { GalleryThumbnails } from '../gallery/thumbnails';
import { closeOnEscape, showPictures } from './side-panel';
import { problemText, readAssignment, type Assignment, type AssignmentProblem, type AssignmentTask } from './assignment-file.ts';
import { fingerprint, type AssignmentSource, type Submission } from './assignment-links.ts';
import { assignmentFileInput } from './assignment-input.ts';
import { renderMarkdown } from './assignment-markdown.ts';
import { SubmitControls } from './assignment-submit.ts';
import { judge, validateAssignment, type GrammarBuilder, type Verdict } from './assignment-validate.ts';

/** What the panel needs of the studio. */
export interface AssignmentHost {
  /** The editor's text now (the student's work). */
  text(): string;
  /** Opens `text` in the editor, asking first when the user's own text would be replaced; `key` names it. */
  open(text: string, title: string, key: string): Promise<boolean>;
  /** The plant on screen (the toolbar's Iterations box may differ from the grammar's own). */
  preview?: { readonly lastResult: { source: string; build: Pick<PlantBuild, 'ok' | 'stats' | 'grammarIterations'> } | undefined };
}

/** A note when the plant on screen of `text` is not at the grammar's own iterations (the toolbar's box), which a check does not read. */
function overrideNote(host: AssignmentHost, text: string): string {
  const shown = host.preview?.lastResult;
  if (!shown || shown.source !== text || !shown.build.ok) return '';
  const { stats, grammarIterations } = shown.build;
  if (grammarIterations <= 0 || stats.iterations === grammarIterations) return '';
  return ` (The check reads the grammar as written, at its #iterations ${grammarIterations}; the plant on screen is at ${stats.iterations}, set by the Iterations box.)`;
}

/** A submission shown: the student's work, and whether the assignment changed since. */
export interface ShownSubmission {
  submission: Submission;
  /** The assignment's fingerprint now differs from the one the student worked on. */
  changed: boolean;
}

/** An element with a class and text (set as text, never as HTML). */
function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text = ''): HTMLElementTagNameMap[K] {
  const node = document.createElement(tag);
  if (className) node.className = className;
  if (text) node.textContent = text;
  return node;
}

export function button(text: string, onClick: () => void, className = '', label = text): HTMLButtonElement {
  const node = element('button', className, text);
  node.type = 'button';
  if (label !== text) node.setAttribute('aria-label', label);
  node.addEventListener('click', onClick);
  return node;
}

/** Says a verdict in `result` (`data-state`: pass, fail, busy). */
function say(result: HTMLElement, state: 'pass' | 'fail' | 'busy', text: string): void {
  result.dataset.state = state;
  result.textContent = text;
}

/** The assignment panel (one per page, made on the first assignment). */
export class AssignmentPanel {
  readonly panel = element('aside', 'learn-panel assignment-panel');
  private readonly article = element('article', 'learn-lesson');
  /** Bumped by each assignment shown: the validation of an earlier one says nothing. */
  private shown = 0;
  /** The grammars' pictures, drawn as the gallery's are, by key (`assignment/FINGERPRINT/gN`). */
  private readonly texts = new Map<string, string>();
  private readonly images = new Map<string, HTMLImageElement>();
  private readonly thumbnails = new GalleryThumbnails(async (key) => this.texts.get(key) ?? '');

  constructor(
    private readonly host: AssignmentHost,
    private readonly builder: GrammarBuilder,
    /** Opens an assignment file the user picks (the panel's "Open an assignment file…"). */
    private readonly openFile: (file: File) => void,
  ) {
    const { panel, article } = this;
    panel.dataset.testid = 'assignment';
    panel.setAttribute('aria-labelledby', 'assignment-heading');
    const header = element('header', 'dialog-header');
    const heading = element('h2', '', 'Assignment');
    heading.id = 'assignment-heading';
    header.append(heading, button('Close', () => this.closeToLearn(), 'quiet', 'Close the assignment'));
    article.dataset.testid = 'assignment-body';
    panel.append(header, article);
    closeOnEscape(panel, () => this.closeToLearn());
    showPictures(this.thumbnails, this.images);
    panel.hidden = true;
    panel.id = 'assignment';
    document.querySelector('footer.statusbar')?.before(panel);
    // The lessons take the same column: opening them hides the assignment, and their list has
    // "Back to the assignment" (learn-panel.ts) while one is open.
    document.getElementById('open-learn')?.addEventListener('click', () => this.close());
  }

  /** Shows the panel (the Learn panel's column: the lessons close). */
  private reveal(): void {
    const learn = document.getElementById('learn');
    if (learn && !learn.hidden) document.getElementById('learn-close')?.click();
    this.panel.hidden = false;
  }

  /** Hides the panel (the Learn panel's list brings it back). */
  close(): void {
    this.panel.hidden = true;
  }

  /** Closes the panel from its own controls: the focus goes to Learn, whose list brings it back. */
  private closeToLearn(): void {
    this.close();
    document.getElementById('open-learn')?.focus();
  }

  /** Opens a grammar of the assignment; on a narrow screen, where the panel covers the studio, it then steps aside. */
  private async open(text: string, title: string, key: string): Promise<void> {
    if ((await this.host.open(text, title, key)) && window.matchMedia('(max-width: 800px)').matches) this.close();
  }

  /** Says that an assignment is on its way. */
  loading(what: string): void {
    this.shown++;
    this.article.replaceChildren(element('p', 'lesson-meta', `Reading ${what}…`));
    this.reveal();
  }

  /** Says why no assignment could be opened, with "Open an assignment file…" instead. */
  showError(message: string): void {
    this.shown++;
    const error = element('p', 'learn-error', message);
    error.setAttribute('role', 'alert');
    error.dataset.testid = 'assignment-error';
    this.article.replaceChildren(element('h2', 'lesson-title', 'The assignment could not be opened'), error, this.fileButton());
    this.reveal();
  }

  /** A button that picks an assignment file. */
  private fileButton(): HTMLElement {
    const input = assignmentFileInput('assignment-file', this.openFile);
    const wrap = element('p', 'assignment-actions');
    wrap.append(button('Open an assignment file…', () => input.click()), input);
    return wrap;
  }

  /**
   * Shows an assignment read from `text` (from `source`); with `submitted`, as a submission: the
   * student's grammar's verdicts, computed now, beside each task.
   */
  show(text: string, source: AssignmentSource, submitted?: ShownSubmission): void {
    const ticket = ++this.shown;
    const { assignment, problems } = readAssignment(text);
    const print = fingerprint(text);
    const title = element('h2', 'lesson-title', assignment.title || 'Untitled assignment');
    title.tabIndex = -1;
    const meta = [assignment.course, assignment.author, assignment.due && `Due: ${assignment.due}`, assignment.section].filter(Boolean).join(' · ');
    const from = source.kind === 'url' ? `From ${source.url}` : source.kind === 'file' ? `From the file ${source.name}` : 'Packed in the link';
    const origin = element('p', 'lesson-meta assignment-origin', `${from} · fingerprint ${print}`);
    origin.dataset.testid = 'assignment-fingerprint';
    const report = element('section', 'assignment-problems');
    report.dataset.testid = 'assignment-problems';
    report.setAttribute('aria-live', 'polite');
    const base = source.kind === 'url' ? source.url : location.href;
    const body = this.body(assignment, base, submitted, print);
    const submit = new SubmitControls({ assignment, source, text, fingerprint: print }, () => this.host.text());
    this.article.replaceChildren(
      ...(submitted ? [this.banner(submitted, assignment)] : []),
      element('p', 'lesson-meta', meta),
      title,
      origin,
      report,
      body,
      submit.element(submitted !== undefined),
      this.fileButton(),
    );
    focusableCode(body);
    this.reveal();
    this.article.scrollTop = 0;
    title.focus();
    void this.report(report, assignment, problems, ticket);
  }

  /** Says the file's problems: those of reading it at once, then those its builds find. */
  private async report(report: HTMLElement, assignment: Assignment, read: AssignmentProblem[], ticket: number): Promise<void> {
    const list = (problems: AssignmentProblem[], done: boolean) => {
      const heading = problems.length === 0 ? (done ? 'No problems in this file: every check fails on its starting grammar and passes on its solution.' : 'Checking the file…') : `${problems.length} problem${problems.length === 1 ? '' : 's'} in this file${done ? '' : ' (still checking…)'}:`;
      const items = element('ul', 'assignment-problem-list');
      for (const problem of problems) items.append(element('li', '', problemText(problem)));
      report.dataset.state = done ? (problems.length === 0 ? 'ok' : 'problems') : 'checking';
      report.replaceChildren(element('p', problems.length === 0 ? '' : 'learn-error', heading), ...(problems.length > 0 ? [items] : []));
    };
    list(read, false);
    const built = await validateAssignment(assignment, this.builder).catch((error: unknown) => [{ line: 1, field: 'file', message: `could not be checked: ${String(error)}` }]);
    if (ticket !== this.shown) return;
    list([...read, ...built].sort((a, b) => a.line - b.line), true);
  }

  /** The banner of a submission: whose work, that it is not the lecturer's text, and the score. */
  private banner({ submission, changed }: ShownSubmission, assignment: Assignment): HTMLElement {
    const box = element('section', 'assignment-submission');
    box.dataset.testid = 'submission-banner';
    const who = submission.name ? `${submission.name}’s work` : 'A student’s work (no name given)';
    box.append(
      element('h3', '', `Submission: ${who}`),
      element('p', '', 'The editor now holds the student’s grammar, not your own text (if you had one, it is kept in My grammars). The verdicts below are computed now, on this grammar as written.'),
    );
    if (changed) {
      box.append(element('p', 'learn-error', `The assignment has changed since the student worked on it (their fingerprint ${submission.fingerprint}): the checks below are the file’s as it is now.`));
    }
    const score = element('p', 'assignment-score', `Checking ${assignment.tasks.length} task${assignment.tasks.length === 1 ? '' : 's'}…`);
    score.dataset.testid = 'submission-score';
    box.append(score);
    return box;
  }

  /** The assignment's text, grammars and tasks. */
  private body(assignment: Assignment, base: string, submitted: ShownSubmission | undefined, print: string): HTMLElement {
    this.images.clear();
    const body = element('div', 'lesson-body');
    const verdicts: Promise<Verdict>[] = [];
    for (const part of assignment.parts) {
      if (part.kind === 'text') body.append(renderMarkdown(part.markdown, base));
      else if (part.kind === 'grammar') body.append(this.figure(assignment.grammars[part.index].title, assignment.grammars[part.index].text, `assignment/g${part.index}`, print));
      else {
        const task = this.task(assignment, assignment.tasks[part.index], part.index, base, submitted);
        body.append(task.box);
        if (task.verdict) verdicts.push(task.verdict);
      }
    }
    if (submitted) void this.score(verdicts);
    this.thumbnails.request([...this.images.keys()]);
    return body;
  }

  /** The submission's score in its banner, once every verdict is in. */
  private async score(verdicts: Promise<Verdict>[]): Promise<void> {
    const ticket = this.shown;
    const all = await Promise.all(verdicts);
    const score = this.article.querySelector<HTMLElement>('[data-testid=submission-score]');
    if (ticket !== this.shown || !score) return;
    const passed = all.filter((v) => v.state === 'pass').length;
    score.textContent = `${passed} of ${all.length} task${all.length === 1 ? '' : 's'} pass${all.length === 1 ? 'es' : ''}.`;
    score.dataset.state = passed === all.length ? 'pass' : 'fail';
  }

  /** A grammar with its picture, its text and a button that opens it. */
  private figure(title: string, text: string, key: string, print: string): HTMLElement {
    const figure = element('figure', 'lesson-figure');
    const picture = `${key}/${print}`; // a picture per version of the file
    this.texts.set(picture, text);
    const image = element('img', 'thumbnail');
    image.alt = `Picture of ${title}`;
    image.width = 320;
    image.height = 240;
    const known = this.thumbnails.picture(picture);
    if (known) image.src = known;
    image.dataset.state = known === undefined ? 'pending' : known ? 'ready' : 'failed';
    this.images.set(picture, image);
    const code = element('pre', 'lesson-code');
    code.tabIndex = 0;
    code.append(element('code', '', text));
    const open = button('Open in the editor', () => void this.open(text, title, key), 'primary', `Open in the editor: ${title}`);
    open.dataset.testid = 'assignment-open';
    figure.append(image, element('figcaption', '', title), code, open);
    return figure;
  }

  /** A task: its text, Check (of the editor's grammar), the starting grammar; a submission's verdict. */
  private task(assignment: Assignment, task: AssignmentTask, n: number, base: string, submitted: ShownSubmission | undefined): { box: HTMLElement; verdict?: Promise<Verdict> } {
    const box = element('section', 'lesson-task-box');
    const name = assignment.tasks.length > 1 ? `Task ${n + 1}` : 'Task';
    const heading = element('h3', '', name);
    heading.id = `assignment-task-${n}`;
    box.setAttribute('aria-labelledby', heading.id);
    const text = element('div', 'task-text');
    text.append(renderMarkdown(task.markdown, base));
    const result = element('p', 'task-result');
    result.setAttribute('role', 'status');
    result.dataset.testid = 'assignment-result';
    const check = button('Check', () => void this.check(task, result), 'primary', `Check ${name.toLowerCase()} on the grammar in the editor`);
    check.dataset.testid = 'assignment-check';
    const actions = element('div', 'task-actions');
    actions.append(check);
    const start = assignment.grammars[task.start];
    if (start) actions.append(button('Open the starting grammar', () => void this.open(start.text, start.title, `assignment/g${task.start}`), '', `Open the starting grammar: ${start.title}`));
    box.append(heading, text, actions, result);
    if (!submitted) return { box };
    const verdict = element('p', 'task-result');
    verdict.dataset.testid = 'submission-verdict';
    say(verdict, 'busy', 'Checking the submitted grammar…');
    const judged = judge(task.check, submitted.submission.grammar, this.builder);
    void judged.then((v) => say(verdict, v.state === 'pass' ? 'pass' : 'fail', `Submitted grammar: ${v.said}`));
    box.insertBefore(verdict, actions);
    return { box, verdict: judged };
  }

  /** Checks the editor's grammar as written against a task, and says the answer. */
  private async check(task: AssignmentTask, result: HTMLElement): Promise<void> {
    say(result, 'busy', 'Checking the grammar in the editor…');
    const text = this.host.text();
    const verdict = await judge(task.check, text, this.builder);
    const hint = verdict.state !== 'pass' && task.hint ? ` Hint: ${task.hint}` : '';
    say(result, verdict.state === 'pass' ? 'pass' : 'fail', verdict.said + hint + overrideNote(this.host, text));
  }
}
