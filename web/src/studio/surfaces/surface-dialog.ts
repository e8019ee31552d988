// The surface editor (issue 46, like vlab's Bézier editor): a declared surface's control points
// moved in a small 3D view, the grammar's `#patch` text following (one undo step per drag, per
// nudge, per number typed), the plant following the text through its ordinary rebuild. The core
// answers what the surface is (`surfacePreview`: its mesh as the plant draws it, its points and
// where each is written); the dialog asks again after every change of the text, so it follows
// what the user types, and says so when the surface has errors or is no longer declared.
import { Matrix4, Vector3 } from 'three';
import { type Point3, type SurfaceAnswer, type SurfacePreview, type SurfacePreviewer } from '../../core';
import { declaredSurfaces, surfaceLetterOf } from '../../editor/surface-lines';
import { PointEdit, type PointTextEditor } from './point-edit';
import { coordinateText, copiesOf } from './point-text';
import { TextPanel } from '../page/text-panel';
import { makeSurfaceControls } from './surface-controls';
import { SurfaceScene } from './surface-scene';

/** What the editor needs of the page: the grammar text. */
export interface SurfaceEditorHost {
  editor: PointTextEditor;
}

/** Distance (CSS pixels) within which a press takes a point: a finger's is larger. */
const REACH = { mouse: 14, touch: 30 } as const;

/** A drag under way: the pointer, the point's edit, and where the point was grabbed. */
interface Drag {
  pointer: number;
  edit: PointEdit;
  copies: number[];
  /** The point's place minus the pointer's first target (the drag keeps the grab). */
  grab: Vector3;
  through: Point3;
}

export class SurfaceDialog {
  private readonly c = makeSurfaceControls();
  private readonly scene: SurfaceScene;
  private letter = '';
  private answer: SurfaceAnswer | null = null;
  private selected: number | null = null;
  private drag: Drag | undefined;
  private toTurtle = new Matrix4();
  private fromTurtle = new Matrix4();
  private readonly panel: TextPanel;

  constructor(
    private readonly host: SurfaceEditorHost,
    private readonly preview: SurfacePreviewer,
  ) {
    const c = this.c;
    this.scene = new SurfaceScene(c.canvas);
    this.panel = new TextPanel(c.dialog, c.close, () => this.refresh());
    c.letter.addEventListener('change', () => this.open(c.letter.value));
    c.point.addEventListener('change', () => this.choose(c.point.value === '' ? null : Number(c.point.value)));
    c.coordinates.forEach((input, axis) => input.addEventListener('change', () => this.typed(axis, Number(input.value))));
    c.frame.addEventListener('click', () => this.scene.frame());
    c.writeOut.addEventListener('click', () => this.writeOut());
    c.canvas.addEventListener('pointerdown', (event) => this.pointerDown(event), { capture: true });
    c.canvas.addEventListener('pointermove', (event) => this.pointerMove(event));
    c.canvas.addEventListener('pointerup', (event) => this.pointerUp(event));
    c.canvas.addEventListener('pointercancel', (event) => this.pointerUp(event));
    c.canvas.addEventListener('keydown', (event) => this.key(event));
  }

  /** Shows surface `letter` of the grammar (the dialog opens, or turns to it). */
  open(letter: string): void {
    const c = this.c;
    if (letter !== this.letter) this.selected = null;
    this.letter = letter;
    this.panel.show();
    this.refresh();
    c.canvas.focus();
  }

  /** Whether the dialog is open. */
  get isOpen(): boolean {
    return this.panel.isOpen;
  }

  /** The grammar text changed (typed, or written by a drag): the dialog follows it at the next frame. */
  textChanged(): void {
    this.panel.textChanged();
  }

  /** Net point `k` on the page (CSS pixels), or null (for tests). */
  pointOnPage(k: number): { x: number; y: number } | null {
    const p = this.answer?.surface?.net[k];
    return p ? this.scene.pageOf(p) : null;
  }

  /** Asks the core for the surface in the text now, and shows it (or why there is none). */
  private refresh(): void {
    const text = this.host.editor.text();
    // A drag moves points only: the colours stay those asked before it (asking derives the plant).
    const before = this.answer?.surface;
    this.answer = this.preview(text, this.letter, !this.drag);
    const surface = this.answer.surface;
    if (surface && this.drag && before?.letter === surface.letter) surface.colors = before.colors;
    const letters = declaredSurfaces(text).map((s) => s.letter);
    this.fillLetters(letters);
    this.c.title.textContent = `Surface ~${this.letter}`;
    this.toTurtle = surface ? new Matrix4().fromArray(surface.toTurtle) : new Matrix4();
    this.fromTurtle = this.toTurtle.clone().invert();
    if (surface && this.selected !== null && this.selected >= surface.net.length) this.selected = null;
    // With errors, the last surface stays in view (not editable) until the text resolves again.
    if (surface && this.drag) this.scene.showMesh(surface);
    else if (surface) this.scene.show(surface, this.selected);
    this.showStatus(text, letters.includes(this.letter));
    this.showPoint();
  }

  /** Says what the core says of the surface: its errors first, else what it is. */
  private showStatus(text: string, declared: boolean): void {
    const { status, library } = this.c;
    const surface = this.answer?.surface ?? null;
    const problems = this.problems(text);
    const error = problems.find((d) => d.severity === 'error');
    status.dataset.state = error || !surface ? 'error' : 'ok';
    if (!declared) status.textContent = `The grammar no longer declares ~${this.letter}.`;
    else if (error) status.textContent = `Line ${error.line}: ${error.message} (${error.code})`;
    else if (!surface) status.textContent = `~${this.letter} has errors: see the grammar's problems.`;
    else {
      const patches = surface.net.length / 16;
      const kind = surface.organ ? `the library's ${surface.organ}` : `${patches} ${patches === 1 ? 'patch' : 'patches'}`;
      const warning = problems[0] ? ` · line ${problems[0].line}: ${problems[0].message}` : '';
      status.textContent = `~${this.letter}: ${kind}, ${surface.precision[0]} × ${surface.precision[1]} quads a patch${warning}`;
    }
    library.hidden = !surface?.organ;
  }

  /** The diagnostics on the lines that declare the surface. */
  private problems(text: string): SurfaceAnswer['diagnostics'] {
    const lines = new Set<number>();
    text.split('\n').forEach((line, k) => {
      if (surfaceLetterOf(line) === this.letter) lines.add(k + 1);
    });
    return (this.answer?.diagnostics ?? []).filter((d) => lines.has(d.line));
  }

  private fillLetters(letters: string[]): void {
    const select = this.c.letter;
    const all = letters.includes(this.letter) || !this.letter ? letters : [...letters, this.letter];
    const key = all.join('');
    if (select.dataset.letters !== key) {
      select.dataset.letters = key;
      select.replaceChildren(...all.map((l) => Object.assign(document.createElement('option'), { value: l, textContent: `~${l}` })));
    }
    select.value = this.letter;
    select.hidden = all.length < 2;
  }

  /** The point list, the chosen point's written x y z, and whether they can be edited. */
  private showPoint(): void {
    const c = this.c;
    const surface = this.editable();
    const count = surface?.net.length ?? 0;
    if (c.point.options.length !== count + 1) {
      const none = Object.assign(document.createElement('option'), { value: '', textContent: count ? 'none: drag one, or choose' : 'none' });
      const options = Array.from({ length: count }, (_, k) => {
        const patch = Math.floor(k / 16);
        const n = k % 16;
        const label = `${count > 16 ? `patch ${patch + 1}, ` : ''}row ${Math.floor(n / 4) + 1}, column ${(n % 4) + 1}`;
        return Object.assign(document.createElement('option'), { value: String(k), textContent: label });
      });
      c.point.replaceChildren(none, ...options);
    }
    c.point.value = this.selected === null ? '' : String(this.selected);
    c.point.disabled = count === 0;
    const written = this.selected === null ? undefined : surface?.written[this.selected];
    c.coordinates.forEach((input, axis) => {
      input.disabled = !written;
      input.step = String(this.step());
      if (document.activeElement !== input || !written) input.value = written ? coordinateText(written.value[axis]) : '';
    });
    c.axis.disabled = count === 0;
  }

  /** The surface if its points are written in the text (not a library shape, nor one with errors). */
  private editable(): SurfacePreview | null {
    const surface = this.answer?.surface;
    return surface && !surface.organ && surface.written.length === surface.net.length ? surface : null;
  }

  private choose(k: number | null): void {
    this.selected = k;
    this.scene.select(k);
    this.showPoint();
  }

  /** The edit of the chosen point's copies (every written copy of it where patches meet). */
  private editOf(k: number): { edit: PointEdit; copies: number[] } | null {
    const surface = this.editable();
    if (!surface) return null;
    const copies = copiesOf(surface.written, k);
    return { edit: new PointEdit(this.host.editor, copies.map((j) => surface.written[j])), copies };
  }

  /** Moves the chosen point to `written` (in the text's coordinates) as one undo step. */
  private place(written: Point3): void {
    if (this.selected === null) return;
    const found = this.editOf(this.selected);
    if (!found) return;
    found.edit.move(written);
    found.edit.end();
  }

  /** A coordinate typed in a field. */
  private typed(axis: number, value: number): void {
    const w = this.selected === null ? undefined : this.editable()?.written[this.selected];
    if (!w || !Number.isFinite(value)) return this.showPoint();
    const next: Point3 = [...w.value];
    next[axis] = value;
    this.place(next);
  }

  /** A nudge of a tenth of a percent… of the surface's size, rounded to a power of ten. */
  private step(): number {
    const surface = this.editable();
    const extent = surface ? Math.max(1e-6, ...surface.written.flatMap((w) => w.value.map(Math.abs))) : 1;
    return 10 ** Math.floor(Math.log10(extent / 20));
  }

  /** Arrow keys nudge the chosen point (x, y; Page Up/Down: z; Shift: ten times); [ and ] choose another. */
  private key(event: KeyboardEvent): void {
    const count = this.editable()?.net.length ?? 0;
    if ((event.key === '[' || event.key === ']') && count > 0) {
      const k = this.selected ?? (event.key === ']' ? -1 : 0);
      this.choose((k + (event.key === ']' ? 1 : count - 1)) % count);
      event.preventDefault();
      return;
    }
    const moves: Record<string, [number, number]> = { ArrowLeft: [0, -1], ArrowRight: [0, 1], ArrowDown: [1, -1], ArrowUp: [1, 1], PageDown: [2, -1], PageUp: [2, 1] };
    const move = moves[event.key];
    const w = this.selected === null ? undefined : this.editable()?.written[this.selected];
    if (!move || !w || event.ctrlKey || event.metaKey || event.altKey) return;
    event.preventDefault();
    const next: Point3 = [...w.value];
    next[move[0]] += move[1] * this.step() * (event.shiftKey ? 10 : 1);
    this.place(next);
  }

  private pointerDown(event: PointerEvent): void {
    if (event.button !== 0 || this.drag) return;
    const surface = this.editable();
    if (!surface) return;
    const k = this.scene.pointAt(event.clientX, event.clientY, event.pointerType === 'touch' ? REACH.touch : REACH.mouse);
    if (k === null) return;
    // A point, not the view: no orbit.
    event.stopImmediatePropagation();
    event.preventDefault();
    const found = this.editOf(k);
    const at = surface.net[k];
    const target = this.scene.dragTarget(event.clientX, event.clientY, at, this.axis());
    if (!found || !target) return;
    this.choose(k);
    this.scene.orbiting = false;
    this.c.canvas.setPointerCapture(event.pointerId);
    this.c.canvas.focus();
    const grab = new Vector3(...at).sub(new Vector3(...target));
    this.drag = { pointer: event.pointerId, ...found, grab, through: at };
  }

  private pointerMove(event: PointerEvent): void {
    const drag = this.drag;
    if (!drag || event.pointerId !== drag.pointer) return;
    const target = this.scene.dragTarget(event.clientX, event.clientY, drag.through, this.axis());
    if (!target) return;
    const turtle = new Vector3(...target).add(drag.grab);
    const written = turtle.clone().applyMatrix4(this.fromTurtle);
    if (!drag.edit.move([written.x, written.y, written.z])) return this.endDrag(event.pointerId);
    this.scene.movePoint(drag.copies, [turtle.x, turtle.y, turtle.z]);
    this.scene.select(this.selected);
  }

  private pointerUp(event: PointerEvent): void {
    if (this.drag?.pointer !== event.pointerId) return;
    this.drag.edit.end();
    this.endDrag(event.pointerId);
  }

  private endDrag(pointer: number): void {
    this.drag = undefined;
    this.scene.orbiting = true;
    if (this.c.canvas.hasPointerCapture(pointer)) this.c.canvas.releasePointerCapture(pointer);
    this.refresh();
  }

  /** The drag's axis as a direction in the view (the written axis through the surface's frame), or null: facing the camera. */
  private axis(): Vector3 | null {
    const value = this.c.axis.value;
    if (value === '') return null;
    const direction = new Vector3().setComponent(Number(value), 1);
    return direction.transformDirection(this.toTurtle);
  }

  /** Writes a library shape's patches into the text (one undo step), so that its points can move. */
  private writeOut(): void {
    this.refresh(); // the changes' offsets are those of the text now
    const surface = this.answer?.surface;
    if (!surface?.organ) return;
    if (surface.writeOut.length === 0) return;
    this.host.editor.replaceRanges(surface.writeOut, { history: true });
    this.refresh();
  }
}
