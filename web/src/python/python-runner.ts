// Running a model through the L-system runtime (python/meristem_lsystem, `run(files, main,
// options)`) on a loaded Pyodide: the package's sources written into Pyodide's file system once,
// then one call of `run` per model, its result as JSON text. No DOM, no worker: the Python worker
// (python-worker.ts) calls these in the browser, the unit test in Node with Pyodide from
// node_modules.
import type { PyodideAPI } from 'pyodide';

/** What a model run is given: the contract of `run` (python/README.md). */
export interface PythonRunRequest {
  /** Every text file of the model, by name (an `.lpy` alone; a vlab object's `.l`, `.v`, `.func`…). */
  files: Record<string, string>;
  /** The name in `files` to run. */
  main: string;
  options: PythonRunOptions;
}

/** `run`'s options; what is left out takes the runtime's default. */
export interface PythonRunOptions {
  /** The dialect to run `main` in (the runtime tells it by the file when left out). */
  dialect?: 'lpy' | 'lpfg';
  /** Steps to derive; null: the model's own derivation length. */
  steps?: number | null;
  seed?: number;
  max_modules?: number;
  /** Seconds the derivation may take before the runtime stops it with an error. */
  time_limit?: number;
}

/** Where the package is written in Pyodide's file system (put on `sys.path`). */
export const PACKAGE_ROOT = '/meristem/python';

/**
 * The glue, in Python: imports the runtime and calls `run`; a runtime that raises (a bug of ours,
 * not the model's: `run` reports the model's errors in its result) is reported as a result with an
 * error too, so the page always gets the contract's shape.
 */
const GLUE = `
import json, sys, traceback
if ${JSON.stringify(PACKAGE_ROOT)} not in sys.path:
    sys.path.insert(0, ${JSON.stringify(PACKAGE_ROOT)})

def _meristem_run(request_json):
    request = json.loads(request_json)
    try:
        from meristem_lsystem import run
        result = run(request["files"], request["main"], request["options"])
        return json.dumps(result, allow_nan=False)
    except Exception as error:
        last = traceback.extract_tb(error.__traceback__)[-1:] or [None]
        where = f" ({last[0].filename.rsplit('/', 1)[-1]}:{last[0].lineno})" if last[0] else ""
        message = f"the Python runtime failed (a bug): {type(error).__name__}: {error}{where}"
        return json.dumps({"ok": False, "dialect": None, "steps": 0, "lstring": "", "materials": [], "notes": [],
                           "error": {"line": 0, "column": 0, "message": message}})
`;

/** Writes the package's sources (path under the import root → text) into Pyodide and defines the glue. */
export function installPackage(py: PyodideAPI, sources: Record<string, string>): void {
  if (Object.keys(sources).length === 0) throw new Error('the L-system runtime (python/meristem_lsystem) is not in this build');
  for (const [path, text] of Object.entries(sources)) {
    const file = `${PACKAGE_ROOT}/${path}`;
    py.FS.mkdirTree(file.slice(0, file.lastIndexOf('/')));
    py.FS.writeFile(file, text, { encoding: 'utf8' });
  }
  py.runPython(GLUE);
}

/** Runs one model; gives `run`'s result as JSON text (the contract's shape, `ok` false on any error). */
export function runModel(py: PyodideAPI, request: PythonRunRequest): string {
  const call = py.globals.get('_meristem_run') as ((json: string) => string) & { destroy?: () => void };
  try {
    return call(JSON.stringify(request));
  } finally {
    call.destroy?.();
  }
}
