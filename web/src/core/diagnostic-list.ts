// A build's diagnostics as columns (issue 50: a text of 100,000 problems). The build worker posts
// them to the page as a few typed arrays (the messages' UTF-8 one of them), whose buffers are
// transferred; the page makes a `Diagnostic` object only for those it reads (the first error, the
// markers, the Problems rows in view). 100,000 objects deserialised from the worker's message held
// the page's main thread for 60–190 ms a build, and their garbage as long again. The one module
// that knows the shape: the facade encodes (`encodeDiagnostics`), the worker posts a list's
// `columns` (their buffers transferred: `columnBuffers`), the page reads them (`new
// DiagnosticList`, which copies nothing).
import type { Diagnostic, Severity } from './types';

/** A list of diagnostics as it crosses from the build worker to the page: a bounded number of objects, whatever its length. */
export interface DiagnosticColumns {
  /** Per diagnostic: 1 an error, 0 a warning. */
  errors: Uint8Array;
  /** Per diagnostic: its code, as an index into `codes`. */
  codeIndices: Uint16Array;
  /** The distinct codes (`E0105`), each once. */
  codes: string[];
  /** Per diagnostic four numbers: `fromByte`, `toByte`, `line`, `column`. */
  places: Uint32Array;
  /**
   * Every message in UTF-8, one after another: transferred, where one string would be copied
   * (13–22 ms for 100,000 messages, against 1 ms to decode the thousand the markers show).
   */
  messages: Uint8Array;
  /** Per diagnostic: where its message ends in `messages` (it starts where the one before ends). */
  messageEnds: Uint32Array;
  /** The rows the list holds, in order, when not all ({@link DiagnosticList.where}). */
  rows?: Uint32Array;
}

/** The columns of `diagnostics` (in the worker: the page never encodes). */
export function encodeDiagnostics(diagnostics: readonly Diagnostic[]): DiagnosticColumns {
  const n = diagnostics.length;
  const errors = new Uint8Array(n);
  const codeIndices = new Uint16Array(n);
  const codes: string[] = [];
  const codeIndex = new Map<string, number>();
  const places = new Uint32Array(4 * n);
  const messageEnds = new Uint32Array(n);
  const encoder = new TextEncoder();
  let messages = new Uint8Array(1024);
  let used = 0;
  diagnostics.forEach((d, i) => {
    errors[i] = d.severity === 'error' ? 1 : 0;
    let code = codeIndex.get(d.code);
    if (code === undefined) codeIndex.set(d.code, (code = codes.push(d.code) - 1));
    codeIndices[i] = code;
    places[4 * i] = d.fromByte;
    places[4 * i + 1] = d.toByte;
    places[4 * i + 2] = d.line;
    places[4 * i + 3] = d.column;
    // A UTF-16 unit is at most 3 bytes of UTF-8.
    if (messages.length - used < 3 * d.message.length) {
      const grown = new Uint8Array(Math.max(2 * messages.length, used + 3 * d.message.length));
      grown.set(messages.subarray(0, used));
      messages = grown;
    }
    used += encoder.encodeInto(d.message, messages.subarray(used)).written;
    messageEnds[i] = used;
  });
  return { errors, codeIndices, codes, places, messages: messages.slice(0, used), messageEnds };
}

let decoder: TextDecoder | undefined;

/** A build's diagnostics, read from their columns: `at(i)` makes the object of one. */
export class DiagnosticList implements Iterable<Diagnostic> {
  /**
   * The list of `columns` (what the worker posted, or {@link encodeDiagnostics} made), their
   * arrays kept, not copied.
   */
  constructor(readonly columns: DiagnosticColumns) {}

  get length(): number {
    return (this.columns.rows ?? this.columns.errors).length;
  }

  /** The row of the columns of diagnostic `i`. */
  private row(i: number): number {
    return this.columns.rows ? this.columns.rows[i] : i;
  }

  severity(i: number): Severity {
    return this.columns.errors[this.row(i)] === 1 ? 'error' : 'warning';
  }

  code(i: number): string {
    return this.columns.codes[this.columns.codeIndices[this.row(i)]];
  }

  /** Where diagnostic `i`'s span starts: a UTF-8 byte offset into the source. */
  fromByte(i: number): number {
    return this.columns.places[4 * this.row(i)];
  }

  /** Where diagnostic `i`'s span ends (exclusive). */
  toByte(i: number): number {
    return this.columns.places[4 * this.row(i) + 1];
  }

  /** Diagnostic `i` (a new object), or undefined past the end. */
  at(i: number): Diagnostic | undefined {
    if (!(i >= 0 && i < this.length)) return undefined;
    const { places, messages, messageEnds } = this.columns;
    const r = this.row(i);
    const message = (decoder ??= new TextDecoder()).decode(messages.subarray(r === 0 ? 0 : messageEnds[r - 1], messageEnds[r]));
    const [fromByte, toByte, line, column] = places.subarray(4 * r, 4 * r + 4);
    return { severity: this.severity(i), code: this.code(i), message, fromByte, toByte, line, column };
  }

  /** The diagnostics whose severity and code `keep` keeps, in order (the columns shared). */
  where(keep: (severity: Severity, code: string) => boolean): DiagnosticList {
    const rows: number[] = [];
    for (let i = 0; i < this.length; i++) if (keep(this.severity(i), this.code(i))) rows.push(this.row(i));
    return rows.length === this.length ? this : new DiagnosticList({ ...this.columns, rows: Uint32Array.from(rows) });
  }

  /** Whether `test` is true of the severity and code of any diagnostic. */
  some(test: (severity: Severity, code: string) => boolean): boolean {
    for (let i = 0; i < this.length; i++) if (test(this.severity(i), this.code(i))) return true;
    return false;
  }

  /** How many diagnostics are of `severity` (all without it). */
  count(severity?: Severity): number {
    if (!severity) return this.length;
    const { errors, rows } = this.columns;
    let n = 0;
    for (let i = 0; i < this.length; i++) n += errors[rows ? rows[i] : i];
    return severity === 'error' ? n : this.length - n;
  }

  /** The first diagnostic of `severity`. */
  first(severity: Severity): Diagnostic | undefined {
    for (let i = 0; i < this.length; i++) if (this.severity(i) === severity) return this.at(i);
    return undefined;
  }

  /** Diagnostics `start` to `end` (exclusive; the end by default) as objects. */
  slice(start = 0, end = this.length): Diagnostic[] {
    const made: Diagnostic[] = [];
    for (let i = Math.max(0, start); i < Math.min(end, this.length); i++) made.push(this.at(i) as Diagnostic);
    return made;
  }

  *[Symbol.iterator](): Iterator<Diagnostic> {
    for (let i = 0; i < this.length; i++) yield this.at(i) as Diagnostic;
  }
}

/** The buffers of `columns`' arrays, to transfer with them (posted, they are not copied). */
export function columnBuffers(columns: DiagnosticColumns): ArrayBuffer[] {
  const { errors, codeIndices, places, messages, messageEnds, rows } = columns;
  return [errors, codeIndices, places, messages, messageEnds, ...(rows ? [rows] : [])].map((a) => a.buffer as ArrayBuffer).filter((b) => b.byteLength > 0);
}

/** The list of `diagnostics`. */
export function diagnosticList(diagnostics: readonly Diagnostic[]): DiagnosticList {
  return new DiagnosticList(encodeDiagnostics(diagnostics));
}

/** No diagnostics. */
export const NO_DIAGNOSTICS = /* @__PURE__ */ new DiagnosticList({
  errors: new Uint8Array(0),
  codeIndices: new Uint16Array(0),
  codes: [],
  places: new Uint32Array(0),
  messages: new Uint8Array(0),
  messageEnds: new Uint32Array(0),
});
