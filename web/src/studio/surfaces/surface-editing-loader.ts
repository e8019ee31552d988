// The surface editor (./surface-dialog.ts, with three.js's orbit controls and the core module that
// answers about surfaces), loaded when it is first opened (issue 22: the first plant needs none of it).
import { loadSurfacePreview } from '../../core';
import type { Notice } from '../page';
import { onDemand } from '../page';
import type { SurfaceDialog, SurfaceEditorHost } from './surface-dialog';

/** The surface editor on the page, loaded on its first opening. */
export class LazySurfaceEditing {
  private dialog: SurfaceDialog | undefined;
  private readonly loaded = onDemand(async () => {
    const [{ SurfaceDialog }, preview] = await Promise.all([import('./surface-dialog'), loadSurfacePreview()]);
    this.dialog = new SurfaceDialog(this.host, preview);
    return this.dialog;
  });

  constructor(
    private readonly host: SurfaceEditorHost,
    private readonly notice: Notice,
  ) {}

  /** Opens the editor on surface `letter` (loading it first; a failure is said, and tried again next time). */
  open(letter: string): void {
    this.loaded()
      .then((dialog) => dialog.open(letter))
      .catch((error: unknown) => this.notice.show('error', `The surface editor could not load: ${error instanceof Error ? error.message : String(error)}`));
  }

  /** The grammar text changed: an open editor follows it. */
  textChanged(): void {
    this.dialog?.textChanged();
  }

  /** Net point `k` of the surface shown, on the page (tests); null when the editor is closed. */
  pointOnPage(k: number): { x: number; y: number } | null {
    return this.dialog?.isOpen ? this.dialog.pointOnPage(k) : null;
  }
}
