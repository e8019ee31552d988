// Opening assignments and submissions: from the studio's address (`?assignment=URL`,
// `#assignment=…`, `#submission=…`: assignment-links.ts), or from a file the user picks. Loaded
// only when one is asked for (learn-loader.ts reads the address with one test at startup).
import { fingerprint, addressRequest, assignmentUrl, unpackAssignment, unpackSubmission, type Submission } from './assignment-links.ts';
import { workerBuilder } from './assignment-builds.ts';
import { fetchAssignment } from './assignment-fetch.ts';
import { MAX_ASSIGNMENT_CHARS } from './assignment-file.ts';
import { AssignmentPanel, type AssignmentHost } from './assignment-panel.ts';

let panel: AssignmentPanel | undefined;

/** The page's assignment panel, made once. */
function thePanel(host: AssignmentHost): AssignmentPanel {
  panel ??= new AssignmentPanel(host, workerBuilder().builder, (file) => void openAssignmentFile(host, file));
  return panel;
}

/** Opens an assignment file the user picked (a lecturer checking their own file, or a student given one). */
export async function openAssignmentFile(host: AssignmentHost, file: File): Promise<void> {
  const shown = thePanel(host);
  if (file.size > MAX_ASSIGNMENT_CHARS * 4) return shown.showError(`${file.name} is larger than an assignment may be (${MAX_ASSIGNMENT_CHARS.toLocaleString('en')} characters).`);
  shown.show(await file.text(), { kind: 'file', name: file.name });
}

/** The assignment of a submission: fetched from its URL, or the text it carries. */
async function submittedAssignment(submission: Submission): Promise<{ ok: true; text: string } | { ok: false; error: string }> {
  if (submission.url === undefined) return { ok: true, text: submission.text ?? '' };
  const url = assignmentUrl(submission.url, location.href);
  if (!url.ok) return url;
  return fetchAssignment(url.url, location.origin);
}

/** Opens a submission link: the student's grammar in the editor (asking first), its verdicts in the panel. */
async function openSubmission(host: AssignmentHost, packed: string): Promise<void> {
  const shown = thePanel(host);
  shown.loading('the submission');
  const unpacked = await unpackSubmission(packed);
  if (!unpacked.ok) return shown.showError(`This submission link could not be opened: ${unpacked.error}.`);
  const { submission } = unpacked;
  const assignment = await submittedAssignment(submission);
  const who = submission.name ? `${submission.name}’s submission` : 'a submission';
  if (!assignment.ok) return shown.showError(`The assignment of ${who} could not be read. ${assignment.error}`);
  const source = submission.url === undefined ? ({ kind: 'packed' } as const) : ({ kind: 'url', url: submission.url } as const);
  const opened = await host.open(submission.grammar, who, `submission/${submission.fingerprint}`);
  if (!opened) return shown.showError(`${who} was not opened: your text stays in the editor. Open the link again to see it.`);
  shown.show(assignment.text, source, { submission, changed: fingerprint(assignment.text) !== submission.fingerprint });
}

/** What opening from the address needs: the studio, and its first plant (then a submission may replace the text). */
export interface AddressHost extends AssignmentHost {
  preview: NonNullable<AssignmentHost['preview']> & { nextDelivery(): Promise<void> };
}

/** Waits for the studio's first plant (at most 20 s: a first build that crashed is never delivered). */
async function firstPlant(host: AddressHost): Promise<void> {
  if (host.preview.lastResult === undefined) await Promise.race([host.preview.nextDelivery(), new Promise((done) => setTimeout(done, 20_000))]);
}

/**
 * Opens what the studio's address asks for, if anything: an assignment, or a submission; after
 * the first plant, so that the studio is whole when the student's grammar replaces its text.
 */
export async function openFromAddress(host: AddressHost): Promise<void> {
  const request = addressRequest(location);
  if (request.kind === 'none') return;
  await firstPlant(host);
  if (request.kind === 'submission') {
    // Not opened again by a reload: the page's text is then the lecturer's own again.
    history.replaceState(null, '', `${location.pathname}${location.search}`);
    return openSubmission(host, request.packed);
  }
  const shown = thePanel(host);
  if (request.kind === 'packed') {
    shown.loading('the assignment');
    const unpacked = await unpackAssignment(request.packed);
    return unpacked.ok ? shown.show(unpacked.text, { kind: 'packed' }) : shown.showError(`This assignment link could not be opened: ${unpacked.error}.`);
  }
  const url = assignmentUrl(request.url, location.href);
  if (!url.ok) return shown.showError(`The assignment could not be opened: ${url.error}.`);
  shown.loading(url.url);
  const fetched = await fetchAssignment(url.url, location.origin);
  if (fetched.ok) shown.show(fetched.text, { kind: 'url', url: url.url });
  else shown.showError(fetched.error);
}
