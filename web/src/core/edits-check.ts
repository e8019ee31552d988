// The check of an edits document that came from outside (a share link, a file), with the core's
// rules but without the core: a door of its own, so that what checks a link's branch edits loads
// with the first link that has some (share/codec.ts), never with the page.
import { EDITS_VERSION, type BranchEdit, type EditsDocument, type Vec3 } from './branches';

/** Limits of the edits document, as the core checks them (crate/src/branches/edits.rs). */
const MAX_EDITS = 100_000;
const MAX_PATH = 10_000;
const MAX_OFFSET = 1_000;

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

/** What a JSON value is, in words (as the core says it). */
function kind(value: unknown): string {
  if (value === null) return 'null';
  if (Array.isArray(value)) return 'a list';
  switch (typeof value) {
    case 'boolean':
      return 'true or false';
    case 'number':
      return 'a number';
    case 'string':
      return 'a string';
    default:
      return 'an object';
  }
}

/** What is wrong with one edit of a document, in the core's words (crate/src/branches/edits.rs), or null. */
function editProblem(edit: unknown): string | null {
  if (!isRecord(edit)) return `an edit is an object with "path" and "handles", not ${kind(edit)}`;
  const extra = Object.keys(edit).find((k) => k !== 'path' && k !== 'handles');
  if (extra !== undefined) return `unknown field "${extra}" (an edit holds only "path" and "handles")`;
  const { path, handles } = edit;
  if (path === undefined) return 'no "path"';
  if (!Array.isArray(path)) return `"path" must be a list of branch indices, not ${kind(path)}`;
  const bad = path.findIndex((i) => !(typeof i === 'number' && Number.isInteger(i) && i >= 0 && i <= 0xffffffff));
  if (bad >= 0) return `index ${bad} of "path" must be a whole number from 0 to ${0xffffffff}, not ${JSON.stringify(path[bad])}`;
  if (handles === undefined) return 'no "handles"';
  if (!Array.isArray(handles)) return `"handles" must be a list of 3 points (P1, P2, P3), not ${kind(handles)}`;
  if (handles.length !== 3) return `"handles" must hold 3 points (P1, P2, P3), not ${handles.length}`;
  for (const [n, h] of handles.entries()) {
    if (!Array.isArray(h) || h.length !== 3) return `handle P${n + 1} must be 3 numbers (heading, left, up), not ${Array.isArray(h) ? `${h.length} numbers` : kind(h)}`;
    const c = h.findIndex((v) => typeof v !== 'number');
    if (c >= 0) return `handle P${n + 1} must be 3 numbers (heading, left, up), but its number ${c + 1} is ${kind(h[c])}`;
  }
  if (path.length === 0 || path.length > MAX_PATH) return `a path has 1 to ${MAX_PATH} indices, not ${path.length}`;
  if (!(handles as number[][]).every((h) => h.every((v) => Number.isFinite(v) && Math.abs(v) <= MAX_OFFSET)))
    return `handle offsets must be finite numbers of at most ${MAX_OFFSET} branch lengths`;
  return null;
}

/**
 * Checks an edits document that came from outside (a share link, a file) with the core's rules,
 * without the core: version 1, at most 100,000 edits, each a path of 1 to 10,000 whole numbers
 * and three handles of three finite numbers of at most 1,000 branch lengths, no other fields.
 * Never throws; a failure says what is wrong.
 */
export function validateEdits(value: unknown): { ok: true; document: EditsDocument } | { ok: false; error: string } {
  const fail = (error: string) => ({ ok: false as const, error });
  if (!isRecord(value)) return fail('the edits are not a JSON object');
  const { version, edits } = value;
  if (typeof version === 'number' && Number.isInteger(version) && version > EDITS_VERSION)
    return fail(`the edits were written by a newer Meristem (version ${version}); this one reads version ${EDITS_VERSION}`);
  if (version !== EDITS_VERSION) return fail(`the edits have no "version": ${EDITS_VERSION}`);
  const extra = Object.keys(value).find((k) => k !== 'version' && k !== 'edits');
  if (extra !== undefined) return fail(`the edits document has an unknown field "${extra}" (it holds only "version" and "edits")`);
  if (!Array.isArray(edits)) return fail(edits === undefined ? 'the edits document has no "edits" list' : `"edits" must be a list of edits, not ${kind(edits)}`);
  if (edits.length > MAX_EDITS) return fail(`more than ${MAX_EDITS} edits`);
  const clean: BranchEdit[] = [];
  for (const [k, edit] of edits.entries()) {
    const problem = editProblem(edit);
    if (problem) return fail(`edit ${k}: ${problem}`);
    const { path, handles } = edit as { path: number[]; handles: number[][] };
    clean.push({ path: [...path], handles: handles.map((h) => [h[0], h[1], h[2]]) as [Vec3, Vec3, Vec3] });
  }
  return { ok: true, document: { version: EDITS_VERSION, edits: clean } };
}
