// A control point moved through the grammar text: every step of a drag rewrites its `x y z`
// (and its copies' where patches meet) outside the undo history, so that the plant follows live
// through the text's ordinary rebuild; the drag's end makes it one undo step, from the text before
// the drag to the text after it (Ctrl+Z after a drag restores the text before it).
import type { Point3 } from '../../core';
import type { TextChange } from '../../editor/growth-directives';
import { movePoints, pointText, replaceSpans, type PointSpan } from './point-text';

/** What a point edit needs of the grammar editor. */
export interface PointTextEditor {
  text(): string;
  replaceRanges(changes: readonly TextChange[], options?: { history?: boolean }): void;
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

  /** Writes `point` at every span, outside the undo history; false when the text changed under the edit (it has stopped). */
  move(point: Point3): boolean {
    if (!this.holds()) return false;
    const insert = pointText(point);
    if (insert === this.written || (this.written === undefined && this.before.every((b) => b === insert))) return true;
    const { changes, spans } = movePoints(this.spans, point);
    this.editor.replaceRanges(changes, { history: false });
    this.spans = spans;
    this.written = insert;
    return true;
  }

  /**
   * Ends the edit: the text before it, then the text now, written again as one undo step (nothing
   * when the point is back where it was, or the text changed under the edit).
   */
  end(): void {
    if (this.written === undefined || !this.holds()) return;
    const final = this.written;
    this.written = undefined;
    const restored = replaceSpans(this.spans, this.before);
    this.editor.replaceRanges(restored.changes, { history: false });
    this.spans = restored.spans;
    if (this.before.every((b) => b === final)) return;
    const done = replaceSpans(this.spans, this.spans.map(() => final));
    this.editor.replaceRanges(done.changes, { history: true });
    this.spans = done.spans;
  }

  /** The spans still hold what the edit last wrote (or what they held when it began). */
  private holds(): boolean {
    if (this.stale) return false;
    const text = this.editor.text();
    this.stale = this.spans.some((s, k) => text.slice(s.from, s.to) !== (this.written ?? this.before[k]));
    return !this.stale;
  }
}
