// The Share button and its dialog: the link to the studio's state, in a read-only field to copy by
// hand, and a Copy button that puts it on the clipboard (or says how to copy it where the clipboard
// is denied). Every link is first opened here with the very decoder that opens it elsewhere: one
// that would be refused (too long for a link, most often) is never offered; the dialog says why
// and offers the grammar as a file instead. The dialog loads with the first share (issue 22: the
// first plant needs none of it); the button, and making the link, are ./share-button.ts.
// Loaded on demand: it imports other areas' files, not their indexes, which would bring their
// wiring into its chunk's graph (and split the first load into more files).
import { saveGrammarFile } from '../files/grammar-files';
import './share-dialog.css';

/** The dialog's elements (see index.html). */
export interface ShareDialogElements {
  dialog: HTMLDialogElement;
  link: HTMLInputElement;
  copy: HTMLButtonElement;
  status: HTMLElement;
  size: HTMLElement;
  /** The link and its Copy button; hidden for a link that would not open. */
  linkRow: HTMLElement;
  /** The copy status and the link's size; hidden with the link. */
  statusLine: HTMLElement;
  /** Why there is no link, and the Download button; shown instead of the link. */
  tooLong: HTMLElement;
  tooLongText: HTMLElement;
  download: HTMLButtonElement;
}

const count = new Intl.NumberFormat('en-US');

export class ShareDialog {
  /** The grammar that Download saves (the one a link could not hold). */
  private text = '';

  constructor(private readonly els: ShareDialogElements) {
    els.copy.addEventListener('click', () => void this.copy());
    els.download.addEventListener('click', () => saveGrammarFile(this.text));
  }

  /** Shows `url`, selected, and tries to copy it at once. */
  async open(url: string): Promise<void> {
    const { dialog, link, status, size } = this.els;
    this.showLink(true);
    link.value = url;
    size.textContent = `${count.format(url.length)} characters`;
    status.textContent = '';
    if (!dialog.open) dialog.showModal();
    link.focus();
    link.select();
    await this.copy();
  }

  /**
   * Says that no link can hold this state (`why`, as the decoder says it) and offers the grammar
   * `text` as a file to send instead.
   */
  refuse(why: string, text: string): void {
    const { dialog, link, tooLongText, download } = this.els;
    this.showLink(false);
    this.text = text;
    link.value = '';
    tooLongText.textContent = `This plant cannot be shared as a link: ${why}. Download the grammar and send the file instead (File ▸ Open reads it).`;
    if (!dialog.open) dialog.showModal();
    download.focus();
  }

  private showLink(shown: boolean): void {
    this.els.linkRow.hidden = !shown;
    this.els.statusLine.hidden = !shown;
    this.els.tooLong.hidden = shown;
  }

  /** Copies the link; says whether it worked. */
  private async copy(): Promise<void> {
    const { link, status } = this.els;
    link.select();
    let copied = false;
    try {
      await navigator.clipboard.writeText(link.value);
      copied = true;
    } catch {
      // The clipboard may be denied (no user gesture, an insecure origin): the field is selected.
    }
    status.dataset.state = copied ? 'copied' : 'manual';
    status.textContent = copied ? 'Link copied to the clipboard.' : 'Select the link and copy it (Ctrl+C).';
  }
}
