// The Share button and its dialog: the link to the studio's state, in a read-only field to copy by
// hand, and a Copy button that puts it on the clipboard (or says how to copy it where the clipboard
// is denied).
import { encodeState, type SharedState } from '../share/codec';
import type { Notice } from './notice';

/** The dialog's elements (see index.html). */
export interface ShareDialogElements {
  dialog: HTMLDialogElement;
  link: HTMLInputElement;
  copy: HTMLButtonElement;
  status: HTMLElement;
  size: HTMLElement;
}

export class ShareDialog {
  constructor(private readonly els: ShareDialogElements) {
    els.copy.addEventListener('click', () => void this.copy());
  }

  /** Shows `url`, selected, and tries to copy it at once. */
  async open(url: string): Promise<void> {
    const { dialog, link, status, size } = this.els;
    link.value = url;
    size.textContent = `${url.length.toLocaleString('en-US')} characters`;
    status.textContent = '';
    if (!dialog.open) dialog.showModal();
    link.focus();
    link.select();
    await this.copy();
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
    void encodeState(now)
      .then((fragment) => {
        shared?.(now, fragment);
        return dialog.open(linkWithFragment(location, fragment));
      })
      .catch((error: unknown) => notice.show('error', `Could not make a link: ${String(error)}`));
  });
}

/** The studio's address without any fragment, then `fragment`: a link that opens this state. */
export function linkWithFragment(location: Pick<Location, 'href' | 'hash'>, fragment: string): string {
  const base = location.hash ? location.href.slice(0, location.href.length - location.hash.length) : location.href.replace(/#$/, '');
  return base + fragment;
}
