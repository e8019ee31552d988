// Python in the studio (issue 49): L-Py and lpfg models run by the L-system runtime
// (python/meristem_lsystem) on Pyodide, in a worker loaded on the first model that needs it
// (python-worker.ts), never in the first load. The page's side is python-client.ts.
export { PythonClient, createPythonWorker, pyodideIndexURL, type PythonJob, type PythonOutcome, type PythonResult, type PythonState, type PythonWorkerLike } from './python-client';
export type { PythonRunOptions, PythonRunRequest } from './python-runner';
