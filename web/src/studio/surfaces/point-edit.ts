// A control point moved through the grammar text: every step of a drag rewrites its `x y z`
// (and its copies' where patches meet) at once, so that the plant follows live through the text's
// ordinary rebuild, and the steps of one drag make one undo step (Ctrl+Z after a drag restores the
// text before it). A nudge or a number typed is an edit of one step.
import type { Point3 } from '../../core';
import type { HistoryStep } from '../../editor/grammar-text';
import type { TextChange } from '../../editor/growth-directives';
import { movePoints, pointText, type PointSpan } from './point-text';

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
  /** What the edit last wrote at every span (undefined: nothing yet). */
  private written: string | undefined;
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
    if (!this.holds()) return false;
    const insert = pointText(point);
    if (insert === this.written || (this.written === undefined && this.before.every((b) => b === insert))) return true;
    const { changes, spans } = movePoints(this.spans, point);
    const step = this.written === undefined ? 'first' : 'next';
    this.editor.replaceRanges(changes, { history: { drag: this.drag, step } });
    this.spans = spans;
    this.written = insert;
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
    this.stale = this.spans.some((s, k) => text.slice(s.from, s.to) !== (this.written ?? this.before[k]));
    return !this.stale;
  }
}
