// Reading an assignment file from the lecturer's own site. The studio is on another origin, so
// the lecturer's server must allow it (CORS): when the browser refuses the file, the answer says
// exactly which header the server needs, so that the lecturer can fix it or open the file instead.
// Limits: the file's size (read as a stream, stopped past the limit) and the time it takes.
import { MAX_ASSIGNMENT_CHARS } from './assignment-file.ts';

/** How long reading the file may take. */
const FETCH_TIMEOUT_MS = 20_000;

/** The file's text, or why not (`cors`: the browser refused it for want of the header). */
export type Fetched = { ok: true; text: string } | { ok: false; error: string; cors: boolean };

/** What the lecturer's server must send for the studio at `origin` to read the file. */
export function corsAdvice(url: string, origin: string): string {
  return (
    `The browser did not let the studio read ${url}. If the file is there, its server must allow other sites to read it: ` +
    `it must send the header “Access-Control-Allow-Origin: *” (or “Access-Control-Allow-Origin: ${origin}”) with the file. ` +
    'GitHub Pages, GitLab Pages and raw.githubusercontent.com send it; on Apache add “Header set Access-Control-Allow-Origin "*"” ' +
    'to the folder’s .htaccess, on nginx “add_header Access-Control-Allow-Origin *;”. Or download the file and open it here.'
  );
}

/** Reads the body up to the limit. */
async function limitedText(response: Response): Promise<string | null> {
  const declared = Number(response.headers.get('content-length') ?? '0');
  if (declared > MAX_ASSIGNMENT_CHARS * 4) return null;
  const reader = response.body?.getReader();
  if (!reader) return response.text();
  const decoder = new TextDecoder();
  let text = '';
  for (;;) {
    const { done, value } = await reader.read();
    if (done) return text + decoder.decode();
    text += decoder.decode(value, { stream: true });
    if (text.length > MAX_ASSIGNMENT_CHARS) {
      await reader.cancel();
      return null;
    }
  }
}

/** Whether the server answers at all when CORS is not asked for: then it was CORS that refused. */
async function reachable(url: string): Promise<boolean> {
  try {
    await fetch(url, { mode: 'no-cors', credentials: 'omit', signal: AbortSignal.timeout(FETCH_TIMEOUT_MS) });
    return true;
  } catch {
    return false;
  }
}

/** Fetches an assignment file; never throws. */
export async function fetchAssignment(url: string, origin: string): Promise<Fetched> {
  let response: Response;
  try {
    response = await fetch(url, { mode: 'cors', credentials: 'omit', redirect: 'follow', signal: AbortSignal.timeout(FETCH_TIMEOUT_MS) });
  } catch (error) {
    if (error instanceof DOMException && error.name === 'TimeoutError') return { ok: false, error: `${url} did not answer within ${FETCH_TIMEOUT_MS / 1000} s`, cors: false };
    if (await reachable(url)) return { ok: false, error: corsAdvice(url, origin), cors: true };
    return { ok: false, error: `Could not reach ${url} (check the address and the connection). If the file is there, its server must also send the header “Access-Control-Allow-Origin: *”.`, cors: true };
  }
  if (!response.ok) return { ok: false, error: `${url} answered ${response.status} ${response.statusText}`.trim() + ': check the address.', cors: false };
  const text = await limitedText(response).catch(() => undefined);
  if (text === undefined) return { ok: false, error: `the connection broke while ${url} was read`, cors: false };
  if (text === null) return { ok: false, error: `${url} is larger than an assignment may be (${MAX_ASSIGNMENT_CHARS.toLocaleString('en')} characters)`, cors: false };
  if (/^\s*<(!doctype html|html)/i.test(text)) {
    return { ok: false, error: `${url} is a web page, not the assignment’s Markdown file: link the file itself (on GitHub, its “Raw” address)`, cors: false };
  }
  return { ok: true, text };
}
