// The builds of assignment checks in node: the real core, as the studio's assignment worker builds
// (the grammar as written, tubes drawn). For tests/core/assignments.test.ts and check-assignment.test.ts.
import { directiveOfKind, inspectPlant, loadVocabulary, writtenDirective } from '../../web/src/core';
import { readAssignment, type AssignmentProblem } from '../../web/src/studio/learn/assignment-file';
import { validateAssignment, type GrammarBuilder } from '../../web/src/studio/learn/assignment-validate';
import { writtenSeed } from '../../web/src/studio/learn/written-seed';

export const nodeBuilder: GrammarBuilder = async (text) => {
  const { build, inspector } = inspectPlant(text, { tubes: true });
  const seed = writtenDirective(directiveOfKind(await loadVocabulary(), 'Seed'));
  return { ok: true, build, inspector, textSeed: writtenSeed(text, seed) };
};

/** Every problem of an assignment file: read, then built; by line. */
export async function assignmentProblems(text: string): Promise<AssignmentProblem[]> {
  const read = readAssignment(text);
  return [...read.problems, ...(await validateAssignment(read.assignment, nodeBuilder))].sort((a, b) => a.line - b.line);
}
