// Opening a model that Python runs (an L-Py model or an lpfg object the hand translation does not
// reach): the notice says "Loading Python (about 13 MB, once)…" while Pyodide is fetched (the first
// model only), then "Running FILE in Python…", each with Stop; what Python derived becomes Meristem
// text in the import worker. The user's text is never touched before that text exists: a model
// stopped leaves the editor as it was. A model whose run stops with an error (at its line), or
// that Python cannot run at all (offline before the first model, a browser without
// WebAssembly), opens as its hand translation with a first note saying why, as the CLI's import
// does; when there is no translation either, the error alone, the editor as it was.
import { PythonClient, type PythonOutcome, type PythonResult, type PythonRunRequest, type PythonState } from '../../python';
import type { Notice } from '../page';
import type { OpenedFile } from './grammar-files';

/** The notice's topic while Python loads or runs (only its own notice is taken back). */
const PYTHON = 'python';

/** What opening a model in Python uses. */
export interface PythonOpeningParts {
  notice: Notice;
  python: () => PythonClient;
  /** Makes Meristem text of what Python derived (`result`, the runtime's JSON) for `main`, in the import worker. */
  derive(result: string, main: string): Promise<OpenedFile>;
}

let shared: PythonClient | undefined;

/** The page's one Python client: Pyodide loads once and serves every model after. */
export function pagePython(): PythonClient {
  return (shared ??= new PythonClient());
}

/** What the notice says in each state ('starting': until the worker says which). */
function stateMessage(state: PythonState | 'starting', main: string): string {
  if (state === 'starting') return `Starting Python for ${main}…`;
  return state === 'loading' ? 'Loading Python (about 13 MB, once)…' : `Running ${main} in Python…`;
}

/** Runs `run` in Python and opens what it derived; `translated` is the hand translation (`name`: what was opened). */
export async function openInPython(run: PythonRunRequest, translated: OpenedFile, name: string, parts: PythonOpeningParts): Promise<OpenedFile> {
  const { notice } = parts;
  const main = baseName(run.main);
  let job: { stop(): void } | undefined;
  const show = (state: PythonState | 'starting') => notice.show('info', stateMessage(state, main), [], PYTHON, [{ label: 'Stop', testid: 'python-stop', run: () => job?.stop() }]);
  show('starting');
  const started = parts.python().run(run, show);
  job = started;
  const outcome = await started.done;
  notice.hide(PYTHON);
  return openOutcome(outcome, translated, run.main, name, parts);
}

/** The text or error an outcome gives; `path` is the file Python ran. */
function openOutcome(outcome: PythonOutcome, translated: OpenedFile, path: string, name: string, parts: PythonOpeningParts): Promise<OpenedFile> | OpenedFile {
  const main = baseName(path);
  switch (outcome.kind) {
    case 'done': {
      const { result } = outcome;
      if (!result.ok) return stoppedByPython(result.error, translated, main);
      return parts.derive(outcome.json, path);
    }
    case 'stopped':
      return { ok: false, error: `you stopped Python while it ran ${name}; your text is as it was` };
    case 'timeout':
      return { ok: false, error: `Python ran ${name} for more than ${Math.round(outcome.seconds)} s, so it was stopped; your text is as it was` };
    case 'failed':
      if (!translated.ok) return { ok: false, error: outcome.message };
      return { ...translated, notes: [`${outcome.message}: this is the translation by hand, without what only Python runs.`, ...translated.notes] };
  }
}

/**
 * A model Python stopped (its error at its line): the hand translation, with that error as its
 * first note, when there is one (as the CLI's import does); else the error, the editor as it was.
 */
function stoppedByPython(error: PythonResult['error'], translated: OpenedFile, main: string): OpenedFile {
  const where = error && error.line > 0 ? `, line ${error.line}${error.column > 0 ? `, column ${error.column}` : ''}` : '';
  const why = `Python stopped the model (${main}${where}): ${error?.message ?? 'no reason given'}`;
  if (!translated.ok || translated.text.trim() === '') return { ok: false, error: `${why}; your text is as it was` };
  return { ...translated, notes: [`${why}; this is the translation by hand.`, ...translated.notes] };
}

/** A path's last part. */
function baseName(path: string): string {
  return path.slice(Math.max(path.lastIndexOf('/'), path.lastIndexOf('\\')) + 1);
}
