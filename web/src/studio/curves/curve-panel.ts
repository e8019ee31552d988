// The curve editor (issue 48, like vlab's funcedit and L-Py's curve panels): a `#curve` or
// `#table` function's points dragged in a small plot, the grammar's line following (one undo step
// per drag, per nudge, per point added or removed, per number typed), the plant following the text
// through its ordinary rebuild. The editor reads the curve from the text again after every change,
// so it follows what the user types, and says so when the line cannot be edited as points.
// The rules it keeps: a point never passes its neighbours' x, the first and the last keep their x
// (they bound the function's domain, as in funcedit), and a curve keeps its least number of
// points (4 for a `#curve`, 2 for a `#table`).
import { curveDeclarations, type CurveDeclaration, type CurveFunctionKind } from '../../editor/curve-lines';
import { TextPanel } from '../page/text-panel';
import { PointEdit, type PointTextEditor } from '../surfaces/point-edit';
import { makeCurveControls } from './curve-controls';
import { curveOutline, curveValue, LEAST_POINTS, type Point2 } from './curve-function';
import { frameOf } from './curve-plot';
import { curveSource, type CurveSource } from './curve-source';
import { decimalsFor, fixedDecimals, numberText, type WrittenPoint } from './curve-text';

/** What the editor needs of the page: the grammar text. */
export interface CurveEditorHost {
  editor: PointTextEditor;
}

/** Distance (CSS pixels) within which a press takes a point: a finger's is larger. */
const REACH = { mouse: 12, touch: 28 } as const;

/** A drag under way: the pointer, the point and its edit, where it was grabbed. */
interface Drag {
  pointer: number;
  k: number;
  edit: PointEdit;
  grab: Point2;
  /** Where the pointer asks the point to be, written at the next frame. */
  pending: Point2 | null;
}

/** The declaration of `name` in `text` (the first, if the text declares it twice), or null. */
export function declarationOf(text: string, name: string): CurveDeclaration | null {
  return curveDeclarations(text).find((d) => d.name === name) ?? null;
}

/** Why the declaration cannot be edited as points, or null. */
export function whyNotEditable(d: CurveDeclaration | null, name: string, text: string): string | null {
  if (!d) return `The grammar declares no curve ${name}.`;
  if (!d.problem) return null;
  const line = text.slice(0, d.lineFrom).split('\n').length;
  return `${d.directive} ${name} (line ${line}) cannot be edited as points: ${d.problem}.`;
}

export class CurvePanel {
  private readonly c = makeCurveControls();
  private name = '';
  /** The points in the text and how an edit of them is written; null while the line cannot be edited. */
  private source: CurveSource | null = null;
  private points: WrittenPoint[] = [];
  private selected: number | null = null;
  private under: Point2 | null = null;
  private drag: Drag | undefined;
  private readonly panel: TextPanel;

  constructor(private readonly host: CurveEditorHost) {
    const c = this.c;
    const plot = c.plot.element;
    this.panel = new TextPanel(c.dialog, c.close, () => this.refresh(false));
    c.coordinates.forEach((input, axis) => input.addEventListener('change', () => this.typed(axis, Number(input.value))));
    c.add.addEventListener('click', () => this.addInWidestGap());
    c.remove.addEventListener('click', () => this.removeChosen());
    c.fit.addEventListener('click', () => this.fit());
    plot.addEventListener('pointerdown', (event) => this.pointerDown(event));
    plot.addEventListener('pointermove', (event) => this.pointerMove(event));
    plot.addEventListener('pointerup', (event) => this.pointerUp(event));
    plot.addEventListener('pointercancel', (event) => this.pointerUp(event));
    plot.addEventListener('pointerleave', () => this.showUnder(null));
    plot.addEventListener('dblclick', (event) => this.doubleClick(event));
    plot.addEventListener('keydown', (event) => this.key(event));
    new ResizeObserver(() => this.draw()).observe(plot);
  }

  /** Shows curve `name` of the grammar; why not (the panel stays as it was) when its line cannot be edited as points. */
  open(name: string): string | null {
    const text = this.host.editor.text();
    const declaration = declarationOf(text, name);
    const why = whyNotEditable(declaration, name, text);
    if (why) return why;
    if (name !== this.name) this.selected = null;
    this.name = name;
    this.panel.show();
    this.refresh(true);
    this.c.plot.element.focus();
    return null;
  }

  /** Whether the panel is open. */
  get isOpen(): boolean {
    return this.panel.isOpen;
  }

  /** The grammar text changed (typed, or written by a drag): the panel follows it at the next frame. */
  textChanged(): void {
    this.panel.textChanged();
  }

  /** Reads the curve from the text now and shows it (or why it cannot be edited); `refit`: frame it anew. */
  private refresh(refit: boolean): void {
    const text = this.host.editor.text();
    const declaration = declarationOf(text, this.name);
    const why = whyNotEditable(declaration, this.name, text);
    this.source = why || !declaration ? null : curveSource(text, declaration);
    this.points = this.source?.points ?? [];
    if (this.selected !== null && this.selected >= this.points.length) this.selected = null;
    const kind = this.kind();
    this.c.title.textContent = `${declaration?.directive ?? 'Curve'} ${this.name}`;
    if (this.points.length > 0 && !this.drag && (refit || this.outsideFrame())) this.fit();
    this.showStatus(why);
    this.showPoint();
    this.c.add.disabled = this.points.length < 2;
    this.c.plot.element.dataset.kind = kind;
    this.draw();
  }

  private draw(): void {
    this.c.plot.draw(this.kind(), this.values(), this.selected, this.under);
  }

  /** How the points draw and read. */
  private kind(): CurveFunctionKind {
    return this.source?.kind ?? 'curve';
  }

  private values(): Point2[] {
    return this.points.map((p) => p.value);
  }

  /** Frames every point and the line between them. */
  private fit(): void {
    const values = this.values();
    if (values.length === 0) return;
    this.c.plot.frame = frameOf(values, curveOutline(this.kind(), values));
    this.draw();
  }

  /**
   * Whether the frame no longer suits the points: one stands outside it or on its edge (a drag
   * ended there: room to go further), or they fill less than half of it (typed smaller).
   */
  private outsideFrame(): boolean {
    const { x, y } = this.c.plot.frame;
    const [dx, dy] = [(x[1] - x[0]) * 0.01, (y[1] - y[0]) * 0.01];
    const values = this.values();
    if (values.some(([px, py]) => px < x[0] + dx || px > x[1] - dx || py < y[0] + dy || py > y[1] - dy)) return true;
    const ideal = frameOf(values, curveOutline(this.kind(), values));
    return ideal.x[1] - ideal.x[0] < 0.5 * (x[1] - x[0]) || ideal.y[1] - ideal.y[0] < 0.5 * (y[1] - y[0]);
  }

  /** Says what the curve is, or why it cannot be edited, or which rule of the language it breaks. */
  private showStatus(why: string | null): void {
    const status = this.c.status;
    const source = this.source;
    const problem = why ?? (source ? ruleBroken(source, this.values()) : null);
    status.dataset.state = problem ? 'error' : 'ok';
    if (problem || !source) {
      status.textContent = problem ?? '';
      return;
    }
    const [first, last] = [this.points[0].value[0], this.points[this.points.length - 1].value[0]];
    status.textContent = `${source.description}, x from ${first} to ${last}`;
  }

  /** The chosen point's x and y in the fields, and what may be done with it. */
  private showPoint(): void {
    const c = this.c;
    const point = this.selected === null ? undefined : this.points[this.selected];
    c.coordinates.forEach((input, axis) => {
      const end = axis === 0 && this.isEnd(this.selected);
      input.disabled = !point || end;
      input.title = end ? 'The first and the last point keep their x: they bound the function' : '';
      input.step = String(this.step(axis));
      if (document.activeElement !== input || !point) input.value = point ? (axis === 0 ? point.x.text : point.y.text) : '';
    });
    const why = this.whyNotRemovable(this.selected);
    c.remove.disabled = why !== null;
    c.remove.title = why ?? 'Remove the chosen point (Delete)';
  }

  private isEnd(k: number | null): boolean {
    return k === 0 || k === this.points.length - 1;
  }

  private whyNotRemovable(k: number | null): string | null {
    const source = this.source;
    if (!source || k === null) return 'Choose a point to remove';
    if (this.isEnd(k)) return 'The first and the last point bound the function: they stay';
    const least = LEAST_POINTS[source.kind];
    if (this.points.length <= least) return `${source.kind === 'curve' ? 'A curve' : 'A table'} needs at least ${least} points`;
    return null;
  }

  /** The decimals a number on `axis` (0: x, 1: y) is written with: the line's own fixed count, else a thousandth of the frame. */
  private decimals(axis: number): { decimals: number; fixed: boolean } {
    const fixed = this.source ? fixedDecimals(this.source.declaration) : null;
    if (fixed !== null) return { decimals: fixed, fixed: true };
    const [low, high] = axis === 0 ? this.c.plot.frame.x : this.c.plot.frame.y;
    return { decimals: decimalsFor(high - low), fixed: false };
  }

  /** A nudge on `axis`: ten times the written resolution (a hundredth of the frame). */
  private step(axis: number): number {
    const { decimals, fixed } = this.decimals(axis);
    return 10 ** -(fixed ? decimals : decimals - 1);
  }

  /** The texts of point `k` moved to `to`: an axis it did not move along keeps its text as written. */
  private texts(k: number, to: Point2): [string, string] {
    const point = this.points[k];
    const written = [point.x, point.y];
    return [0, 1].map((axis) => {
      const { decimals, fixed } = this.decimals(axis);
      const text = numberText(to[axis], decimals, fixed);
      return Number(text) === written[axis].value ? written[axis].text : text;
    }) as [string, string];
  }

  /** Where point `k` may go when asked to `to`: between its neighbours' x, an end at its own x. */
  private allowed(k: number, to: Point2): Point2 {
    const range = this.xRange(k);
    return [range ? Math.min(range[1], Math.max(range[0], to[0])) : this.points[k].value[0], to[1]];
  }

  private xRange(k: number): [number, number] | null {
    if (this.isEnd(k)) return null;
    const [low, high] = [this.points[k - 1].value[0], this.points[k + 1].value[0]];
    return low <= high ? [low, high] : [-Infinity, Infinity];
  }

  /** An edit of point `k`: its x and y, or its y alone (an end). */
  private editOf(k: number): PointEdit {
    return new PointEdit(this.host.editor, this.source?.spansOf(k) ?? []);
  }

  /** Writes point `k` at `to` through `edit`; false when the text changed under the edit. */
  private write(edit: PointEdit, k: number, to: Point2): boolean {
    const texts = this.texts(k, this.allowed(k, to));
    return this.source ? edit.write(this.source.insertsOf(k, texts)) : false;
  }

  /** Moves point `k` to `to` as one undo step (a nudge, a number typed). */
  private place(k: number, to: Point2): void {
    const edit = this.editOf(k);
    this.write(edit, k, to);
    edit.end();
    this.refresh(false);
  }

  private typed(axis: number, value: number): void {
    const k = this.selected;
    if (k === null || !this.source || !Number.isFinite(value)) return this.showPoint();
    const to: [number, number] = [...this.points[k].value];
    to[axis] = value;
    this.place(k, to);
  }

  private choose(k: number | null): void {
    this.selected = k;
    this.showPoint();
    this.draw();
  }

  /** Adds a point at `at` (between the ends: never before the first nor after the last) as one undo step, and chooses it. */
  private addAt(at: Point2): void {
    const source = this.source;
    const values = this.values();
    if (!source || values.length < 2) return;
    let k = values.findIndex((p) => p[0] > at[0]);
    k = Math.min(values.length - 1, Math.max(1, k < 0 ? values.length - 1 : k));
    const x = Math.min(values[k][0], Math.max(values[k - 1][0], at[0]));
    const texts = [0, 1].map((axis) => numberText([x, at[1]][axis], this.decimals(axis).decimals, this.decimals(axis).fixed));
    this.host.editor.replaceRanges(source.addChanges(this.host.editor.text(), k, [texts[0], texts[1]]), { history: true });
    this.selected = k;
    this.refresh(false);
  }

  /** Adds a point in the middle of the widest gap between two points' x, on the function's line there. */
  private addInWidestGap(): void {
    const values = this.values();
    const kind = this.kind();
    if (!this.source || values.length < 2) return;
    let k = 1;
    for (let j = 2; j < values.length; j++) if (values[j][0] - values[j - 1][0] > values[k][0] - values[k - 1][0]) k = j;
    const x = (values[k][0] + values[k - 1][0]) / 2;
    const y = values.length >= LEAST_POINTS[kind] ? curveValue(kind, values, x) : (values[k][1] + values[k - 1][1]) / 2;
    this.addAt([x, y]);
  }

  private removeChosen(): void {
    const k = this.selected;
    if (!this.source || k === null || this.whyNotRemovable(k)) return;
    this.host.editor.replaceRanges(this.source.removeChanges(k), { history: true });
    this.selected = Math.min(k, this.points.length - 2);
    this.refresh(false);
  }

  /** The value under the pointer: the function's at the pointer's x (or the dragged point). */
  private showUnder(at: Point2 | null): void {
    const values = this.values();
    const kind = this.kind();
    const ready = this.source && values.length >= LEAST_POINTS[kind];
    this.under = at && ready ? [at[0], curveValue(kind, values, at[0])] : null;
    const shown = this.under;
    this.c.under.textContent = shown ? `${this.name}(${short(shown[0])}) = ${short(shown[1])}` : '';
    this.draw();
  }

  /** Arrow keys move the chosen point (Shift ten times as far, Alt a tenth); [ and ] choose another, Home and End the first and the last; Insert adds, Delete removes. */
  private key(event: KeyboardEvent): void {
    const count = this.points.length;
    if (!this.source || count === 0 || event.ctrlKey || event.metaKey) return;
    const handled = this.chooseOrChange(event.key, count) || this.nudge(event);
    if (handled) event.preventDefault();
  }

  private chooseOrChange(key: string, count: number): boolean {
    if (key === 'Home' || key === 'End') this.choose(key === 'Home' ? 0 : count - 1);
    else if (key === '[' || key === ']') {
      const k = this.selected ?? (key === ']' ? -1 : 0);
      this.choose((k + (key === ']' ? 1 : count - 1)) % count);
    } else if (key === 'Insert' || key === '+') this.addInWidestGap();
    else if (key === 'Delete' || key === 'Backspace') this.removeChosen();
    else return false;
    return true;
  }

  private nudge(event: KeyboardEvent): boolean {
    const moves: Record<string, [number, number]> = { ArrowLeft: [0, -1], ArrowRight: [0, 1], ArrowDown: [1, -1], ArrowUp: [1, 1] };
    const move = moves[event.key];
    const k = this.selected;
    if (!move || k === null) return false;
    const to: [number, number] = [...this.points[k].value];
    to[move[0]] += move[1] * this.step(move[0]) * (event.shiftKey ? 10 : event.altKey ? 0.1 : 1);
    this.place(k, to);
    return true;
  }

  private pointerDown(event: PointerEvent): void {
    if (event.button !== 0 || this.drag || !this.source) return;
    const plot = this.c.plot;
    const k = plot.pointAt(this.values(), event.clientX, event.clientY, event.pointerType === 'touch' ? REACH.touch : REACH.mouse);
    plot.element.focus();
    if (k === null) return;
    event.preventDefault();
    const at = plot.valueAt(event.clientX, event.clientY, false);
    const p = this.points[k].value;
    plot.element.setPointerCapture(event.pointerId);
    this.drag = { pointer: event.pointerId, k, edit: this.editOf(k), grab: [p[0] - at[0], p[1] - at[1]], pending: null };
    this.choose(k);
  }

  private pointerMove(event: PointerEvent): void {
    const drag = this.drag;
    const at = this.c.plot.valueAt(event.clientX, event.clientY, !drag);
    if (!drag) return this.showUnder(at);
    if (event.pointerId !== drag.pointer) return;
    const first = drag.pending === null;
    drag.pending = [at[0] + drag.grab[0], at[1] + drag.grab[1]];
    // One write a frame: the text, and so the plant's rebuild, at the pace of the screen.
    if (first) requestAnimationFrame(() => this.flush(drag));
  }

  /** Writes where the drag asked the point to be since the last frame. */
  private flush(drag: Drag): void {
    if (!drag.pending || this.drag !== drag) return;
    const to = this.allowed(drag.k, drag.pending);
    drag.pending = null;
    if (!this.write(drag.edit, drag.k, to)) return this.endDrag();
    // The point follows at once; the text's change redraws the rest at the next frame.
    const [x, y] = this.texts(drag.k, to);
    this.points[drag.k] = { ...this.points[drag.k], value: [Number(x), Number(y)] };
    this.under = null;
    this.c.under.textContent = `point ${drag.k + 1}: x ${x}, y ${y}`;
    this.draw();
  }

  private pointerUp(event: PointerEvent): void {
    const drag = this.drag;
    if (drag?.pointer !== event.pointerId) return;
    this.flush(drag);
    drag.edit.end();
    this.endDrag();
  }

  private endDrag(): void {
    const plot = this.c.plot.element;
    if (this.drag && plot.hasPointerCapture(this.drag.pointer)) plot.releasePointerCapture(this.drag.pointer);
    this.drag = undefined;
    this.refresh(false);
  }

  private doubleClick(event: MouseEvent): void {
    if (!this.source) return;
    const plot = this.c.plot;
    if (plot.pointAt(this.values(), event.clientX, event.clientY, REACH.mouse) !== null) return;
    this.addAt(plot.valueAt(event.clientX, event.clientY));
  }
}

/** The rule of the language the points break (docs/LANGUAGE.md "Curve functions"), or null. */
export function ruleBroken(source: Pick<CurveSource, 'kind' | 'declaration'>, values: readonly Point2[]): string | null {
  const least = LEAST_POINTS[source.kind];
  const directive = source.declaration.directive;
  if (values.length < least) return `${directive} ${source.declaration.name} needs at least ${least} points, not ${values.length} (E0210): add one.`;
  const k = values.findIndex((p, j) => j > 0 && p[0] < values[j - 1][0]);
  if (k < 0) return null;
  const must = source.kind === 'table' ? 'must not decrease (E0210)' : 'should grow along the curve';
  return `The x of point ${k + 1} is less than the one before: the points' x ${must}.`;
}

/** A value in the readout: 4 significant digits. */
function short(value: number): string {
  return String(Number(value.toPrecision(4)));
}
