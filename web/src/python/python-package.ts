// The L-system runtime's Python sources (python/meristem_lsystem/ at the repository root), bundled
// as text into the Python worker's chunk (never the first load): the worker writes them into
// Pyodide's file system and imports the package from there.

/** Every `.py` of the package, by its path inside the glob's folder. */
const SOURCES = import.meta.glob('../../../python/meristem_lsystem/**/*.py', { query: '?raw', import: 'default', eager: true }) as Record<string, string>;

/** The package's folder name, as Python imports it. */
export const PACKAGE = 'meristem_lsystem';

/** The package's files: path under the import root (`meristem_lsystem/x.py`) → source text. */
export function packageSources(): Record<string, string> {
  const files: Record<string, string> = {};
  for (const [path, text] of Object.entries(SOURCES)) {
    const at = path.indexOf(`/${PACKAGE}/`);
    if (at >= 0) files[path.slice(at + 1)] = text;
  }
  return files;
}
