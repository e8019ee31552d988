// The course's data, as the lessons plugin (scripts/lessons-plugin.ts) writes it at build time from
// public/lessons/*.md and the Learn panel fetches it: `lessons/index.json` lists the lessons,
// `lessons/SLUG.json` holds one. Defined once, here, for both sides; the page trusts nothing it
// fetched, hence the checks below.
import { abopChapterHeading } from '../gallery/chapters.ts'; // with its extension: the vite config's plugins load this file in node

/** One lesson in the list. */
export interface LessonSummary {
  /** The file's name without `.md` (`04-bracketed`): the lesson's URL is `lessons/SLUG.json`. */
  slug: string;
  title: string;
  /** The front matter's `chapter`: an ABOP chapter number (`1`) or any heading (`Green's RL-systems`). */
  chapter: string;
  /** Place within the chapter. */
  order: number;
  /** Where in the book (the front matter's `section`, e.g. "§1.6, Fig. 1.24"), or ''. */
  section: string;
}

/** A grammar of a lesson (a ```lsys block): shown with its picture, opened with one click. */
export interface LessonGrammar {
  /** The grammar's first comment line, or "Grammar N". */
  title: string;
  text: string;
}

/** A task (a ```task block): its text, the check the studio evaluates, a hint and the solution. */
export interface LessonTask {
  /** The task's text, rendered from Markdown at build time. */
  html: string;
  /** The check, in the predicate language of lesson-check.ts (parsed at build time already). */
  check: string;
  /** Said after a failed check, or ''. */
  hint: string;
  /** The solution's grammar, hidden until asked for. */
  solution: string;
  /** The grammar the task starts from: the index of the last ```lsys block before it. */
  start: number;
}

/** One lesson, whole. */
export interface Lesson extends LessonSummary {
  /**
   * The text, rendered from our own Markdown at build time. Where a block stood, an empty
   * `<div class="lesson-grammar" data-grammar="N">` or `<div class="lesson-task" data-task="N">`.
   */
  html: string;
  grammars: LessonGrammar[];
  tasks: LessonTask[];
}

/** The heading of a chapter: "ABOP chapter 1: graphical modeling using L-systems", or the text as written. */
export function chapterHeading(chapter: string): string {
  return /^\d+$/.test(chapter) ? abopChapterHeading(Number(chapter)) : chapter;
}

/** Course order: ABOP chapters by number, then other chapters by name; within one, by `order`, then slug. */
export function compareLessons(a: LessonSummary, b: LessonSummary): number {
  const rank = (c: string) => (/^\d+$/.test(c) ? [0, Number(c), ''] : [1, 0, c]) as [number, number, string];
  const [ra, rb] = [rank(a.chapter), rank(b.chapter)];
  return ra[0] - rb[0] || ra[1] - rb[1] || ra[2].localeCompare(rb[2]) || a.order - b.order || a.slug.localeCompare(b.slug);
}

const isRecord = (value: unknown): value is Record<string, unknown> => typeof value === 'object' && value !== null;
const hasStrings = (value: Record<string, unknown>, keys: string[]) => keys.every((key) => typeof value[key] === 'string');

function isSummary(value: unknown): value is LessonSummary {
  return isRecord(value) && hasStrings(value, ['slug', 'title', 'chapter', 'section']) && typeof value.order === 'number' && /^[a-z0-9][a-z0-9-]*$/.test(value.slug as string);
}

/** Checks that fetched JSON is the list of lessons. */
export function isLessonIndex(value: unknown): value is LessonSummary[] {
  return Array.isArray(value) && value.every(isSummary);
}

/** Checks that fetched JSON is one lesson. */
export function isLesson(value: unknown): value is Lesson {
  if (!isSummary(value)) return false;
  const { html, grammars, tasks } = value as Partial<Lesson>;
  return (
    typeof html === 'string' &&
    Array.isArray(grammars) &&
    grammars.every((g) => isRecord(g) && hasStrings(g, ['title', 'text'])) &&
    Array.isArray(tasks) &&
    tasks.every((t) => isRecord(t) && hasStrings(t, ['html', 'check', 'hint', 'solution']) && typeof t.start === 'number' && t.start >= 0 && t.start < grammars.length)
  );
}
