// The Python worker: Pyodide (Python 3.14 in WebAssembly), loaded on the first model that needs it
// from the site's own `pyodide/` folder (scripts/pyodide-plugin.ts; the service worker caches it on
// that first use), with the L-system runtime's sources written into its file system; then each
// request runs one model through `run` (python-runner.ts). The worker lives on between models (a
// second model does not load Python again); the page terminates it to stop a model, and then starts
// a fresh one.
// The page's Content-Security-Policy (index.html) does not reach into this worker: a worker has the
// policy its own script is served with. Pyodide compiles WebAssembly and builds its JavaScript glue
// with eval (Emscripten's EM_ASM), which the page's `script-src 'self' 'wasm-unsafe-eval'` would
// refuse; the worker is started from the page's own origin (`worker-src 'self'`) and fetches only
// from it (`pyodide/…`), so the page's policy holds as it was.
import type { loadPyodide as LoadPyodide, PyodideAPI } from 'pyodide';
import { packageSources } from './python-package';
import type { PythonWorkerRequest, PythonWorkerResponse } from './python-protocol';
import { installPackage, runModel } from './python-runner';

let python: Promise<PyodideAPI> | undefined;

function reply(response: PythonWorkerResponse): void {
  postMessage(response);
}

/** Pyodide started, with the runtime installed (once per worker). */
async function startPython(indexURL: string): Promise<PyodideAPI> {
  const { loadPyodide } = (await import(/* @vite-ignore */ `${indexURL}pyodide.mjs`)) as { loadPyodide: typeof LoadPyodide };
  const py = await loadPyodide({ indexURL, stdout: () => {}, stderr: () => {} });
  installPackage(py, packageSources());
  return py;
}

addEventListener('message', async (event: MessageEvent<PythonWorkerRequest>) => {
  const { indexURL, run } = event.data;
  if (!python) {
    reply({ kind: 'loading' });
    python = startPython(indexURL);
  }
  let py: PyodideAPI;
  try {
    py = await python;
  } catch (error) {
    python = undefined;
    reply({ kind: 'failed', message: `Python could not start: ${error instanceof Error ? error.message : String(error)}` });
    return;
  }
  reply({ kind: 'running' });
  const started = performance.now();
  try {
    reply({ kind: 'done', result: runModel(py, run), millis: Math.round(performance.now() - started) });
  } catch (error) {
    // Pyodide itself broke (out of memory, a stack overflow in WebAssembly): this worker is spent.
    reply({ kind: 'failed', message: `Python stopped: ${error instanceof Error ? error.message : String(error)}` });
  }
});
