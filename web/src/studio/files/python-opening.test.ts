import { describe, expect, it } from 'vitest';
import { FakeJobWorker } from '../../build/fake-job-worker';
import { PythonClient, type PythonRunRequest } from '../../python';
import type { PythonWorkerRequest, PythonWorkerResponse } from '../../python/python-protocol';
import type { Notice } from '../page';
import type { OpenedFile } from './grammar-files';
import { openInPython } from './python-opening';

class FakePythonWorker extends FakeJobWorker<PythonWorkerRequest, PythonWorkerResponse> {}

const run: PythonRunRequest = { files: { 'models/tree.lpy': 'Axiom: A' }, main: 'models/tree.lpy', options: { dialect: 'lpy', steps: null, seed: 0 } };
const translated: OpenedFile = { ok: true, text: 'axiom: F', dialect: 'lpy', notes: ['line 1: Python imports are not translated'] };

/** A notice that records what it shows; its Stop button pressed with `stop()`. */
function fakeNotice() {
  const shown: string[] = [];
  let stop = () => {};
  const notice = {
    show: (_kind: string, message: string, _items: string[] = [], _topic?: string, actions: { run(): void }[] = []) => {
      shown.push(message);
      stop = () => actions[0]?.run();
    },
    hide: () => shown.push('(hidden)'),
  } as unknown as Notice;
  return { notice, shown, stop: () => stop() };
}

/** Opens `run` with a fake worker that answers `answers` once the run starts; what it opened and showed. */
async function opening(answers: PythonWorkerResponse[], pressStop = false, hand: OpenedFile = translated) {
  const worker = new FakePythonWorker();
  const python = new PythonClient(() => worker, () => 'http://site/pyodide/');
  const { notice, shown, stop } = fakeNotice();
  const derived: string[] = [];
  const pending = openInPython(run, hand, 'tree.lpy', {
    notice,
    python: () => python,
    derive: async (result, main) => {
      derived.push(`${main} | ${result}`);
      return { ok: true, text: 'axiom: F F', dialect: 'lpy', notes: [] };
    },
  });
  for (const answer of answers) worker.send(answer);
  if (pressStop) stop();
  return { opened: await pending, shown, derived, worker };
}

const result = (fields: object) => JSON.stringify({ ok: true, dialect: 'lpy', steps: 5, lstring: 'F F', materials: [], notes: [], error: null, ...fields });

describe('opening a model in Python', () => {
  it('says Python loads, then runs the file, and makes text of what it derived', async () => {
    const { opened, shown, derived } = await opening([{ kind: 'loading' }, { kind: 'running' }, { kind: 'done', result: result({}), millis: 1234 }]);
    expect(shown).toEqual(['Starting Python for tree.lpy…', 'Loading Python (about 13 MB, once)…', 'Running tree.lpy in Python…', '(hidden)']);
    expect(derived).toEqual([`models/tree.lpy | ${result({})}`]);
    expect(opened).toEqual({ ok: true, text: 'axiom: F F', dialect: 'lpy', notes: [] });
  });

  it('gives the model’s error at its line and column, as the first note of the hand translation', async () => {
    const error = { line: 7, column: 12, message: "NameError: name 'leng' is not defined" };
    const { opened, derived } = await opening([{ kind: 'running' }, { kind: 'done', result: result({ ok: false, error }), millis: 5 }]);
    expect(derived).toEqual([]);
    expect(opened).toEqual({
      ...translated,
      notes: ["Python stopped the model (tree.lpy, line 7, column 12): NameError: name 'leng' is not defined; this is the translation by hand.", ...(translated.ok ? translated.notes : [])],
    });
  });

  it('gives the model’s error alone, the text as it was, when there is no hand translation', async () => {
    const error = { line: 2, column: 0, message: 'SyntaxError: unclosed (' };
    const { opened } = await opening([{ kind: 'running' }, { kind: 'done', result: result({ ok: false, error }), millis: 5 }], false, { ok: false, error: 'nothing' });
    expect(opened).toEqual({ ok: false, error: 'Python stopped the model (tree.lpy, line 2): SyntaxError: unclosed (; your text is as it was' });
  });

  it('opens nothing when stopped, and ends the worker', async () => {
    const { opened, worker } = await opening([{ kind: 'running' }], true);
    expect(opened).toEqual({ ok: false, error: 'you stopped Python while it ran tree.lpy; your text is as it was' });
    expect(worker.terminated).toBe(true);
  });

  it('opens the hand translation, saying why, when Python cannot be loaded', async () => {
    const { opened } = await opening([{ kind: 'loading' }, { kind: 'failed', message: 'Python could not start: Failed to fetch' }]);
    expect(opened).toEqual({
      ok: true,
      text: 'axiom: F',
      dialect: 'lpy',
      notes: ['Python could not start: Failed to fetch: this is the translation by hand, without what only Python runs.', 'line 1: Python imports are not translated'],
    });
  });
});
