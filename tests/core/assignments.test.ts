// Assignment files (docs/ASSIGNMENTS.md) against the real core: the example reads and validates
// without a problem, and each kind of problem a lecturer can make is said with its line and field
// (read by assignment-file.ts, or found by building: assignment-validate.ts, with the builds the
// studio's worker makes, here the core in node).
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { problemText, readAssignment } from '../../web/src/studio/learn/assignment-file';
import { judge } from '../../web/src/studio/learn/assignment-validate';
import { assignmentProblems as problems, nodeBuilder as builder } from './assignment-builder';

const EXAMPLE = readFileSync(new URL('../../public/assignments/example-koch.md', import.meta.url), 'utf8');

/** An assignment file of these lines (`lines[0]` is the file's line 1). */
const file = (...lines: string[]) => `${lines.join('\n')}\n`;
const HEAD = ['---', 'title: T', '---', '']; // lines 1–4
const START = ['```lsys', '// Start', 'axiom: F', 'F -> FF', '#iterations 2', '```', '']; // lines 5–11: 4 segments

describe('the example assignment', () => {
  it('reads without a problem and every check fails on its start and passes on its solution', async () => {
    const { assignment } = readAssignment(EXAMPLE);
    expect(assignment.title).toBe('Koch islands, one step further');
    expect(assignment.tasks).toHaveLength(3);
    expect(await problems(EXAMPLE)).toEqual([]);
  });

  it('judges a wrong answer as failing and a right one as passing, in words', async () => {
    const { assignment } = readAssignment(EXAMPLE);
    const task = assignment.tasks[0];
    const wrong = await judge(task.check, assignment.grammars[0].text.replace('#iterations 2', '#iterations 4'), builder);
    expect(wrong).toEqual({ state: 'fail', said: 'Not yet: segments is 16384, the task wants 2048.' });
    expect((await judge(task.check, task.solution, builder)).state).toBe('pass');
    const broken = await judge(task.check, 'axiom: F\nF -> -> F\n', builder);
    expect(broken.state).toBe('error');
    expect(broken.said).toMatch(/^Not yet: the grammar has errors \(line 2: /);
  });
});

describe('a problem of an assignment file is said with its line and field', () => {
  it('a task without a check', async () => {
    const text = file(...HEAD, ...START, '```task', 'Do it.', 'solution:', 'axiom: FFF', '```');
    expect((await problems(text)).map(problemText)).toEqual(['line 12, check: this task has no check: line, so nothing can say whether it is done']);
  });

  it('a check that names an unknown fact, with its column', async () => {
    const text = file(...HEAD, ...START, '```task', 'Do it.', 'check: segmnts > 4', 'solution:', 'axiom: FFFFF', '```');
    const found = await problems(text);
    expect(found).toHaveLength(1);
    expect(found[0]).toMatchObject({ line: 14, field: 'check' });
    expect(found[0].message).toMatch(/"segmnts" is not a fact.*\(column 8\)$/);
  });

  it('a starting grammar with errors, at the line of the error in the file', async () => {
    const text = file(...HEAD, '```lsys', '// Start', 'axiom: F', 'F -> -> F', '```', '', '```task', 'Do it.', 'check: segments > 4', 'solution:', 'axiom: FFFFF', '```');
    const found = await problems(text);
    expect(found.map((p) => [p.line, p.field])).toEqual([[8, 'grammar']]);
    expect(found[0].message).toMatch(/^the grammar has an error: /);
  });

  it('a solution that does not pass its own check', async () => {
    const text = file(...HEAD, ...START, '```task', 'Do it.', 'check: segments > 4', 'solution:', 'axiom: FF', '```');
    expect((await problems(text)).map(problemText)).toEqual(['line 14, solution: the solution does not pass its own check: Not yet: segments is 2, the task wants more than 4.']);
  });

  it('a solution with errors, at its line in the file', async () => {
    const text = file(...HEAD, ...START, '```task', 'Do it.', 'check: segments > 4', 'solution:', 'axiom: F', 'F -> -> F', '```');
    const found = await problems(text);
    expect(found.map((p) => [p.line, p.field])).toEqual([[17, 'solution']]);
  });

  it('a check that already passes on the starting grammar', async () => {
    const text = file(...HEAD, ...START, '```task', 'Do it.', 'check: segments >= 4', 'solution:', 'axiom: FFFFF', '```');
    expect((await problems(text)).map(problemText)).toEqual([
      'line 14, check: the check already passes on the starting grammar (“Start”: Passed: segments is 4.): a student who changes nothing would pass',
    ]);
  });

  it('the front matter: no title, an unknown key, none at all', async () => {
    const tasks = [...START, '```task', 'Do it.', 'check: segments > 4', 'solution:', 'axiom: FFFFF', '```'];
    expect((await problems(file('---', 'titel: T', '---', '', ...tasks))).map(problemText)).toEqual([
      'line 1, title: the front matter needs title: (the assignment’s name, shown to students)',
      'line 2, front matter: unknown key "titel" (keys: title, course, author, due, section)',
    ]);
    expect((await problems(file('# T', ...tasks))).map((p) => [p.line, p.field])).toEqual([[1, 'front matter']]);
  });

  it('a task before any grammar, a block never closed, a file without tasks', async () => {
    expect((await problems(file(...HEAD, '```task', 'Do it.', 'check: segments > 4', 'solution:', 'axiom: FFFFF', '```'))).map(problemText)).toEqual([
      'line 5, task: a task starts from a grammar: put an ```lsys block before it',
    ]);
    const unclosed = await problems(file(...HEAD, ...START, '```task', 'Do it.', 'check: segments > 4', 'solution:', 'axiom: FFFFF'));
    expect(unclosed.map((p) => [p.line, p.field])).toEqual([[12, 'task']]);
    expect((await problems(file(...HEAD, ...START))).map(problemText)).toEqual(['line 4, task: an assignment has at least one ```task block (its text, check:, solution:)']);
  });

  it('refuses a file too long to be an assignment, before reading it', () => {
    const read = readAssignment(`---\ntitle: T\n---\n${'x'.repeat(200_001)}`);
    expect(read.problems.map((p) => p.field)).toEqual(['file']);
  });
});
