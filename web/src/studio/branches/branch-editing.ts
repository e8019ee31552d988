// Editing branches by their Bézier handles (issue 8) in the studio. The edits are one document
// (overrides keyed by each branch's stable path, docs/LANGUAGE.md "Branches") with an undo and a
// redo stack. Whenever there are edits, or the Edit mode is on, the plant on screen is the page
// core's editable build of the text (`editPlant`, rebuilt after every build the worker delivers)
// with the document applied; edits whose branch no longer exists are kept, and named in the notice.
// In Edit mode a click selects a branch and shows its handles; dragging one moves the branch and
// its descendants, and only the vertices that moved are uploaded.
import {
  applyMeshUpdate,
  DragRefused,
  loadBranchEditing,
  noEdits,
  type BuildOptions,
  type EditPlant,
  type EditReport,
  type EditsDocument,
  type Handle,
  type MeshBuffers,
  type MeshUpdate,
  type PlantEditor,
} from '../../core';
import type { PlantView } from '../../view';
import './branch-editing.css';

/** Plants with more segments than this are not edited on the page (the editor builds on its thread). */
export const MAX_EDITABLE_SEGMENTS = 60_000;

/** The page elements of branch editing (see index.html). */
export interface BranchEditingElements {
  toggle: HTMLButtonElement;
  undo: HTMLButtonElement;
  redo: HTMLButtonElement;
  reset: HTMLButtonElement;
}

/** What the session needs of the page. */
export interface BranchEditingHost {
  /** The text and options of the plant on screen (the last good build), if any. */
  shown(): { source: string; options: BuildOptions; segments: number; flat: boolean } | undefined;
  /** Says something in the notice bar (null: nothing to say). */
  tell(kind: 'info' | 'error', message: string | null, items?: string[]): void;
  /** Edit mode started or ended (e.g. the context view stops picking modules meanwhile). */
  modeChanged(on: boolean): void;
}

/** "0/2/1": a branch path as the studio writes it. */
export function pathText(path: readonly number[]): string {
  return path.join('/');
}

/** What to say of edits that do not apply to the plant on screen. */
export function staleEditsMessage(report: EditReport): { message: string; items: string[] } | null {
  const n = report.notApplied.length;
  if (n === 0) return null;
  return {
    message: `${n} branch ${n === 1 ? 'edit no longer applies' : 'edits no longer apply'} to this plant (kept, in case the branch comes back):`,
    items: report.notApplied.map((e) => `branch ${pathText(e.path)}: ${e.reason}`),
  };
}

/** Two edits documents are the same edits. */
function same(a: EditsDocument, b: EditsDocument): boolean {
  return JSON.stringify(a) === JSON.stringify(b);
}

export class BranchEditSession {
  private doc: EditsDocument = noEdits();
  private readonly undoStack: EditsDocument[] = [];
  private readonly redoStack: EditsDocument[] = [];
  private editor: PlantEditor | undefined;
  /** The mesh on screen when it is the editor's (its arrays are the view's). */
  private mesh: MeshBuffers | undefined;
  private editing = false;
  private selected: number | null = null;
  private drag: { handle: Handle; before: EditsDocument; pointer: number } | undefined;
  /** Where the last press was, and whether it dragged a handle: the click after either is no pick. */
  private press = { x: 0, y: 0, handle: false };
  /** A click on the plant before the editor was there (its core still loading): picked once it is. */
  private pendingPick: { x: number; y: number } | undefined;
  /** The last report of edits that do not apply (shown in the notice). */
  private stale = '';
  /** Counts attaches and drops: an attach that waited for the core goes on only if it is the last. */
  private attachments = 0;
  /** Branch editing's `editPlant`, once loaded (its core module is not the first plant's). */
  private editPlant: EditPlant | undefined;

  constructor(
    private readonly els: BranchEditingElements,
    private readonly view: PlantView,
    private readonly host: BranchEditingHost,
  ) {
    els.toggle.addEventListener('click', () => this.setMode(!this.editing));
    els.undo.addEventListener('click', () => this.undo());
    els.redo.addEventListener('click', () => this.redo());
    els.reset.addEventListener('click', () => this.reset());
    const canvas = view.canvas;
    canvas.addEventListener('pointerdown', (event) => this.pointerDown(event), { capture: true });
    canvas.addEventListener('pointermove', (event) => this.pointerMove(event));
    canvas.addEventListener('pointerup', (event) => this.pointerUp(event));
    canvas.addEventListener('pointercancel', (event) => this.pointerUp(event));
    canvas.addEventListener('click', (event) => this.click(event));
    view.onRender(() => this.pickPending());
    window.addEventListener('keydown', (event) => {
      if (!this.editing) return;
      if (event.key === 'Escape' && !document.querySelector('dialog[open]')) this.setMode(false);
    });
    window.addEventListener('keydown', (event) => {
      // Ctrl+Z over the view undoes branch edits; in the editor and fields it stays theirs.
      const inText = (event.target as HTMLElement | null)?.closest('input, textarea, select, .cm-editor, dialog');
      if (!inText && (this.editing || this.doc.edits.length > 0) && this.handleKey(event)) event.preventDefault();
    });
    this.showButtons();
  }

  /** The edits in force (for share links and downloads); undefined when there are none. */
  document(): EditsDocument | undefined {
    return this.doc.edits.length > 0 ? structuredClone(this.doc) : undefined;
  }

  /** Replaces the edits by `doc` (a shared link's), as one undoable step. */
  restore(doc: EditsDocument): void {
    if (same(doc, this.doc)) return;
    this.commit(doc);
  }

  /** Whether Edit mode is on. */
  get active(): boolean {
    return this.editing;
  }

  /** The selected branch's handles on the page (for tests): P0..P3 in CSS pixels. */
  handlesOnPage(): { x: number; y: number }[] {
    if (!this.editor || this.selected === null) return [];
    const points = this.editor.controlPoints().slice(12 * this.selected, 12 * this.selected + 12);
    return [0, 1, 2, 3].map((i) => this.view.pageOf([points[3 * i], points[3 * i + 1], points[3 * i + 2]]));
  }

  /** The selected branch's path, or null. */
  selectedPath(): number[] | null {
    return this.editor && this.selected !== null ? (this.editor.branches()[this.selected]?.path ?? null) : null;
  }

  /**
   * A build of the text is on screen (the worker's, unedited). With edits or in Edit mode, the
   * page's editor takes its place: rebuilt for this text, the edits applied, the plant shown.
   */
  plantShown(): void {
    this.dropEditor();
    if (this.doc.edits.length === 0 && !this.editing) {
      this.tellStale(null);
      return;
    }
    this.attach();
  }

  private setMode(on: boolean): void {
    if (on) {
      const shown = this.host.shown();
      if (!shown) return;
      if (shown.segments > MAX_EDITABLE_SEGMENTS) {
        this.host.tell('error', `Branch editing works on plants of up to ${MAX_EDITABLE_SEGMENTS.toLocaleString('en-US')} segments; this one has ${shown.segments.toLocaleString('en-US')}.`);
        return;
      }
    }
    this.editing = on;
    this.selected = null;
    this.pendingPick = undefined;
    this.view.holdTubes('editing', on); // the handles reshape tubes
    this.view.showHandles(null);
    this.view.canvas.classList.toggle('editing-branches', on);
    if (on && !this.editor) this.attach();
    if (!on && this.doc.edits.length === 0) this.plantShown(); // back to the worker's plant
    else if (!on && this.editor) {
      // Drags patched the tubes alone: the segments (the Lines mode's) come with a whole copy.
      this.mesh = this.editor.mesh();
      this.view.showPlant(this.mesh, this.host.shown()?.flat ?? false);
    }
    this.host.modeChanged(on);
    this.showButtons();
  }

  /**
   * Builds the editor for the plant on screen and shows it with the edits applied. Branch editing
   * is in the core module with the importers and exporters, which the first plant does without:
   * the first call loads it, then attaches unless the plant or the mode changed meanwhile.
   */
  private attach(): void {
    const shown = this.host.shown();
    if (!shown || shown.segments > MAX_EDITABLE_SEGMENTS) {
      if (shown && this.doc.edits.length > 0) {
        this.host.tell('error', `The branch edits are not shown: this plant has more than ${MAX_EDITABLE_SEGMENTS.toLocaleString('en-US')} segments.`);
      }
      this.editing = false;
      this.showButtons();
      return;
    }
    const editPlant = this.editPlant;
    if (!editPlant) {
      const waiting = ++this.attachments;
      // Busy (the pointer says so) until the core has loaded: a click meanwhile waits for it.
      const canvas = this.view.canvas;
      canvas.setAttribute('aria-busy', 'true');
      loadBranchEditing()
        .then(
          (loaded) => {
            this.editPlant = loaded;
            if (waiting === this.attachments && !this.editor && (this.editing || this.doc.edits.length > 0)) this.attach();
          },
          (error: unknown) => this.host.tell('error', `Branch editing could not be loaded: ${String(error)}`),
        )
        .finally(() => canvas.removeAttribute('aria-busy'));
      return;
    }
    const { editor } = editPlant(shown.source, shown.options);
    this.editor = editor;
    const { report, update } = editor.applyEdits(this.doc);
    this.mesh = update.mesh ?? editor.mesh();
    this.view.showPlant(this.mesh, shown.flat);
    this.tellStale(report);
    if (this.selected !== null && this.selected >= editor.branches().length) this.selected = null;
    this.showSelection();
    this.pickPending();
  }

  private dropEditor(): void {
    this.attachments++; // an attach still loading the core is for a plant no longer shown
    this.editor?.free();
    this.editor = undefined;
    this.mesh = undefined;
    this.selected = null;
    this.pendingPick = undefined; // a click on a plant no longer shown
    this.view.showHandles(null);
  }

  private tellStale(report: EditReport | null): void {
    const stale = report ? staleEditsMessage(report) : null;
    const key = stale ? stale.items.join('\n') : '';
    if (key === this.stale) return;
    this.stale = key;
    this.host.tell('info', stale?.message ?? null, stale?.items);
  }

  private showSelection(): void {
    if (!this.editor || this.selected === null) {
      this.view.showHandles(null);
      return;
    }
    this.view.showHandles(this.editor.controlPoints().slice(12 * this.selected, 12 * this.selected + 12));
  }

  private pointerDown(event: PointerEvent): void {
    this.press = { x: event.clientX, y: event.clientY, handle: false };
    if (!this.editing || !this.editor || this.selected === null || event.button !== 0) return;
    const handle = this.view.handleAt(event.clientX, event.clientY);
    if (handle === null) return;
    // A handle, not the plant: no orbit, no click on the plant.
    event.stopImmediatePropagation();
    event.preventDefault();
    this.view.setOrbitEnabled(false);
    this.view.canvas.setPointerCapture(event.pointerId);
    this.drag = { handle, before: this.editor.edits(), pointer: event.pointerId };
    this.press.handle = true;
  }

  private pointerMove(event: PointerEvent): void {
    const drag = this.drag;
    if (!drag || !this.editor || this.selected === null || event.pointerId !== drag.pointer) return;
    const points = this.editor.controlPoints();
    const at = 12 * this.selected + 3 * drag.handle;
    const target = this.view.dragTarget(event.clientX, event.clientY, [points[at], points[at + 1], points[at + 2]]);
    if (!target) return;
    let update: MeshUpdate;
    try {
      update = this.editor.drag(this.selected, drag.handle, target);
    } catch (error) {
      // Past the reach of an edit (the pointer near the horizon): the handle stays where it was.
      if (error instanceof DragRefused) return;
      throw error;
    }
    // (Said on the Reshape button, for the tests: a drag re-meshes only what moved, or the whole plant.)
    this.els.toggle.dataset.lastDrag = update.full ? 'whole' : 'partial';
    if (update.full && update.mesh) {
      this.mesh = update.mesh;
      this.view.showPlant(this.mesh, this.host.shown()?.flat ?? false);
    } else if (this.mesh) {
      applyMeshUpdate(this.mesh, update);
      this.view.patchVertices(update.ranges);
    }
    this.showSelection();
  }

  private pointerUp(event: PointerEvent): void {
    const drag = this.drag;
    if (!drag || event.pointerId !== drag.pointer) return;
    this.drag = undefined;
    this.view.setOrbitEnabled(true);
    if (this.view.canvas.hasPointerCapture(event.pointerId)) this.view.canvas.releasePointerCapture(event.pointerId);
    if (!this.editor) return;
    const after = this.editor.edits();
    if (same(after, drag.before)) return;
    this.undoStack.push(this.mergedWithStale(drag.before));
    this.redoStack.length = 0;
    this.doc = this.mergedWithStale(after);
    this.showButtons();
  }

  /**
   * The editor's edits (applied ones only) and the document's edits that do not apply to this
   * plant: those stay in the document, in case their branch comes back.
   */
  private mergedWithStale(applied: EditsDocument): EditsDocument {
    if (!this.editor) return applied;
    const editor = this.editor;
    const kept = this.doc.edits.filter((e) => editor.findBranch(e.path) === null);
    return { version: applied.version, edits: [...applied.edits, ...kept] };
  }

  private click(event: MouseEvent): void {
    if (!this.editing || event.detail === 0) return;
    // Not the end of a handle drag, nor of an orbit.
    if (this.press.handle || Math.hypot(event.clientX - this.press.x, event.clientY - this.press.y) > 4) return;
    this.pendingPick = { x: event.clientX, y: event.clientY };
    this.pickPending();
  }

  /**
   * Selects the branch under the click kept in {@link pendingPick}, once the editor's plant is on
   * screen: at once, or (Edit mode pressed and the plant clicked while the core loads, or the
   * editor's plant on its way to the GPU) after the frame that shows it.
   */
  private pickPending(): void {
    const at = this.pendingPick;
    if (!at || !this.editor || this.view.uploading) return;
    this.pendingPick = undefined;
    const triangle = this.view.pickTriangle(at.x, at.y);
    this.selected = triangle === null ? null : this.editor.branchAt(triangle);
    this.showSelection();
  }

  /** Makes `doc` the edits (one undoable step) and shows the plant with them. */
  private commit(doc: EditsDocument): void {
    this.undoStack.push(this.doc);
    this.redoStack.length = 0;
    this.doc = structuredClone(doc);
    this.reapply();
  }

  private undo(): void {
    this.step(this.undoStack, this.redoStack);
  }

  private redo(): void {
    this.step(this.redoStack, this.undoStack);
  }

  /** Undoes or redoes: the edits from the top of `from`, the edits now kept on `to`. */
  private step(from: EditsDocument[], to: EditsDocument[]): void {
    const doc = from.pop();
    if (!doc) return;
    to.push(this.doc);
    this.doc = doc;
    this.reapply();
  }

  private reset(): void {
    if (this.doc.edits.length > 0) this.commit(noEdits());
  }

  private reapply(): void {
    if (this.editor) {
      const { report, update } = this.editor.applyEdits(this.doc);
      this.mesh = update.mesh ?? this.editor.mesh();
      this.view.showPlant(this.mesh, this.host.shown()?.flat ?? false);
      this.tellStale(report);
      this.showSelection();
    } else {
      this.plantShown();
    }
    this.showButtons();
  }

  private showButtons(): void {
    const { toggle, undo, redo, reset } = this.els;
    toggle.setAttribute('aria-pressed', String(this.editing));
    undo.disabled = this.undoStack.length === 0;
    redo.disabled = this.redoStack.length === 0;
    reset.disabled = this.doc.edits.length === 0;
  }

  /** Ctrl+Z / Ctrl+Shift+Z while the view has the focus (the editor keeps its own). */
  private handleKey(event: KeyboardEvent): boolean {
    if (!(event.ctrlKey || event.metaKey) || event.altKey || event.code !== 'KeyZ') return false;
    if (event.shiftKey) this.redo();
    else this.undo();
    return true;
  }
}
