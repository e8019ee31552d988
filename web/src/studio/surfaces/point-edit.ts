// A control point moved through the grammar text: every step of a drag rewrites its `x y z`
// (and its copies' where patches meet) at once, so that the plant follows live through the text's
// ordinary rebuild, and the steps of one drag make one undo step (Ctrl+Z after a drag restores the
// text before it). A nudge or a number typed is an edit of one step. The curve editor moves a
// curve function's points the same way, its x and y written at two spans ({@link PointEdit.write}).
import type { Point3 } from '../../core';
import type { HistoryStep } from '../../editor/grammar-text';
import type { TextChange } from '../../editor/growth-directives';
import { pointText, replaceSpans, type PointSpan } from './point-text';

/** What a point edit needs of the grammar editor. */
export interface PointTextEditor {
  text(): string;
  replaceRanges(changes: readonly TextChange[], options?: { history?: HistoryStep }): void;
}

/** One control point's edit (a drag, a nudge or a number typed): {@link move} as often as it goes, then {@link end}. */
export class PointEdit {
  private spans: PointSpan[];
  /** Each span's text when the edit began. */
  private readonly before: string[];
  /** What the edit last wrote at each span (undefined: nothing yet). */
  private written: readonly string[] | undefined;
  /** The text changed under the edit (the user typed): it writes nothing more. */
  private stale = false;
  /** The edit's undo step: its steps carry this time, which joins them. */
  private readonly drag = Date.now();

  constructor(
    private readonly editor: PointTextEditor,
    spans: readonly PointSpan[],
  ) {
    this.spans = spans.map((s) => ({ ...s }));
    const text = editor.text();
    this.before = this.spans.map((s) => text.slice(s.from, s.to));
  }

  /** Whether the edit can still write (false once the text changed under it). */
  get live(): boolean {
    return !this.stale;
  }

  /** Writes `point` at every span; false when the text changed under the edit (it has stopped). */
  move(point: Point3): boolean {
    const insert = pointText(point);
    return this.write(this.spans.map(() => insert));
  }

  /** Writes `inserts[k]` at span k; false when the text changed under the edit (it has stopped). */
  write(inserts: readonly string[]): boolean {
    if (!this.holds()) return false;
    const same = (texts: readonly string[]) => texts.every((t, k) => t === inserts[k]);
    if (same(this.written ?? this.before)) return true;
    const { changes, spans } = replaceSpans(this.spans, inserts);
    const step = this.written === undefined ? 'first' : 'next';
    this.editor.replaceRanges(changes, { history: { drag: this.drag, step } });
    this.spans = spans;
    this.written = [...inserts];
    return true;
  }

  /** Ends the edit: its steps are one undo step, closed to what comes after. */
  end(): void {
    if (this.written === undefined) return;
    this.written = undefined;
    this.editor.replaceRanges([], { history: { drag: this.drag, step: 'last' } });
  }

  /** The spans still hold what the edit last wrote (or what they held when it began). */
  private holds(): boolean {
    if (this.stale) return false;
    const text = this.editor.text();
    const expected = this.written ?? this.before;
    this.stale = this.spans.some((s, k) => text.slice(s.from, s.to) !== expected[k]);
    return !this.stale;
  }
}
