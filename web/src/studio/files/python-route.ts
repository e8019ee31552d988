// The Python route of opening files, in the import worker: whether Python runs what was opened
// (the core's rule: an L-Py model or an lpfg object whose hand translation falls short), with
// what files (a `.zip` unpacked, binary files left out); and Meristem text from what Python
// derived (the core's importDerived, with an lpfg object's view file, functions and colours).
// The page runs the model in between (python-opening.ts).
import { unzipSync } from 'fflate';
import { importDerived, pythonRoute, type ImportedGrammar, type ObjectFile } from '../../core';
import type { PythonRunRequest } from '../../python';
import { decodeText, MAX_FILE_BYTES, MAX_OBJECT_BYTES, opened, type OpenedFile } from './grammar-files';

/** The seed a model is run with in Python (the runtime's default; the same seed, the same plant). */
export const PYTHON_SEED = 0;

/**
 * What to run in Python when `translated`, the hand translation of `files` (one file or an
 * object), falls short (the core's rule): the model's text files, the one to run and its dialect;
 * null when the translation is used. Binary files (textures) are left out: the runtime reads text.
 */
export function pythonRequest(given: ObjectFile[], translated: OpenedFile): PythonRunRequest | null {
  if (translated.ok && translated.dialect === null) return null; // Meristem's own language
  const files = unpacked(given);
  if (files === null) return null;
  const notes = translated.ok ? translated.notes.map((message) => ({ line: 0, message })) : [];
  const translation: ImportedGrammar = { text: translated.ok ? translated.text : '', notes, dialect: translated.ok ? translated.dialect : null };
  const route = pythonRoute(files, translation);
  if (route === null) return null;
  const texts: Record<string, string> = {};
  for (const file of files) if (!file.bytes.includes(0)) texts[file.name] = decodeText(file.bytes).text;
  return { files: texts, main: route.main, options: { dialect: route.dialect, steps: null, seed: PYTHON_SEED } };
}

/**
 * The files with any `.zip` among them unpacked (folders and files over {@link MAX_FILE_BYTES}
 * left out), as the core's importers unpack them; null when an archive is broken or unpacks to
 * more than {@link MAX_OBJECT_BYTES}.
 */
export function unpacked(files: ObjectFile[]): ObjectFile[] | null {
  const all: ObjectFile[] = [];
  let total = 0;
  for (const file of files) {
    if (!/\.zip$/i.test(file.name)) {
      all.push(file);
      continue;
    }
    try {
      const inner = unzipSync(file.bytes, { filter: (f) => !f.name.endsWith('/') && !f.name.startsWith('__MACOSX/') && f.originalSize <= MAX_FILE_BYTES });
      for (const [name, bytes] of Object.entries(inner)) {
        total += bytes.length;
        if (total > MAX_OBJECT_BYTES) return null;
        all.push({ name, bytes });
      }
    } catch {
      return null;
    }
  }
  return all;
}

/**
 * Meristem text from what Python derived for `main` (`resultJson`, the runtime's result) with the
 * files it ran (the view file, functions and colours of an lpfg object still apply). The text
 * says in its first lines that Python derived it, in how many steps, with which seed.
 */
export function openDerivedBytes(resultJson: string, main: string, files: ObjectFile[]): OpenedFile {
  return opened(importDerived(resultJson, main, unpacked(files) ?? files, PYTHON_SEED), `Python's result for ${main} could not be read`);
}
