// Opening shared links: the one the page was opened with, and one pasted into the tab's address bar
// later. Opening a link never loses the user's text: the autosaved work is kept in My grammars first.
import { decodeState, hasSharedState, type SharedState } from '../share/codec';
import { titleOf, type GrammarStore } from '../share/storage';
import type { Autosave } from './autosave';
import { fetchExample } from './gallery';
import type { LinkState } from './link-state';
import type { Notice } from './notice';
import { linkWithFragment } from './share-dialog';
import type { OpenedText, TextOpening } from './text-opening';

/** Where the editor's first text comes from. */
export interface StartingText extends OpenedText {
  from: 'link' | 'autosave' | 'example';
  /** The link's state, when it came from one. */
  state?: SharedState;
}

/**
 * The text the studio opens with: a shared link's (its fragment is then removed from the address,
 * so a reload restores the user's later edits), else the autosaved text, else the example
 * `firstExample`. A link that cannot be opened is said in the notice, and the studio opens as if
 * it had none.
 */
export async function startingText(store: GrammarStore, notice: Notice, firstExample: string): Promise<StartingText> {
  if (hasSharedState(location.hash)) {
    const opened = await openLink(location.hash, store, notice);
    history.replaceState(null, '', linkWithFragment(location, ''));
    if (opened) return { text: opened.state.text, file: '', from: 'link', state: opened.state };
  }
  const saved = store.restore();
  if (saved && saved.text.trim() !== '') return { text: saved.text, file: '', from: 'autosave' };
  return { text: await fetchExample(firstExample), file: firstExample, from: 'example' };
}

/**
 * Decodes a shared link. A rejected one is said in the notice (and nothing changes). An accepted
 * one first keeps the autosaved work in My grammars, unless it is the link's text or saved there
 * already: opening a link never loses a user's text.
 */
export async function openLink(fragment: string, store: GrammarStore, notice: Notice): Promise<{ state: SharedState } | null> {
  const decoded = await decodeState(fragment);
  if (!decoded.ok) {
    notice.show('error', `This link could not be opened: ${decoded.error}. The studio opened as usual.`);
    return null;
  }
  const previous = store.restore();
  if (previous && previous.text.trim() !== '' && previous.text !== decoded.state.text && !store.list().some((g) => g.text === previous.text)) {
    const kept = store.save(`Before a shared link: ${titleOf(previous.text)}`, previous.text);
    notice.show(
      'info',
      kept
        ? `Opened a shared link. Your previous text is kept in My grammars as “${kept.name}”.`
        : 'Opened a shared link. Your previous text could not be kept (this browser’s storage is full): Ctrl+Z in the editor does not reach it.',
    );
  } else notice.hide();
  return { state: decoded.state };
}

/** What opening a pasted link goes through. */
export interface PastedLinkParts {
  store: GrammarStore;
  notice: Notice;
  autosave: Autosave;
  opening: TextOpening;
  link: LinkState;
  /** Builds the link's plant with its options. */
  buildNow(): void;
}

/**
 * Opens a link pasted into this tab's address bar: the text now is autosaved (it is what the link
 * may replace), the link's text replaces it (asking first), then its options, edits and camera.
 */
export function openPastedLinks(parts: PastedLinkParts): void {
  window.addEventListener('hashchange', () => {
    if (!hasSharedState(location.hash)) return;
    parts.autosave.flush();
    void openLink(location.hash, parts.store, parts.notice).then((opened) => {
      history.replaceState(null, '', linkWithFragment(location, ''));
      if (!opened) return;
      void parts.opening.replace(opened.state.text, 'the shared link', 'link').then((done) => {
        if (!done) return;
        parts.link.restore(opened.state);
        parts.buildNow();
      });
    });
  });
}
