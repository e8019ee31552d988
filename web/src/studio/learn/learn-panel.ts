// The Learn panel (index.html `#learn`): the course of public/lessons, by chapter and order; a
// lesson's text, its grammars with their pictures and an "Open in the editor" button, its tasks
// with a Check of the plant on screen and a hidden solution; previous and next lesson. A side
// column beside the studio on wide screens, over it on narrow ones (styles/side-panels.css); not modal, so the
// editor and the plant stay in reach while a task is worked on. Escape closes it.
import './learn-panel.css';
import { directiveOfKind, loadVocabulary, writtenDirective, type PlantBuild, type PlantInspector } from '../../core';
import { chapterHeading, isLesson, isLessonIndex, type Lesson, type LessonGrammar, type LessonSummary, type LessonTask } from './lesson-manifest';
import { evaluateCheck, parseCheck, plantFacts, spokenAnswer } from './lesson-check';
import { writtenSeed } from './written-seed';
import { assignmentFileInput } from './assignment-input';
// Loaded on demand: it imports other areas' files, not their indexes, which would bring their
// wiring into its chunk's graph (and split the first load into more files).
import { byId } from '../page/page-elements';
import { focusableCode } from '../page/focusable-code';
import { GalleryThumbnails } from '../gallery/thumbnails';
import { closeOnEscape, showPictures } from './side-panel';

/** The list of lessons, relative to the page (built by scripts/lessons-plugin.ts). */
const INDEX_URL = 'lessons/index.json';

/** How long Check waits for a build on its way before it checks the plant on screen. */
const CHECK_WAIT_MS = 10_000;

/** The panel's fixed elements in index.html. */
export function learnElements() {
  return {
    toggle: byId('open-learn', HTMLButtonElement),
    panel: byId('learn', HTMLElement),
    close: byId('learn-close', HTMLButtonElement),
    contents: byId('learn-contents', HTMLElement),
    lesson: byId('learn-lesson', HTMLElement),
  };
}

/** The panel's elements. */
export type LearnElements = ReturnType<typeof learnElements>;

/** A build as the live preview keeps it. */
interface ShownBuild {
  /** The text the plant was built from. */
  source: string;
  build: PlantBuild;
  inspector: Pick<PlantInspector, 'moduleTexts'>;
}

/** What the panel needs of the studio: the plant on screen (the live preview) and opening texts. */
export interface LearnHost {
  /** The live preview: the last build, the last one without errors, and whether it is of the text now. */
  preview: {
    readonly settled: boolean;
    nextDelivery(): Promise<void>;
    readonly lastResult: ShownBuild | undefined;
    readonly lastGood: ShownBuild | undefined;
  };
  /** Opens `text` in the editor (asking first if the user's text would be lost); `key` names it (`lesson/SLUG/N`). */
  open(text: string, title: string, key: string): Promise<boolean>;
  /** The editor's text now (an assignment's Check and Submit… read it). */
  text(): string;
}

async function fetchJson(url: string): Promise<unknown> {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}${response.status === 500 ? `: ${await response.text()}` : ''}`);
  return response.json();
}

/** An element with a class and text (set as text, never as HTML). */
function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text = ''): HTMLElementTagNameMap[K] {
  const node = document.createElement(tag);
  if (className) node.className = className;
  if (text) node.textContent = text;
  return node;
}

function button(text: string, label: string, onClick: () => void, className = ''): HTMLButtonElement {
  const node = element('button', className, text);
  node.type = 'button';
  if (label !== text) node.setAttribute('aria-label', label);
  node.addEventListener('click', onClick);
  return node;
}

/** Opens the assignment or submission the studio's address asks for (its code loads now). */
export function openFromAddress(host: LearnHost): Promise<void> {
  return import('./assignment-opening').then((opening) => opening.openFromAddress(host));
}

/** The Learn panel. */
export class LearnPanel {
  private index: LessonSummary[] | undefined;
  private current: Lesson | undefined;
  private readonly lessons = new Map<string, Promise<Lesson>>();
  /** Grammar texts of the lessons shown, by picture key (`lesson/SLUG/g0`, `lesson/SLUG/s0`). */
  private readonly texts = new Map<string, string>();
  private readonly images = new Map<string, HTMLImageElement>();
  private readonly thumbnails = new GalleryThumbnails(async (key) => this.texts.get(key) ?? '');

  constructor(
    private readonly els: LearnElements,
    private readonly host: LearnHost,
  ) {
    els.toggle.addEventListener('click', () => (els.panel.hidden ? void this.open() : this.close()));
    els.close.addEventListener('click', () => this.close());
    closeOnEscape(els.panel, () => this.close());
    showPictures(this.thumbnails, this.images);
  }

  /** Opens the panel on the lesson shown last, or on the list of lessons. */
  async open(): Promise<void> {
    const { panel, toggle } = this.els;
    panel.hidden = false;
    toggle.setAttribute('aria-expanded', 'true');
    try {
      this.index ??= await this.fetchIndex();
      if (this.current) this.focusLesson();
      else this.showContents();
    } catch (error) {
      this.els.contents.replaceChildren(element('p', 'learn-error', `Could not load the lessons: ${error instanceof Error ? error.message : String(error)}`));
      this.els.contents.hidden = false;
      this.els.lesson.hidden = true;
    }
  }

  /** Closes the panel and gives the focus back to the Learn button. */
  close(): void {
    this.els.panel.hidden = true;
    this.els.toggle.setAttribute('aria-expanded', 'false');
    this.els.toggle.focus();
  }

  private async fetchIndex(): Promise<LessonSummary[]> {
    const index = await fetchJson(INDEX_URL);
    if (!isLessonIndex(index)) throw new Error(`${INDEX_URL} is not a list of lessons`);
    return index;
  }

  private fetchLesson(slug: string): Promise<Lesson> {
    let lesson = this.lessons.get(slug);
    if (!lesson) {
      const url = `lessons/${slug}.json`;
      lesson = fetchJson(url).then((value) => {
        if (!isLesson(value)) throw new Error(`${url} is not a lesson`);
        return value;
      });
      lesson.catch(() => this.lessons.delete(slug));
      this.lessons.set(slug, lesson);
    }
    return lesson;
  }

  /** The list of lessons, grouped by chapter. */
  showContents(): void {
    const { contents, lesson } = this.els;
    const groups = new Map<string, LessonSummary[]>();
    for (const entry of this.index ?? []) groups.set(entry.chapter, [...(groups.get(entry.chapter) ?? []), entry]);
    contents.replaceChildren(
      ...[...groups].map(([chapter, entries]) => {
        const section = element('section', 'learn-chapter');
        const list = element('ol', 'learn-list');
        for (const entry of entries) {
          const item = element('li', '');
          const open = button(entry.title, entry.title, () => void this.showLesson(entry.slug), 'learn-entry');
          open.dataset.slug = entry.slug;
          if (entry.section) open.append(element('span', 'learn-section', entry.section));
          item.append(open);
          list.append(item);
        }
        section.append(element('h3', '', chapterHeading(chapter)), list);
        return section;
      }),
    );
    contents.append(this.assignments());
    const back = this.backToAssignment();
    if (back) contents.prepend(back);
    contents.hidden = false;
    lesson.hidden = true;
    const first = (this.current && contents.querySelector<HTMLButtonElement>(`[data-slug="${this.current.slug}"]`)) || contents.querySelector('button');
    first?.focus();
  }

  /** "Back to the assignment", when one was opened (assignment-panel.ts) and then closed. */
  private backToAssignment(): HTMLElement | undefined {
    const shown = document.getElementById('assignment');
    const title = shown?.querySelector('.lesson-title')?.textContent;
    if (!shown || !title) return undefined;
    const back = button(`Back to the assignment: ${title}`, `Back to the assignment: ${title}`, () => {
      this.close();
      shown.hidden = false;
      shown.querySelector<HTMLElement>('.lesson-title')?.focus();
    }, 'learn-entry');
    back.dataset.testid = 'learn-back-to-assignment';
    return back;
  }

  /** "Your own assignments": an assignment file opened (docs/ASSIGNMENTS.md), its code loaded then. */
  private assignments(): HTMLElement {
    const section = element('section', 'learn-chapter');
    const input = assignmentFileInput('learn-assignment-file', (file) => void import('./assignment-opening').then((opening) => opening.openAssignmentFile(this.host, file)));
    const about = 'An assignment of your course (a Markdown file: docs/ASSIGNMENTS.md). Open it to work on it, or, as its author, to see what is wrong with it.';
    section.append(element('h3', '', 'Your own assignments'), element('p', 'learn-section', about), button('Open an assignment file…', 'Open an assignment file…', () => input.click()), input);
    return section;
  }

  /** Shows a lesson (fetched on first view). */
  async showLesson(slug: string): Promise<void> {
    let lesson: Lesson;
    try {
      lesson = await this.fetchLesson(slug);
    } catch (error) {
      this.els.lesson.replaceChildren(element('p', 'learn-error', `Could not load the lesson: ${error instanceof Error ? error.message : String(error)}`));
      this.els.contents.hidden = true;
      this.els.lesson.hidden = false;
      return;
    }
    this.current = lesson;
    this.render(lesson);
    this.els.contents.hidden = true;
    this.els.lesson.hidden = false;
    this.els.lesson.scrollTop = 0;
    this.focusLesson();
  }

  private focusLesson(): void {
    this.els.lesson.querySelector<HTMLElement>('.lesson-title')?.focus();
  }

  private render(lesson: Lesson): void {
    const index = this.index ?? [];
    const at = index.findIndex((l) => l.slug === lesson.slug);
    const title = element('h2', 'lesson-title', lesson.title);
    title.tabIndex = -1;
    const meta = [chapterHeading(lesson.chapter), lesson.section, at >= 0 ? `lesson ${at + 1} of ${index.length}` : ''].filter(Boolean).join(' · ');
    const body = element('div', 'lesson-body');
    // Our own lesson files, rendered from Markdown at build time (scripts/lesson-files.ts): trusted
    // HTML, so innerHTML. Everything else in the panel is set as text.
    body.innerHTML = lesson.html;
    this.images.clear(); // the texts stay: a picture still being drawn may be of an earlier lesson
    const keys: string[] = [];
    lesson.grammars.forEach((grammar, n) => {
      const key = `lesson/${lesson.slug}/g${n}`;
      keys.push(key);
      body.querySelector(`.lesson-grammar[data-grammar="${n}"]`)?.replaceChildren(this.figure(grammar, key, 'Open in the editor'));
    });
    lesson.tasks.forEach((task, n) => {
      const key = `lesson/${lesson.slug}/s${n}`;
      keys.push(key);
      body.querySelector(`.lesson-task[data-task="${n}"]`)?.replaceChildren(this.task(lesson, task, n, key));
    });
    focusableCode(body);
    this.els.lesson.replaceChildren(
      button('All lessons', 'All lessons', () => this.showContents(), 'quiet learn-back'),
      element('p', 'lesson-meta', meta),
      title,
      body,
      this.pager(index, at),
    );
    this.thumbnails.request(keys);
  }

  /** A grammar with its picture, its text and a button that opens it. */
  private figure(grammar: LessonGrammar, key: string, action: string): HTMLElement {
    this.texts.set(key, grammar.text);
    const figure = element('figure', 'lesson-figure');
    const image = element('img', 'thumbnail');
    image.alt = `Picture of ${grammar.title}`;
    image.width = 320;
    image.height = 240;
    image.dataset.state = 'pending';
    const known = this.thumbnails.picture(key);
    if (known) image.src = known;
    if (known !== undefined) image.dataset.state = known ? 'ready' : 'failed';
    this.images.set(key, image);
    const code = element('pre', 'lesson-code');
    code.tabIndex = 0; // it scrolls sideways: see focusableCode
    code.append(element('code', '', grammar.text));
    const open = button(action, `${action}: ${grammar.title}`, () => void this.host.open(grammar.text, grammar.title, key).then((done) => done && this.openedOnNarrowScreen()), 'primary');
    open.dataset.testid = 'lesson-open';
    figure.append(image, element('figcaption', '', grammar.title), code, open);
    return figure;
  }

  /** On a narrow screen the panel covers the studio: the opened grammar is what the user wants to see. */
  private openedOnNarrowScreen(): void {
    if (window.matchMedia('(max-width: 800px)').matches) this.close();
  }

  /** A task: its text, Check with the answer, and the solution behind "Show solution". */
  private task(lesson: Lesson, task: LessonTask, n: number, solutionKey: string): HTMLElement {
    const box = element('section', 'lesson-task-box');
    const name = lesson.tasks.length > 1 ? `Task ${n + 1}` : 'Task';
    const heading = element('h3', '', name);
    heading.id = `task-${lesson.slug}-${n}`;
    box.setAttribute('aria-labelledby', heading.id);
    const text = element('div', 'task-text');
    text.innerHTML = task.html; // our own lesson file, rendered at build time (see render)
    const result = element('p', 'task-result');
    result.setAttribute('role', 'status');
    result.dataset.testid = 'task-result';
    const check = button('Check', `Check ${name.toLowerCase()} on the plant on screen`, () => void this.check(task, result), 'primary');
    check.dataset.testid = 'task-check';
    const start = lesson.grammars[task.start];
    const restart = button('Open the starting grammar', `Open the starting grammar: ${start.title}`, () => void this.host.open(start.text, start.title, `lesson/${lesson.slug}/g${task.start}`));
    const actions = element('div', 'task-actions');
    actions.append(check, restart);
    const solution = element('details', 'task-solution');
    const summary = element('summary', '', 'Show solution');
    const title = `the solution of ${lesson.title}${lesson.tasks.length > 1 ? `, task ${n + 1}` : ''}`;
    const figure = this.figure({ title, text: task.solution }, solutionKey, 'Open solution');
    figure.querySelector('figcaption')?.remove();
    solution.append(summary, figure);
    box.append(heading, text, actions, result, solution);
    return box;
  }

  /** Evaluates a task's check on the plant on screen and says the answer in `result`. */
  private async check(task: LessonTask, result: HTMLElement): Promise<void> {
    const say = (state: 'pass' | 'fail' | 'busy', text: string) => {
      result.dataset.state = state;
      result.textContent = text;
    };
    const parsed = parseCheck(task.check);
    if (!parsed.ok) return say('fail', `This task's check cannot be read: ${parsed.error.message}.`);
    say('busy', 'Checking the plant on screen…');
    const { preview } = this.host;
    // The build of the text now, if one is on its way (a crashed build is never delivered: not for ever).
    if (!preview.settled) await Promise.race([preview.nextDelivery(), new Promise((done) => setTimeout(done, CHECK_WAIT_MS))]);
    const last = preview.lastResult;
    if (!last) return say('fail', 'Not yet: there is no plant on screen.');
    if (!last.build.ok) return say('fail', 'Not yet: the grammar has errors (marked in the editor); the plant on screen is an older one. Fix them, then check again.');
    const seedDirective = writtenDirective(directiveOfKind(await loadVocabulary(), 'Seed'));
    const facts = await plantFacts(parsed.check, last.build, last.inspector, writtenSeed(last.source, seedDirective));
    if (!facts.ok) return say('fail', `Not yet: ${facts.reason}.`);
    const answer = evaluateCheck(parsed.check, facts.facts);
    say(answer.pass ? 'pass' : 'fail', spokenAnswer(answer) + (!answer.pass && task.hint ? ` Hint: ${task.hint}` : ''));
  }

  /** Previous and next lesson. */
  private pager(index: LessonSummary[], at: number): HTMLElement {
    const nav = element('nav', 'lesson-pager');
    nav.setAttribute('aria-label', 'Other lessons');
    const previous = index[at - 1];
    const next = at >= 0 ? index[at + 1] : undefined;
    if (previous) nav.append(button(`← ${previous.title}`, `Previous lesson: ${previous.title}`, () => void this.showLesson(previous.slug), 'learn-previous'));
    if (next) nav.append(button(`${next.title} →`, `Next lesson: ${next.title}`, () => void this.showLesson(next.slug), 'learn-next'));
    return nav;
  }
}
