// Reads the course's lesson files (public/lessons/*.md; the format is in docs/LESSONS.md) into the
// data the Learn panel shows (web/src/studio/learn/lesson-manifest.ts). Runs in node, at build time: the
// Markdown is rendered to HTML here, with `marked`, so no Markdown library ships to the browser, and
// every check is parsed here, so a malformed lesson fails the build with its file and line.
import { readdirSync, readFileSync } from 'node:fs';
import { basename, join, relative } from 'node:path';
import { Marked, type Token, type Tokens } from 'marked';
import { parseExampleHeader } from '../web/src/studio/gallery/gallery-manifest.ts';
import { parseCheck } from '../web/src/studio/learn/lesson-check.ts';
import { compareLessons, type Lesson, type LessonGrammar, type LessonSummary, type LessonTask } from '../web/src/studio/learn/lesson-manifest.ts';

/** A problem in a lesson file, located: its message reads `public/lessons/FILE.md:LINE: …`. */
export class LessonFileError extends Error {
  constructor(
    readonly file: string,
    readonly line: number,
    problem: string,
  ) {
    super(`${file}:${line}: ${problem}`);
  }
}

/** Reads the front matter: `---`, then `key: value` lines, then `---`. Returns the fields and the body's first line. */
function frontMatter(file: string, lines: string[]): { fields: Map<string, string>; bodyStart: number } {
  if (lines[0]?.trim() !== '---') throw new LessonFileError(file, 1, 'a lesson starts with front matter: ---, title:, chapter:, order:, ---');
  const fields = new Map<string, string>();
  for (let i = 1; i < lines.length; i++) {
    const line = lines[i].trim();
    if (line === '---') return { fields, bodyStart: i + 1 };
    if (line === '' || line.startsWith('#')) continue;
    const match = /^([a-z]+)\s*:\s*(.*)$/.exec(line);
    if (!match) throw new LessonFileError(file, i + 1, `front matter lines are "key: value", not "${line}"`);
    if (!['title', 'chapter', 'order', 'section'].includes(match[1])) throw new LessonFileError(file, i + 1, `unknown front matter key "${match[1]}" (keys: title, chapter, order, section)`);
    fields.set(match[1], match[2].trim());
  }
  throw new LessonFileError(file, 1, 'the front matter has no closing ---');
}

function summary(file: string, fields: Map<string, string>): LessonSummary {
  const slug = basename(file, '.md');
  if (!/^[a-z0-9][a-z0-9-]*$/.test(slug)) throw new LessonFileError(file, 1, 'a lesson file is named with lower-case letters, digits and dashes (e.g. 04-bracketed.md)');
  for (const key of ['title', 'chapter', 'order']) if (!fields.get(key)) throw new LessonFileError(file, 1, `the front matter needs ${key}:`);
  const order = Number(fields.get('order'));
  if (!Number.isFinite(order)) throw new LessonFileError(file, 1, `order: is a number, not "${fields.get('order')}"`);
  return { slug, title: fields.get('title')!, chapter: fields.get('chapter')!, order, section: fields.get('section') ?? '' };
}

/** Reads a ```task block: its text, `check:`, `hint:` and `solution:` (the rest of the block). */
function taskBlock(file: string, line: number, text: string, markdown: Marked, start: number): LessonTask {
  const lines = text.split('\n');
  const keyLine = (key: string) => lines.findIndex((l) => l.startsWith(`${key}:`));
  const [check, hint, solution] = [keyLine('check'), keyLine('hint'), keyLine('solution')];
  if (check < 0) throw new LessonFileError(file, line, 'a task needs a check: line');
  if (solution < 0) throw new LessonFileError(file, line, 'a task needs a solution: (the grammar follows on the next lines)');
  if (solution < check || (hint >= 0 && solution < hint)) throw new LessonFileError(file, line + 1 + solution, 'solution: comes last in a task: the grammar is the rest of the block');
  const firstKey = Math.min(check, hint < 0 ? check : hint);
  const value = (index: number) => lines[index].replace(/^[a-z]+:\s*/, '').trim();
  const parsed = parseCheck(value(check));
  if (!parsed.ok) {
    const column = lines[check].indexOf(value(check)) + parsed.error.offset + 1;
    throw new LessonFileError(file, line + 1 + check, `check: ${parsed.error.message} (column ${column})`);
  }
  if (start < 0) throw new LessonFileError(file, line, 'a task starts from a grammar: put an ```lsys block before it');
  const grammar = lines.slice(solution + 1).join('\n').trim();
  if (value(solution) !== '' || grammar === '') throw new LessonFileError(file, line + 1 + solution, 'write the solution grammar on the lines after solution:');
  const prose = lines.slice(0, firstKey).join('\n').trim();
  if (prose === '') throw new LessonFileError(file, line, 'a task says what to do before its check: line');
  return { html: markdown.parse(prose, { async: false }), check: value(check), hint: hint < 0 ? '' : value(hint), solution: `${grammar}\n`, start };
}

/** A relative link of a lesson is relative to its file, so to the page it is under lessons/. */
function pageRelative(href: string): string {
  return /^([a-z][a-z0-9+.-]*:|\/|#)/i.test(href) ? href : `lessons/${href}`;
}

/** Our Markdown's changes: headings start at h3 (the panel's h2 is the lesson's title); relative links point into lessons/. */
function adaptToken(token: Token): void {
  if (token.type === 'heading') token.depth = Math.min(6, token.depth + 2);
  if (token.type === 'link' || token.type === 'image') token.href = pageRelative(token.href);
}

/** The Markdown renderer of lessons (GitHub's dialect, with {@link adaptToken} on every token `parse` reads). */
function lessonMarkdown(): Marked {
  return new Marked({ gfm: true, walkTokens: adaptToken });
}

/**
 * Reads one lesson file (`file` is its path as messages name it, its name the lesson's slug; `text`
 * its contents). Throws {@link LessonFileError}.
 */
export function readLesson(file: string, text: string): Lesson {
  const lines = text.replace(/\r\n?/g, '\n').split('\n');
  const { fields, bodyStart } = frontMatter(file, lines);
  const markdown = lessonMarkdown();
  const body = lines.slice(bodyStart).join('\n');
  const grammars: LessonGrammar[] = [];
  const tasks: LessonTask[] = [];
  let line = bodyStart + 1; // of the token being read (1-based)
  const tokens = markdown.lexer(body).map((token): Token => {
    const at = line;
    line += token.raw.split('\n').length - 1;
    if (token.type !== 'code' || !['lsys', 'task'].includes((token as Tokens.Code).lang ?? '')) return token;
    const code = token as Tokens.Code;
    if (code.lang === 'lsys') {
      const header = parseExampleHeader('', code.text);
      grammars.push({ title: header.title || `Grammar ${grammars.length + 1}`, text: `${code.text}\n` });
      return { type: 'html', block: true, pre: false, raw: code.raw, text: `<div class="lesson-grammar" data-grammar="${grammars.length - 1}"></div>\n` };
    }
    tasks.push(taskBlock(file, at, code.text, markdown, grammars.length - 1));
    return { type: 'html', block: true, pre: false, raw: code.raw, text: `<div class="lesson-task" data-task="${tasks.length - 1}"></div>\n` };
  });
  markdown.walkTokens(tokens, (token) => {
    adaptToken(token); // lexer and parser, unlike parse, do not walk the tokens
    if (token.type === 'code' && ['lsys', 'task'].includes((token as Tokens.Code).lang ?? '')) {
      throw new LessonFileError(file, bodyStart + 1, '```lsys and ```task blocks stand on their own, not inside a list or a quote');
    }
  });
  const html = markdown.parser(tokens as Token[] & { links: {} }, { async: false });
  return { ...summary(file, fields), html, grammars, tasks };
}

/** Reads every `*.md` of `dir`, in course order. Throws {@link LessonFileError} on the first problem. */
export function readLessons(dir: string): Lesson[] {
  const files = readdirSync(dir).filter((file) => file.endsWith('.md')).sort();
  return files.map((file) => readLesson(relative(process.cwd(), join(dir, file)), readFileSync(join(dir, file), 'utf8'))).sort(compareLessons);
}

/** The list of lessons (`lessons/index.json`): each lesson without its text. */
export function lessonIndex(lessons: Lesson[]): LessonSummary[] {
  return lessons.map(({ slug, title, chapter, order, section }) => ({ slug, title, chapter, order, section }));
}
