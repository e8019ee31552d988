// A lecturer's assignment file (docs/ASSIGNMENTS.md): the lessons' Markdown format (front matter,
// text, ```lsys grammars, ```task blocks with check, hint and a hidden solution) with the front
// matter of a course (title, course, author, due). Read here in the page (and in node by the tests
// and scripts/check-assignment.ts), never trusted: every problem is collected with its line and
// field rather than thrown, so a lecturer sees them all at once. What needs a build (a grammar
// with errors, a solution that fails its check) is assignment-validate.ts's.
import { parseCheck } from './lesson-check.ts';

/** Longest assignment file read (characters): a file past it is refused before it is read. */
export const MAX_ASSIGNMENT_CHARS = 200_000;
/** Most grammars and most tasks one assignment may have. */
export const MAX_ASSIGNMENT_BLOCKS = 40;

/** The front matter's keys: `title` is required. `chapter`, `order` (a lesson's) are read and ignored. */
const KEYS = ['title', 'course', 'author', 'due', 'section', 'chapter', 'order'] as const;

/** What is wrong with an assignment file: where (1-based line), which field, and what. */
export interface AssignmentProblem {
  line: number;
  /** `front matter`, `title`, `grammar`, `task`, `check`, `hint`, `solution`, `file`. */
  field: string;
  message: string;
}

/** A grammar of the assignment (a ```lsys block). */
export interface AssignmentGrammar {
  /** Its first comment line, or "Grammar N". */
  title: string;
  text: string;
  /** The file's line of the grammar's first line. */
  line: number;
}

/** A task (a ```task block). */
export interface AssignmentTask {
  /** What to do (Markdown). */
  markdown: string;
  check: string;
  /** The file's line of `check:` (0 when it has none). */
  checkLine: number;
  hint: string;
  /** The solution's grammar ('' when it has none): in the file, so hidden, not secret. */
  solution: string;
  /** The file's line of the solution's first line. */
  solutionLine: number;
  /** The grammar it starts from: the index of the last ```lsys block before it (-1: none). */
  start: number;
  /** The file's line of the block's fence. */
  line: number;
}

/** The file's text between blocks, a grammar, or a task, in the order written. */
export type AssignmentPart = { kind: 'text'; markdown: string } | { kind: 'grammar'; index: number } | { kind: 'task'; index: number };

/** An assignment, read. */
export interface Assignment {
  title: string;
  course: string;
  author: string;
  due: string;
  section: string;
  parts: AssignmentPart[];
  grammars: AssignmentGrammar[];
  tasks: AssignmentTask[];
}

/** An assignment and the problems of its file (none: it is well formed). */
export interface ReadAssignment {
  assignment: Assignment;
  problems: AssignmentProblem[];
}

/** Reads the front matter into `into`; returns the first line of the body (0-based index). */
function frontMatter(lines: string[], into: Assignment, problems: AssignmentProblem[]): number {
  if (lines[0]?.trim() !== '---') {
    problems.push({ line: 1, field: 'front matter', message: 'an assignment starts with front matter: a line ---, then title: …, then ---' });
    return 0;
  }
  for (let i = 1; i < lines.length; i++) {
    const line = lines[i].trim();
    if (line === '---') return i + 1;
    if (line === '' || line.startsWith('#')) continue;
    const match = /^([A-Za-z_]+)\s*:\s*(.*)$/.exec(line);
    const key = match?.[1].toLowerCase() as (typeof KEYS)[number] | undefined;
    if (!match || !key) problems.push({ line: i + 1, field: 'front matter', message: `front matter lines are "key: value", not "${line.slice(0, 60)}"` });
    else if (!KEYS.includes(key)) problems.push({ line: i + 1, field: 'front matter', message: `unknown key "${match[1]}" (keys: title, course, author, due, section)` });
    else if (key !== 'chapter' && key !== 'order') into[key] = match[2].trim();
  }
  problems.push({ line: 1, field: 'front matter', message: 'the front matter has no closing ---' });
  return lines.length;
}

/** A fenced block: its language, its lines, the line of its fence (1-based) and whether it was closed. */
interface Fence {
  lang: string;
  body: string[];
  line: number;
  closed: boolean;
}

/** Reads a ```task block. */
function taskBlock(fence: Fence, start: number, problems: AssignmentProblem[]): AssignmentTask {
  const { body, line } = fence;
  const at = (i: number) => line + 1 + i; // the file's line of the block's line i
  const keyLines = (key: string) => body.flatMap((l, i) => (l.startsWith(`${key}:`) ? [i] : []));
  const [checks, hints, solutions] = [keyLines('check'), keyLines('hint'), keyLines('solution')];
  const value = (i: number) => body[i].replace(/^[a-z]+:\s*/, '').trim();
  for (const [key, found] of [['check', checks], ['hint', hints], ['solution', solutions]] as const) {
    if (found.length > 1) problems.push({ line: at(found[1]), field: key, message: `a task has one ${key}: line (this is its second)` });
  }
  const [check, hint, solution] = [checks[0] ?? -1, hints[0] ?? -1, solutions[0] ?? -1];
  const task: AssignmentTask = { markdown: '', check: '', checkLine: 0, hint: hint < 0 ? '' : value(hint), solution: '', solutionLine: 0, start, line };
  if (start < 0) problems.push({ line, field: 'task', message: 'a task starts from a grammar: put an ```lsys block before it' });
  if (check < 0) problems.push({ line, field: 'check', message: 'this task has no check: line, so nothing can say whether it is done' });
  else {
    task.check = value(check);
    task.checkLine = at(check);
    const parsed = parseCheck(task.check);
    if (!parsed.ok) problems.push({ line: at(check), field: 'check', message: `${parsed.error.message} (column ${body[check].indexOf(task.check) + parsed.error.offset + 1})` });
  }
  if (solution < 0) problems.push({ line, field: 'solution', message: 'this task has no solution: line (the solution grammar follows it, to the end of the block)' });
  else if (solution < Math.max(check, hint)) problems.push({ line: at(solution), field: 'solution', message: 'solution: comes last in a task: the grammar is the rest of the block' });
  else {
    task.solution = body.slice(solution + 1).join('\n').trim();
    task.solutionLine = at(solution + 1);
    if (value(solution) !== '' || task.solution === '') problems.push({ line: at(solution), field: 'solution', message: 'write the solution grammar on the lines after solution:' });
    else task.solution += '\n';
  }
  const keys = [check, hint, solution].filter((i) => i >= 0);
  task.markdown = body.slice(0, keys.length > 0 ? Math.min(...keys) : body.length).join('\n').trim();
  if (task.markdown === '') problems.push({ line, field: 'task', message: 'a task says what to do before its check: line' });
  return task;
}

/** The title of a grammar: its first comment line (`// Koch island`), as the gallery's headers. */
function grammarTitle(text: string, n: number): string {
  const first = text.split('\n').find((l) => l.trim() !== '');
  const comment = first && /^\s*\/\/\s*(.+)$/.exec(first);
  return comment ? comment[1].trim() : `Grammar ${n}`;
}

/** Splits the body into Markdown text and fenced blocks (any fence: a ```lsys inside a ~~~ block is text). */
function fences(lines: string[], from: number): (string | Fence)[] {
  const out: (string | Fence)[] = [];
  let text: string[] = [];
  for (let i = from; i < lines.length; i++) {
    const open = /^(`{3,}|~{3,})\s*([\w-]*)/.exec(lines[i]);
    if (!open) {
      text.push(lines[i]);
      continue;
    }
    const fence: Fence = { lang: open[2], body: [], line: i + 1, closed: false };
    for (i++; i < lines.length; i++) {
      if (lines[i].startsWith(open[1]) && lines[i].trim() === lines[i].trim().charAt(0).repeat(lines[i].trim().length)) {
        fence.closed = true;
        break;
      }
      fence.body.push(lines[i]);
    }
    if (fence.lang !== 'lsys' && fence.lang !== 'task') {
      text.push(lines[fence.line - 1], ...fence.body, ...(fence.closed ? [lines[i]] : []));
      continue;
    }
    out.push(text.join('\n'), fence);
    text = [];
  }
  out.push(text.join('\n'));
  return out;
}

/** Reads an assignment file; never throws. */
export function readAssignment(source: string): ReadAssignment {
  const assignment: Assignment = { title: '', course: '', author: '', due: '', section: '', parts: [], grammars: [], tasks: [] };
  const problems: AssignmentProblem[] = [];
  if (source.length > MAX_ASSIGNMENT_CHARS) {
    problems.push({ line: 1, field: 'file', message: `the file is ${source.length.toLocaleString('en')} characters long; an assignment has at most ${MAX_ASSIGNMENT_CHARS.toLocaleString('en')}` });
    return { assignment, problems };
  }
  const lines = source.replace(/^\uFEFF/, '').replace(/\r\n?/g, '\n').split('\n');
  const body = frontMatter(lines, assignment, problems);
  if (body > 0 && assignment.title === '') problems.push({ line: 1, field: 'title', message: 'the front matter needs title: (the assignment’s name, shown to students)' });
  for (const piece of fences(lines, body)) {
    if (typeof piece === 'string') {
      if (piece.trim() !== '') assignment.parts.push({ kind: 'text', markdown: piece });
      continue;
    }
    if (!piece.closed) problems.push({ line: piece.line, field: piece.lang === 'lsys' ? 'grammar' : 'task', message: `this \`\`\`${piece.lang} block is never closed (a line \`\`\` ends it)` });
    const { grammars, tasks } = assignment;
    if (grammars.length + tasks.length >= 2 * MAX_ASSIGNMENT_BLOCKS) {
      problems.push({ line: piece.line, field: 'file', message: `an assignment has at most ${MAX_ASSIGNMENT_BLOCKS} grammars and ${MAX_ASSIGNMENT_BLOCKS} tasks; the rest is not read` });
      break;
    }
    if (piece.lang === 'lsys') {
      const text = `${piece.body.join('\n').trim()}\n`;
      if (text.trim() === '') problems.push({ line: piece.line, field: 'grammar', message: 'this ```lsys block is empty' });
      grammars.push({ title: grammarTitle(text, grammars.length + 1), text, line: piece.line + 1 });
      assignment.parts.push({ kind: 'grammar', index: grammars.length - 1 });
    } else {
      tasks.push(taskBlock(piece, grammars.length - 1, problems));
      assignment.parts.push({ kind: 'task', index: tasks.length - 1 });
    }
  }
  if (assignment.tasks.length === 0 && problems.every((p) => p.field !== 'file')) {
    problems.push({ line: body + 1, field: 'task', message: 'an assignment has at least one ```task block (its text, check:, solution:)' });
  }
  problems.sort((a, b) => a.line - b.line);
  return { assignment, problems };
}

/** A problem as one line: `line 12, check: …`. */
export function problemText(problem: AssignmentProblem): string {
  return `line ${problem.line}, ${problem.field}: ${problem.message}`;
}
