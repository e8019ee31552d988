// Branch editing (./branch-editing.ts), loaded when it is first wanted: the Reshape button pressed,
// or a shared link's edits to show (issue 22: the first plant needs none of it). Until then there
// are no edits, and only the button listens.
import type { EditsDocument } from '../../core';
import type { PlantView } from '../../view';
import type { BranchEditingElements, BranchEditingHost, BranchEditSession } from './branch-editing';
import { onDemand } from '../page';

/** What the studio asks of branch editing (the link, downloads, each build, the tests). */
export type BranchEdits = Pick<BranchEditSession, 'document' | 'restore' | 'plantShown' | 'handlesOnPage' | 'selectedPath'>;

/** A {@link BranchEditSession} on `els` that loads with its first use. */
export class LazyBranchEditing implements BranchEdits {
  private session: BranchEditSession | undefined;
  /** A link's edits, restored before the session has loaded. */
  private pending: EditsDocument | undefined;
  /** The first press: shown pressed at once; the session, once loaded, takes the press. */
  private readonly toggled = () => {
    this.els.toggle.setAttribute('aria-pressed', 'true');
    void this.load().then((session) => (session ? this.els.toggle.click() : this.els.toggle.setAttribute('aria-pressed', 'false')));
  };

  constructor(
    private readonly els: BranchEditingElements,
    private readonly view: PlantView,
    private readonly host: BranchEditingHost,
  ) {
    els.toggle.addEventListener('click', this.toggled);
  }

  /** Loads branch editing in the background (a failure is tried again by the first use). */
  preload(): Promise<unknown> {
    return this.loaded().catch(() => undefined);
  }

  /** As {@link BranchEditSession.document}. */
  document(): EditsDocument | undefined {
    if (this.session) return this.session.document();
    return this.pending && structuredClone(this.pending);
  }

  /** As {@link BranchEditSession.restore}; loads branch editing first. */
  restore(doc: EditsDocument): void {
    if (this.session) return this.session.restore(doc);
    this.pending = doc;
    void this.load();
  }

  /** As {@link BranchEditSession.plantShown}: nothing to do before it has loaded (no edits, no Edit mode). */
  plantShown(): void {
    this.session?.plantShown();
  }

  /** As {@link BranchEditSession.handlesOnPage}. */
  handlesOnPage(): { x: number; y: number }[] {
    return this.session?.handlesOnPage() ?? [];
  }

  /** As {@link BranchEditSession.selectedPath}. */
  selectedPath(): number[] | null {
    return this.session?.selectedPath() ?? null;
  }

  private readonly loaded = onDemand(async () => {
    const { BranchEditSession } = await import('./branch-editing');
    this.els.toggle.removeEventListener('click', this.toggled); // the session listens to its button now
    const session = new BranchEditSession(this.els, this.view, this.host);
    this.session = session;
    if (this.pending) {
      session.restore(this.pending);
      this.pending = undefined;
    }
    return session;
  });

  /** The session, loaded (undefined, told, when it could not load: the next use tries again). */
  private load(): Promise<BranchEditSession | undefined> {
    return this.loaded().catch((error: unknown) => {
      this.host.tell('error', `Branch editing could not be loaded: ${String(error)}`);
      return undefined;
    });
  }
}
