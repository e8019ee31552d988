// Where an assignment comes from and where a student's work goes, as links of the studio's address:
//
//   ?assignment=https://lecturer.example/a1.md   the file on the lecturer's site (fetched with CORS)
//   #assignment=1.<packed Markdown>               the file itself, packed as share links are
//   #submission=1.<packed JSON>                   a student's work: the assignment's identity (its
//                                                 URL, or its text when it came packed, and its
//                                                 fingerprint), their grammar, their name
//
// Every link is hostile until read: sizes are limited, the JSON's shape is checked, nothing in it is
// trusted but the grammar's text, which is only ever built and shown as text. A submission's
// verdicts are never in the link: they are computed again where it is opened.
import { loadCodec, MAX_FRAGMENT, MAX_TEXT } from '../../share';
import { MAX_ASSIGNMENT_CHARS } from './assignment-file.ts';

/** The format version of packed assignments and submissions. */
const VERSION = 1;
/** Longest assignment URL accepted. */
const MAX_URL = 2048;
/** Longest student name kept. */
export const MAX_NAME = 120;

/** Where an assignment came from. */
export type AssignmentSource = { kind: 'url'; url: string } | { kind: 'packed' } | { kind: 'file'; name: string };

/** A student's work on an assignment. */
export interface Submission {
  /** The assignment's URL, when it was opened from one. */
  url?: string;
  /** The assignment's text, when it came packed in a link or from a file (no URL to fetch it from). */
  text?: string;
  /** The {@link fingerprint} of the assignment's text the student worked on. */
  fingerprint: string;
  /** The assignment's title, as the student saw it. */
  title: string;
  /** The student's grammar. */
  grammar: string;
  /** The name the student gave, or ''. */
  name: string;
}

/** What the address asks for. */
export type AddressRequest = { kind: 'url'; url: string } | { kind: 'packed'; packed: string } | { kind: 'submission'; packed: string } | { kind: 'none' };

/** Reads the studio's address: an assignment's URL, a packed assignment, a submission, or none. */
export function addressRequest(location: Pick<Location, 'search' | 'hash'>): AddressRequest {
  const hash = /^#(assignment|submission)=(\d+\.[A-Za-z0-9_-]*)$/.exec(location.hash);
  if (hash) return { kind: hash[1] === 'submission' ? 'submission' : 'packed', packed: hash[2] };
  const url = new URLSearchParams(location.search).get('assignment');
  return url ? { kind: 'url', url } : { kind: 'none' };
}

/** A URL an assignment may be fetched from (http or https, not too long), or why not. */
export function assignmentUrl(text: string, base: string): { ok: true; url: string } | { ok: false; error: string } {
  if (text.length > MAX_URL) return { ok: false, error: `the assignment’s address is longer than ${MAX_URL} characters` };
  let url: URL;
  try {
    url = new URL(text, base);
  } catch {
    return { ok: false, error: `“${text.slice(0, 80)}” is not a web address` };
  }
  if (url.protocol !== 'https:' && url.protocol !== 'http:') return { ok: false, error: `an assignment is read from an http or https address, not ${url.protocol}` };
  if (url.protocol === 'http:' && new URL(base).protocol === 'https:' && !['localhost', '127.0.0.1'].includes(url.hostname)) {
    return { ok: false, error: `the studio is served over https, and a browser does not let it read a file over http (${url.href}): put the file on an https address` };
  }
  return { ok: true, url: url.href };
}

/**
 * The fingerprint of an assignment's text (line ends normalized): 16 hex digits of two FNV-1a
 * hashes. It names a version of the file, so that a submission says which one the student saw; it
 * is not a signature (a file in a link can be changed with its fingerprint).
 */
export function fingerprint(text: string): string {
  const normalized = text.replace(/\r\n?/g, '\n');
  let a = 0x811c9dc5;
  let b = 0x01000193 ^ normalized.length;
  for (let i = 0; i < normalized.length; i++) {
    const c = normalized.charCodeAt(i);
    a = Math.imul(a ^ c, 0x01000193) >>> 0;
    b = Math.imul(b ^ c ^ (i & 0xff), 0x5bd1e995) >>> 0;
  }
  return a.toString(16).padStart(8, '0') + b.toString(16).padStart(8, '0');
}

/** The studio's address (without query or fragment) with `suffix`. */
export function studioAddress(location: Pick<Location, 'origin' | 'pathname'>, suffix: string): string {
  return `${location.origin}${location.pathname}${suffix}`;
}

/** The link that opens an assignment for students: its URL's, or the file packed into the link. */
export async function assignmentLink(location: Pick<Location, 'origin' | 'pathname'>, source: AssignmentSource, text: string): Promise<string> {
  if (source.kind === 'url') return studioAddress(location, `?assignment=${encodeURIComponent(source.url)}`);
  return studioAddress(location, fragment('assignment', await (await loadCodec()).packText(text)));
}

/** The fragment of a packed assignment or a submission: `#assignment=1.…`, `#submission=1.…`. */
function fragment(kind: 'assignment' | 'submission', packed: string): string {
  return ['#', kind, '=', VERSION, '.', packed].join('');
}

/** The link of a student's work (its fragment is checked against the length a link may have). */
export async function submissionLink(location: Pick<Location, 'origin' | 'pathname'>, submission: Submission): Promise<{ ok: true; link: string } | { ok: false; error: string }> {
  const packed = await (await loadCodec()).packText(JSON.stringify({ v: VERSION, ...submission }));
  if (packed.length > MAX_FRAGMENT) return { ok: false, error: `the link would be ${packed.length.toLocaleString('en')} characters long, and a link holds at most ${MAX_FRAGMENT.toLocaleString('en')}` };
  return { ok: true, link: studioAddress(location, fragment('submission', packed)) };
}

/** The text inside a packed link (`1.<payload>`), or why it cannot be read. */
async function unpack(packed: string, what: string): Promise<{ ok: true; text: string } | { ok: false; error: string }> {
  if (packed.length > MAX_FRAGMENT) return { ok: false, error: `the ${what} link is too long (${packed.length} characters; at most ${MAX_FRAGMENT})` };
  const dot = packed.indexOf('.');
  const version = Number(packed.slice(0, dot));
  if (version !== VERSION) return { ok: false, error: `the ${what} link was made by ${version > VERSION ? 'a newer' : 'another'} Meristem (format ${version})` };
  try {
    return await (await loadCodec()).unpackText(packed.slice(dot + 1));
  } catch {
    return { ok: false, error: 'the page could not load its link reader (check the connection, then reload)' };
  }
}

/** The assignment's text packed in a link. */
export async function unpackAssignment(packed: string): Promise<{ ok: true; text: string } | { ok: false; error: string }> {
  const unpacked = await unpack(packed, 'assignment');
  if (unpacked.ok && unpacked.text.length > MAX_ASSIGNMENT_CHARS) return { ok: false, error: `the assignment in the link is longer than ${MAX_ASSIGNMENT_CHARS.toLocaleString('en')} characters` };
  return unpacked;
}

const isRecord = (value: unknown): value is Record<string, unknown> => typeof value === 'object' && value !== null && !Array.isArray(value);
const optionalString = (value: unknown, max: number) => value === undefined || (typeof value === 'string' && value.length <= max);

/** A student's work from its link, its shape checked (never its verdicts: there are none in it). */
export async function unpackSubmission(packed: string): Promise<{ ok: true; submission: Submission } | { ok: false; error: string }> {
  const unpacked = await unpack(packed, 'submission');
  if (!unpacked.ok) return unpacked;
  let json: unknown;
  try {
    json = JSON.parse(unpacked.text);
  } catch {
    return { ok: false, error: 'the submission link does not hold valid JSON' };
  }
  if (!isRecord(json)) return { ok: false, error: 'the submission link does not hold a submission' };
  const { url, text, fingerprint: print, title, grammar, name } = json;
  if (typeof grammar !== 'string' || grammar.length > MAX_TEXT) return { ok: false, error: 'the submission link holds no grammar (or one too long)' };
  if (typeof print !== 'string' || !/^[0-9a-f]{16}$/.test(print)) return { ok: false, error: 'the submission link does not say which assignment it answers' };
  if (!optionalString(url, MAX_URL) || !optionalString(text, MAX_ASSIGNMENT_CHARS) || !optionalString(title, 500) || !optionalString(name, MAX_NAME)) {
    return { ok: false, error: 'the submission link’s assignment or name is malformed' };
  }
  if (url === undefined && text === undefined) return { ok: false, error: 'the submission link has neither the assignment’s address nor its text' };
  const submission: Submission = { fingerprint: print, title: (title as string | undefined) ?? '', grammar, name: (name as string | undefined) ?? '' };
  if (url !== undefined) submission.url = url as string;
  if (text !== undefined) submission.text = text as string;
  return { ok: true, submission };
}
