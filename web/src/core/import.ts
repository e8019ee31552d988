// The facade over the core's importers (`crate/src/import`): another dialect's text in, Meristem
// text and notes out. The studio's file opening (studio/files/grammar-files.ts) calls this.
import {
  importDerived as coreImportDerived,
  importGrammar as coreImportGrammar,
  importObject as coreImportObject,
  needsPython as coreNeedsPython,
  pythonMain as corePythonMain,
} from '../../../crate/pkg/meristem.js';
import { guarded } from './init';
import { assertIoReady } from './io';

/** The notations the core imports: Green's RL-systems, Lparser `.ls`, cpfg `.l`, L-Py `.lpy`. */
export type Dialect = 'green' | 'lparser' | 'cpfg' | 'lpy';

/** Something the importer could not translate, or translated only approximately. */
export interface ImportNote {
  /** 1-based line of the imported text; 0 when the note concerns the whole file. */
  line: number;
  message: string;
}

/** The result of {@link importGrammar}. */
export interface ImportedGrammar {
  /** The grammar in Meristem's language (empty when the dialect could not be told). */
  text: string;
  /** One note per construct that was not translated, in line order. */
  notes: ImportNote[];
  /** The dialect read, or `null` when neither the name nor the content told it. */
  dialect: Dialect | null;
}

/**
 * Translates a file written in another L-system dialect into Meristem's language. `fileName`
 * (e.g. `tree.ls`) tells the dialect by its extension, else the content does; a dialect name
 * (`lparser`, …) may be given instead to force one. Never throws on odd input: what cannot be
 * translated comes back as notes. Requires {@link initIo} to have finished.
 */
export function importGrammar(text: string, fileName: string): ImportedGrammar {
  assertIoReady();
  return JSON.parse(guarded(() => coreImportGrammar(text, fileName))) as ImportedGrammar;
}

/** One file of what is opened together: its name (a path inside the dropped folder) and bytes. */
export interface ObjectFile {
  name: string;
  bytes: Uint8Array;
}

/**
 * Imports files opened together as one model: a vlab object (its `.l` with the view file `.v`,
 * function files `.func`/`.fset` and colour map `.map` or materials `.mat`), as a folder's files,
 * several files or a `.zip`; or an L-Py model. Never throws: a broken archive or a folder without
 * an L-system comes back as a note with `dialect` null. Requires {@link initIo} to have finished.
 */
export function importObject(files: ObjectFile[]): ImportedGrammar {
  assertIoReady();
  const { names, bytes, lengths } = packed(files);
  return JSON.parse(guarded(() => coreImportObject(names, bytes, lengths))) as ImportedGrammar;
}

/** Files as the boundary takes them: names, all bytes one after the other, each file's length. */
function packed(files: ObjectFile[]): { names: string[]; bytes: Uint8Array; lengths: Uint32Array } {
  const bytes = new Uint8Array(files.reduce((n, f) => n + f.bytes.length, 0));
  let at = 0;
  for (const f of files) {
    bytes.set(f.bytes, at);
    at += f.bytes.length;
  }
  return { names: files.map((f) => f.name), bytes, lengths: new Uint32Array(files.map((f) => f.bytes.length)) };
}

/** The file of a model that Python runs, and the dialect it is run in (the runtime's `options.dialect`). */
export interface PythonRoute {
  main: string;
  dialect: 'lpy' | 'lpfg';
}

/**
 * The core's rule for the Python route: the file of `files` that Python runs, when they are an
 * L-Py model or an lpfg object and their hand translation (`translation`, what
 * {@link importGrammar} or {@link importObject} gave) falls short (no axiom, a note of something
 * dropped or approximated, or no plant); null when the translation is used. Requires {@link initIo}.
 */
export function pythonRoute(files: ObjectFile[], translation: ImportedGrammar): PythonRoute | null {
  assertIoReady();
  const { names, bytes, lengths } = packed(files);
  const route = JSON.parse(guarded(() => corePythonMain(names, bytes, lengths))) as PythonRoute | null;
  if (route === null) return null;
  return guarded(() => coreNeedsPython(JSON.stringify(translation))) ? route : null;
}

/**
 * Meristem text from a model Python ran: `resultJson` is the runtime's result for the file `main`
 * of `files` (the files it was given), run with `seed`; the derived string goes through the
 * importers (with an lpfg object's view file, functions and colours). Requires {@link initIo}.
 */
export function importDerived(resultJson: string, main: string, files: ObjectFile[], seed: number): ImportedGrammar {
  assertIoReady();
  const { names, bytes, lengths } = packed(files);
  return JSON.parse(guarded(() => coreImportDerived(resultJson, main, names, bytes, lengths, seed))) as ImportedGrammar;
}
