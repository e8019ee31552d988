// A panel beside the grammar text that edits it (the surface editor, the curve editor): a
// non-modal <dialog>, so that the text and the plant stay in use while it is open. Escape or its
// Close button closes it and gives the focus back to what had it; it follows the text at most once
// a frame, however often the text changes (a drag writes it at every step). Its look: text-panel.css.
import './text-panel.css';

/** The panel's dialog, its opening and closing, and its following of the text. */
export class TextPanel {
  /** What had the focus when the panel opened: it gets it back when the panel closes. */
  private opener: HTMLElement | null = null;
  private followQueued = false;

  /** `follow` reads the text again and shows it (called at the next frame after a change, while open). */
  constructor(
    readonly dialog: HTMLDialogElement,
    close: HTMLButtonElement,
    private readonly follow: () => void,
  ) {
    dialog.classList.add('text-panel');
    close.addEventListener('click', () => dialog.close());
    dialog.addEventListener('close', () => {
      if (this.opener?.isConnected) this.opener.focus();
      this.opener = null;
    });
    dialog.addEventListener('keydown', (event) => {
      if (event.key !== 'Escape') return;
      event.preventDefault();
      dialog.close();
    });
  }

  /** Shows the panel (it stays open if it is). */
  show(): void {
    if (this.dialog.open) return;
    this.opener = document.activeElement instanceof HTMLElement ? document.activeElement : null;
    this.dialog.show();
  }

  /** Whether the panel is open. */
  get isOpen(): boolean {
    return this.dialog.open;
  }

  /** The grammar text changed (typed, or written by the panel): it follows at the next frame. */
  textChanged(): void {
    if (!this.dialog.open || this.followQueued) return;
    this.followQueued = true;
    requestAnimationFrame(() => {
      this.followQueued = false;
      if (this.dialog.open) this.follow();
    });
  }
}
