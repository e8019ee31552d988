// The text's problems as the editor reads them: the core's diagnostics (a DiagnosticList, their
// columns as the build worker sent them) in document order, with their ranges in the text. A
// range and a CodeMirror diagnostic are made only for a problem read (the markers of the first
// thousand, the Problems panel's rows in view, F8's search): 100,000 of them made and sorted on
// every build of a text with that many problems held the page for tens of milliseconds.
import type { Diagnostic as EditorDiagnostic } from '@codemirror/lint';
import { NO_DIAGNOSTICS, utf16Offsets, type DiagnosticList } from '../core';

/** The problems of one text, in document order (by start, then end; the core's order among equal ranges). */
export class ProblemList {
  private constructor(
    private readonly diagnostics: DiagnosticList,
    /** A UTF-8 byte offset into the text as a UTF-16 position. */
    private readonly toUtf16: (byteOffset: number) => number,
    /** The diagnostics in document order, when the core's is not (it is for the core's lists). */
    private readonly order: Uint32Array | undefined,
  ) {}

  /**
   * The problems of `diagnostics` (UTF-8 byte spans) in `text`: ranges in UTF-16 units, clamped to
   * the text, each converted when read (the order of the spans is the order of their ranges).
   */
  static of(text: string, diagnostics: DiagnosticList): ProblemList {
    const n = diagnostics.length;
    const before = (a: number, b: number) => diagnostics.fromByte(a) - diagnostics.fromByte(b) || diagnostics.toByte(a) - diagnostics.toByte(b);
    let ordered = true;
    for (let i = 1; i < n && ordered; i++) ordered = before(i - 1, i) <= 0;
    const order = ordered ? undefined : new Uint32Array(n).map((_, i) => i).sort((a, b) => before(a, b) || a - b);
    return new ProblemList(diagnostics, utf16Offsets(text), order);
  }

  static readonly NONE = new ProblemList(NO_DIAGNOSTICS, () => 0, undefined);

  get length(): number {
    return this.diagnostics.length;
  }

  /** The errors among them. */
  get errors(): number {
    return this.diagnostics.count('error');
  }

  /** Where problem `i` is, in the text it was made for. */
  range(i: number): { from: number; to: number } {
    const r = this.order ? this.order[i] : i;
    const from = this.toUtf16(this.diagnostics.fromByte(r));
    return { from, to: Math.max(from, this.toUtf16(this.diagnostics.toByte(r))) };
  }

  /** Problem `i` as CodeMirror's (a new object; the code is its source, shown after the message). */
  at(i: number): EditorDiagnostic {
    const d = this.diagnostics.at(this.order ? this.order[i] : i);
    return { ...this.range(i), severity: d?.severity ?? 'error', message: d?.message ?? '', source: d?.code };
  }
}
