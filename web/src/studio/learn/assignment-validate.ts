// The checks of an assignment that need the core: each grammar builds without errors, each task's
// check fails on its starting grammar (a student who changes nothing must not pass) and passes on
// its solution. Problems carry the file's line and field, as assignment-file.ts's. The builds are
// the caller's (`GrammarBuilder`: the studio's own build worker, or the core in node's tests), and
// every verdict is computed here from a build, as a submission's are (assignment-verdicts.ts).
import type { PlantBuild, PlantInspector } from '../../core';
import type { Assignment, AssignmentProblem, AssignmentTask } from './assignment-file.ts';
import { evaluateCheck, parseCheck, plantFacts, spokenAnswer } from './lesson-check.ts';

/** A grammar built: its build and an inspector of it (freed by {@link judge}), or why there is none. */
export type Built = { ok: true; build: PlantBuild; inspector: Pick<PlantInspector, 'moduleTexts' | 'free'>; textSeed?: number } | { ok: false; reason: string };

/** Builds a grammar as written (its own `#iterations` and `#seed`). */
export type GrammarBuilder = (text: string) => Promise<Built>;

/** A check's verdict on one grammar. */
export interface Verdict {
  /** `pass`, `fail`, or `error`: the grammar has errors, or its facts cannot be had. */
  state: 'pass' | 'fail' | 'error';
  /** In words: "Passed: whorl is 3.", "Not yet: …", or what kept it from being checked. */
  said: string;
  /** The grammar's first error (`line`: the grammar's own line), when it has some. */
  error?: { line: number; message: string };
}

/** Evaluates `check` on `text`, built by `builder`. */
export async function judge(check: string, text: string, builder: GrammarBuilder): Promise<Verdict> {
  const parsed = parseCheck(check);
  if (!parsed.ok) return { state: 'error', said: `The check cannot be read: ${parsed.error.message}.` };
  const built = await builder(text);
  if (!built.ok) return { state: 'error', said: `Could not build the grammar: ${built.reason}.` };
  try {
    const error = built.build.diagnostics.first('error');
    if (error || !built.build.ok) {
      const first = error ? { line: error.line, message: error.message } : { line: 1, message: 'the grammar has errors' };
      return { state: 'error', said: `Not yet: the grammar has errors (line ${first.line}: ${first.message}).`, error: first };
    }
    const facts = await plantFacts(parsed.check, built.build, built.inspector, built.textSeed);
    if (!facts.ok) return { state: 'error', said: `Not yet: ${facts.reason}.` };
    const answer = evaluateCheck(parsed.check, facts.facts);
    return { state: answer.pass ? 'pass' : 'fail', said: spokenAnswer(answer) };
  } finally {
    built.inspector.free();
  }
}

/** The problems of one task that need builds: its start passes, its solution fails or has errors. */
async function taskProblems(assignment: Assignment, task: AssignmentTask, builder: GrammarBuilder): Promise<AssignmentProblem[]> {
  const problems: AssignmentProblem[] = [];
  const start = assignment.grammars[task.start];
  if (start) {
    const onStart = await judge(task.check, start.text, builder);
    if (onStart.state === 'pass') {
      problems.push({ line: task.checkLine, field: 'check', message: `the check already passes on the starting grammar (“${start.title}”: ${onStart.said}): a student who changes nothing would pass` });
    }
  }
  const onSolution = await judge(task.check, task.solution, builder);
  if (onSolution.error) {
    problems.push({ line: task.solutionLine + onSolution.error.line - 1, field: 'solution', message: `the solution grammar has an error: ${onSolution.error.message}` });
  } else if (onSolution.state !== 'pass') {
    problems.push({ line: task.checkLine, field: 'solution', message: `the solution does not pass its own check: ${onSolution.said}` });
  }
  return problems;
}

/** The problems of a grammar block: its errors, each at the file's line. */
async function grammarProblems(text: string, line: number, builder: GrammarBuilder): Promise<AssignmentProblem[]> {
  const built = await builder(text);
  if (!built.ok) return [{ line, field: 'grammar', message: `could not build this grammar: ${built.reason}` }];
  built.inspector.free();
  return built.build.diagnostics
    .where((severity) => severity === 'error')
    .slice(0, 5)
    .map((d) => ({ line: line + d.line - 1, field: 'grammar', message: `the grammar has an error: ${d.message}` }));
}

/**
 * The problems of a well-read assignment that need builds (assignment-file.ts reports the others;
 * a task it found incomplete is skipped here), sorted by line.
 */
export async function validateAssignment(assignment: Assignment, builder: GrammarBuilder): Promise<AssignmentProblem[]> {
  const problems: AssignmentProblem[] = [];
  for (const grammar of assignment.grammars) problems.push(...(await grammarProblems(grammar.text, grammar.line, builder)));
  for (const task of assignment.tasks) {
    if (task.check === '' || task.solution === '' || !parseCheck(task.check).ok) continue;
    problems.push(...(await taskProblems(assignment, task, builder)));
  }
  return problems.sort((a, b) => a.line - b.line);
}
