// The text's problems as the editor reads them: the core's diagnostics (a DiagnosticList, their
// columns as the build worker sent them) with their ranges in the text, in document order. A
// CodeMirror diagnostic is made only for a problem read (the markers of the first thousand, the
// Problems panel's rows in view): 100,000 of them made and sorted on every build of a text with
// that many problems held the page for tens of milliseconds.
import type { Diagnostic as EditorDiagnostic } from '@codemirror/lint';
import { NO_DIAGNOSTICS, utf16Offsets, type DiagnosticList } from '../core';

/** The problems of one text, in document order (by start, then end; the core's order among equal ranges). */
export class ProblemList {
  private constructor(
    private readonly diagnostics: DiagnosticList,
    /** Per diagnostic (in the core's order): from, to, UTF-16 positions in the text. */
    private readonly ranges: Uint32Array,
    /** The diagnostics in document order, when the core's is not (it is for the core's lists). */
    private readonly order: Uint32Array | undefined,
  ) {}

  /** The problems of `diagnostics` (UTF-8 byte spans) in `text`: ranges in UTF-16 units, clamped to the text. */
  static of(text: string, diagnostics: DiagnosticList): ProblemList {
    const toUtf16 = utf16Offsets(text);
    const n = diagnostics.length;
    const ranges = new Uint32Array(2 * n);
    let ordered = true;
    for (let i = 0; i < n; i++) {
      const from = toUtf16(diagnostics.fromByte(i));
      const to = Math.max(from, toUtf16(diagnostics.toByte(i)));
      ranges[2 * i] = from;
      ranges[2 * i + 1] = to;
      if (i > 0 && (from < ranges[2 * i - 2] || (from === ranges[2 * i - 2] && to < ranges[2 * i - 1]))) ordered = false;
    }
    const order = ordered ? undefined : new Uint32Array(n).map((_, i) => i).sort((a, b) => ranges[2 * a] - ranges[2 * b] || ranges[2 * a + 1] - ranges[2 * b + 1] || a - b);
    return new ProblemList(diagnostics, ranges, order);
  }

  static readonly NONE = new ProblemList(NO_DIAGNOSTICS, new Uint32Array(0), undefined);

  get length(): number {
    return this.diagnostics.length;
  }

  private errorCount = -1;

  /** The errors among them. */
  get errors(): number {
    if (this.errorCount < 0) this.errorCount = this.diagnostics.count('error');
    return this.errorCount;
  }

  /** Where problem `i` is, in the text it was made for. */
  range(i: number): { from: number; to: number } {
    const r = this.order ? this.order[i] : i;
    return { from: this.ranges[2 * r], to: this.ranges[2 * r + 1] };
  }

  /** Problem `i` as CodeMirror's (a new object; the code is its source, shown after the message). */
  at(i: number): EditorDiagnostic {
    const d = this.diagnostics.at(this.order ? this.order[i] : i);
    return { ...this.range(i), severity: d?.severity ?? 'error', message: d?.message ?? '', source: d?.code };
  }
}
