// Opening shared links: the one the page was opened with, and one pasted into the tab's address bar
// later. Opening a link never loses the user's text: it is kept first (TextKeeper), and when this
// browser cannot keep it anywhere the link is opened only after the user downloads it.
import { decodeState, type GrammarStore, hasSharedState, type KeptTexts, loadCodec, type SharedState } from '../../share';
import { askToDownload, type Notice, type QuestionDialog } from '../page';
import { fetchExample } from '../gallery';
import { keptSentence, type OpenedText, restoreAutosave, saveGrammarFile, type TextKeeper, type TextOpening } from '../files';
import type { LinkState } from './link-state';
import { linkWithFragment } from './share-button';

/** Where the editor's first text comes from. */
export interface StartingText extends OpenedText {
  from: 'link' | 'autosave' | 'example';
  /** The link's state, when it came from one. */
  state?: SharedState;
}

/** What choosing the first text reads and asks. */
export interface StartingParts {
  store: GrammarStore;
  kept: KeptTexts;
  keeper: TextKeeper;
  notice: Notice;
  /** Asked when the autosaved text cannot be kept before a link replaces it. */
  cannotKeep: QuestionDialog;
}

/** The notice of a link that was refused. */
function refused(notice: Notice, error: string): void {
  notice.show('error', `This link could not be opened: ${error}. The studio opened as usual.`);
}

/**
 * The text the studio opens with: a shared link's (its fragment is then removed from the address,
 * so a reload restores the user's later edits), else the autosaved text, else the example
 * `firstExample`. A link that cannot be opened is said in the notice, and the studio opens as if
 * it had none; so does a link the user declines because their text could not be kept.
 */
export async function startingText(parts: StartingParts, firstExample: string): Promise<StartingText> {
  // The link's reader is not in the first load: a page opened from a link asks for it now, while
  // the core downloads and the autosave is read (the one case it costs a request before the plant).
  if (hasSharedState(location.hash)) loadCodec().catch(() => undefined); // a failure is decodeState's to say
  const saved = await restoreAutosave(parts.store, parts.kept);
  if (hasSharedState(location.hash)) {
    const decoded = await decodeState(location.hash);
    history.replaceState(null, '', linkWithFragment(location, ''));
    if (!decoded.ok) refused(parts.notice, decoded.error);
    else if (await keepBeforeLink(parts, saved?.text, decoded.state.text)) {
      return { text: decoded.state.text, file: '', from: 'link', state: decoded.state };
    }
  }
  if (saved && saved.text.trim() !== '') return { text: saved.text, file: '', from: 'autosave' };
  return { text: await fetchExample(firstExample), file: firstExample, from: 'example' };
}

/**
 * Keeps the autosaved `previous` text before a link's `text` replaces it, and says where in the
 * notice. When nothing can keep it, the user downloads it first or declines the link: false then.
 */
async function keepBeforeLink(parts: StartingParts, previous: string | undefined, text: string): Promise<boolean> {
  const { notice } = parts;
  const kept = previous === undefined || previous === text ? 'safe' : await parts.keeper.keep(previous, 'a shared link');
  if (kept === 'safe') notice.hide();
  else if (kept) notice.show('info', `Opened a shared link. ${keptSentence(kept)}`);
  else if (previous !== undefined && (await askToDownload(parts.cannotKeep, 'the shared link'))) {
    const file = saveGrammarFile(previous);
    notice.show('info', `Opened a shared link. Your previous text was downloaded as ${file}: this browser’s storage could not keep it.`);
  } else {
    notice.show(
      'error',
      'The shared link was not opened, so your text stays as it was: this browser’s storage is full or switched off. Free some space (delete grammars in My grammars) or save your text as a file, then open the link again.',
    );
    return false;
  }
  return true;
}

/** What opening a pasted link goes through. */
export interface PastedLinkParts {
  notice: Notice;
  opening: TextOpening;
  link: LinkState;
  /** Builds the link's plant with its options. */
  buildNow(): void;
}

/**
 * Opens a link pasted into this tab's address bar: its text replaces the editor's (asking first,
 * and keeping the user's text, through TextOpening), then its options, edits and camera apply.
 */
export function openPastedLinks(parts: PastedLinkParts): void {
  window.addEventListener('hashchange', () => {
    if (!hasSharedState(location.hash)) return;
    const fragment = location.hash;
    history.replaceState(null, '', linkWithFragment(location, ''));
    void decodeState(fragment).then(async (decoded) => {
      if (!decoded.ok) return refused(parts.notice, decoded.error);
      const { state } = decoded;
      const tell = (kept: string) => (kept ? parts.notice.show('info', `Opened a shared link. ${kept}`) : parts.notice.hide());
      if (!(await parts.opening.replace(state.text, 'the shared link', 'link', { what: 'a shared link', tell }))) return;
      parts.link.restore(state);
      parts.buildNow();
    });
  });
}
