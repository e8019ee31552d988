// Opening and saving grammar files: `.lsys` (Meristem's language) as it is, Green, Lparser `.ls`,
// cpfg `.l` and L-Py `.lpy` through the core's importers, with their notes; text that is not UTF-8
// (old Lparser files) read as Windows-1252. Saving writes the editor's text as `NAME.lsys`.
import { importGrammar, importObject, type Dialect, type ImportedGrammar, type ObjectFile } from '../../core';
import { titleOf } from '../../share';
import { saveFile } from './save-file';

/** Largest grammar file opened (bytes). */
export const MAX_FILE_BYTES = 1_000_000;

/** What opening a file gives. */
export type OpenedFile =
  | {
      ok: true;
      /** The grammar in Meristem's language. */
      text: string;
      /** The dialect it was imported from; null for Meristem's own. */
      dialect: Dialect | null;
      /** What the importer could not translate, `line N: …` (or a note about the encoding). */
      notes: string[];
    }
  | { ok: false; error: string };

const DIALECT_NAMES: Record<Dialect, string> = { green: "Green's RL-systems", lparser: 'Lparser', cpfg: 'cpfg', lpy: 'L-Py' };

/** A dialect's name for people. */
export function dialectName(dialect: Dialect): string {
  return DIALECT_NAMES[dialect];
}

/** UTF-8 if the bytes are, else Windows-1252 (what pre-Unicode grammar files are written in). */
export function decodeText(bytes: Uint8Array): { text: string; utf8: boolean } {
  try {
    return { text: new TextDecoder('utf-8', { fatal: true }).decode(bytes), utf8: true };
  } catch {
    return { text: new TextDecoder('windows-1252').decode(bytes), utf8: false };
  }
}

/** A grammar file's bytes checked and decoded, before any import. */
export type CheckedFile =
  | {
      ok: true;
      text: string;
      /** Meristem's own language (`.lsys`): nothing to import. */
      lsys: boolean;
      /** A note about the encoding, when the file is not UTF-8. */
      notes: string[];
    }
  | { ok: false; error: string };

/** Checks a grammar file's size and that it is text, and decodes it (quick: the page does this itself). */
export function checkGrammarBytes(name: string, bytes: Uint8Array): CheckedFile {
  if (bytes.length > MAX_FILE_BYTES) {
    return { ok: false, error: `${name} is too large for a grammar (${bytes.length.toLocaleString('en-US')} bytes; at most ${MAX_FILE_BYTES.toLocaleString('en-US')})` };
  }
  if (bytes.includes(0)) return { ok: false, error: `${name} is not a text file` };
  const { text, utf8 } = decodeText(bytes);
  return { ok: true, text, lsys: /\.lsys$/i.test(name), notes: utf8 ? [] : ['The file is not UTF-8; it was read as Windows-1252.'] };
}

/**
 * Reads a grammar file: `.lsys` (and any file the importers do not recognise) as Meristem's
 * language; other dialects, told by extension or content, translated with notes. Requires the
 * core (for the importers): the studio calls it in the import worker.
 */
export function openGrammarBytes(name: string, bytes: Uint8Array): OpenedFile {
  const checked = checkGrammarBytes(name, bytes);
  if (!checked.ok) return checked;
  const { text, notes: encoding } = checked;
  if (checked.lsys) return { ok: true, text, dialect: null, notes: encoding };
  const imported = importGrammar(text, name);
  if (imported.dialect === null) return { ok: true, text, dialect: null, notes: encoding };
  const notes = imported.notes.map((n) => (n.line > 0 ? `line ${n.line}: ${n.message}` : n.message));
  return { ok: true, text: imported.text, dialect: imported.dialect, notes: [...encoding, ...notes] };
}

/** Largest total of files opened together (bytes): a vlab object is far smaller. */
export const MAX_OBJECT_BYTES = 32_000_000;

/**
 * Reads files opened together (a dropped folder, several files, a `.zip`): one grammar file
 * alone as {@link openGrammarBytes} does; otherwise a vlab object (its `.l` with its view file,
 * functions and colours) or an L-Py model, imported whole with its notes.
 */
export function openObjectBytes(files: ObjectFile[]): OpenedFile {
  if (files.length === 1 && !/\.zip$/i.test(files[0].name)) return openGrammarBytes(files[0].name, files[0].bytes);
  const total = files.reduce((n, f) => n + f.bytes.length, 0);
  if (total > MAX_OBJECT_BYTES) {
    return { ok: false, error: `the files are too large for a model (${total.toLocaleString('en-US')} bytes; at most ${MAX_OBJECT_BYTES.toLocaleString('en-US')})` };
  }
  return opened(importObject(files), 'no L-system file among them');
}

/** An import as the page shows it: notes as `line N: …`; no dialect is an error (`fallback` when no note says why). */
export function opened(imported: ImportedGrammar, fallback: string): OpenedFile {
  const notes = imported.notes.map((n) => (n.line > 0 ? `line ${n.line}: ${n.message}` : n.message));
  if (imported.dialect === null) return { ok: false, error: notes.join(' ') || fallback };
  return { ok: true, text: imported.text, dialect: imported.dialect, notes };
}

/** A file name for a grammar titled `title`: letters, digits, `-` and `_`, then `.lsys`. */
export function lsysFileName(title: string): string {
  const stem = title
    .normalize('NFKD')
    .replace(/[^\w\s-]/g, '')
    .trim()
    .replace(/[\s_]+/g, '-')
    .replace(/-+/g, '-')
    .slice(0, 60)
    .replace(/^-|-$/g, '')
    .toLowerCase();
  return `${stem || 'grammar'}.lsys`;
}

/** Downloads `text` as a `.lsys` file named after its title; returns the file name. */
export function saveGrammarFile(text: string): string {
  const name = lsysFileName(titleOf(text));
  saveFile(new TextEncoder().encode(text), name, 'text/plain');
  return name;
}
