// The Share button and its dialog: the link to the studio's state, in a read-only field to copy by
// hand, and a Copy button that puts it on the clipboard (or says how to copy it where the clipboard
// is denied). Every link is first opened here with the very decoder that opens it elsewhere: one
// that would be refused (too long for a link, most often) is never offered; the dialog says why
// and offers the grammar as a file instead.
import { decodeState, encodeState, MAX_FRAGMENT, type SharedState } from '../share/codec';
import { saveGrammarFile } from './grammar-files';
import type { Notice } from './notice';

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

/**
 * Makes a link of `state` and opens it as a receiver would: the fragment, or the receiver's reason
 * to refuse it (its grammar is then the thing to share).
 */
export async function shareableLink(state: SharedState): Promise<{ ok: true; fragment: string } | { ok: false; why: string }> {
  const fragment = await encodeState(state);
  const length = fragment.length - 1; // without its '#', as the decoder counts
  if (length > MAX_FRAGMENT) {
    return { ok: false, why: `the link would be ${count.format(length)} characters long, and a link holds at most ${count.format(MAX_FRAGMENT)}` };
  }
  const decoded = await decodeState(fragment);
  return decoded.ok ? { ok: true, fragment } : { ok: false, why: decoded.error };
}

/**
 * The Share button: the studio's state now, `state()`, as a link in the dialog (a failure in the
 * notice); `shared` hears the state and its fragment too (the embed snippets).
 */
export function installShareButton(
  button: HTMLButtonElement,
  dialog: ShareDialog,
  state: () => SharedState,
  notice: Notice,
  shared?: (state: SharedState, fragment: string) => void,
): void {
  button.addEventListener('click', () => {
    const now = state();
    void shareableLink(now)
      .then((link) => {
        if (!link.ok) return dialog.refuse(link.why, now.text);
        shared?.(now, link.fragment);
        return dialog.open(linkWithFragment(location, link.fragment));
      })
      .catch((error: unknown) => notice.show('error', `Could not make a link: ${String(error)}`));
  });
}

/** The studio's address without any fragment, then `fragment`: a link that opens this state. */
export function linkWithFragment(location: Pick<Location, 'href' | 'hash'>, fragment: string): string {
  const base = location.hash ? location.href.slice(0, location.href.length - location.hash.length) : location.href.replace(/#$/, '');
  return base + fragment;
}
