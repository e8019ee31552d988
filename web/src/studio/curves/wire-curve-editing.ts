// The curve editor (issue 48), wired to the studio's parts: opened from the text (the gutter's
// marker of a `#curve`/`#table` line, Alt+B on it), following every change of the text. Wired
// with the surface editor, once the vocabulary has arrived (the gutter's markers need it); the
// panel itself (./curve-panel.ts) loads on its first opening.
import type { Notice } from '../page';
import { onDemand } from '../page';
import type { StudioParts } from '../parts';
import type { CurveEditorHost, CurvePanel } from './curve-panel';

/** The panel on the page, loaded on its first opening. */
export class LazyCurveEditing {
  private panel: CurvePanel | undefined;
  private readonly loaded = onDemand(async () => {
    const { CurvePanel } = await import('./curve-panel');
    return (this.panel = new CurvePanel(this.host));
  });

  constructor(
    private readonly host: CurveEditorHost,
    private readonly notice: Notice,
  ) {}

  /** Opens the panel on curve `name` (loading it first); says why not when its line cannot be edited as points. */
  open(name: string): void {
    this.loaded()
      .then((panel) => {
        const why = panel.open(name);
        if (why) this.notice.show('info', why);
      })
      .catch((error: unknown) => this.notice.show('error', `The curve editor could not load: ${error instanceof Error ? error.message : String(error)}`));
  }

  /** The grammar text changed: an open panel follows it. */
  textChanged(): void {
    this.panel?.textChanged();
  }
}

/** The curve editor on the grammar in `editor`. */
export function wireCurveEditing({ editor, notice }: Pick<StudioParts, 'editor' | 'notice'>): void {
  const editing = new LazyCurveEditing({ editor }, notice);
  editor.onOpenEditor(({ what, name }) => {
    if (what === 'curve') editing.open(name);
  });
  editor.onChange(() => editing.textChanged());
}
