// The Share button: the studio's state as a link, made and opened here first with the very decoder
// that opens it elsewhere (./share-dialog.ts shows it, loaded with the first share).
import { decodeState, encodeState, MAX_FRAGMENT, type SharedState } from '../../share';
import type { Notice } from '../page';
import type { ShareDialog } from './share-dialog';

const count = new Intl.NumberFormat('en-US');

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
 * The Share button: the studio's state now, `state()`, as a link in the dialog (`dialog()`, made on
 * the first share; a failure in the notice); `shared` hears the state and its fragment too (the embed snippets).
 */
export function installShareButton(
  button: HTMLButtonElement,
  dialog: () => Promise<ShareDialog>,
  state: () => SharedState,
  notice: Notice,
  shared?: (state: SharedState, fragment: string) => void,
): void {
  button.addEventListener('click', () => {
    const now = state();
    void shareableLink(now)
      .then((link) => {
        return dialog().then((shown) => {
          if (!link.ok) return shown.refuse(link.why, now.text);
          shared?.(now, link.fragment);
          return shown.open(linkWithFragment(location, link.fragment));
        });
      })
      .catch((error: unknown) => notice.show('error', `Could not make a link: ${String(error)}`));
  });
}

/** The studio's address without any fragment, then `fragment`: a link that opens this state. */
export function linkWithFragment(location: Pick<Location, 'href' | 'hash'>, fragment: string): string {
  const base = location.hash ? location.href.slice(0, location.href.length - location.hash.length) : location.href.replace(/#$/, '');
  return base + fragment;
}
