// Share links, wired to the studio's parts: the whole state in the link's fragment; the page's own
// link (the Share button, its dialog and embed snippets), and links pasted into the address bar.
import type { BranchEdits } from '../branches';
import { onDemand } from '../page';
import type { StudioParts } from '../parts';
import { openPastedLinks, type StartingText } from './link-opening';
import { LinkState } from './link-state';
import { installShareButton } from './share-button';
import type { LazyVariants } from '../variants';

/** Restores the link the studio opened with (if any), and connects the Share button and pasted links. */
export function wireLinks(parts: StudioParts, branchEdits: BranchEdits, start: StartingText, variants: LazyVariants): { preload(): Promise<unknown> } {
  const { els, editor, derivation, sliders, viewOptions, view, preview, notice, opening, timeline } = parts;
  const link = new LinkState({ editor, derivation, sliders, viewOptions, view, branchEdits, preview, timeline, variants });
  if (start.state) link.restore(start.state); // iterations, seed, edits, camera, timeline (its view options apply already)
  // The Share dialog and its embed snippets load with the first share (issue 22).
  const shareDialog = onDemand(async () => {
    const [{ ShareDialog }, { EmbedSnippets }] = await Promise.all([import('./share-dialog'), import('./embed-snippets')]);
    return { dialog: new ShareDialog(els.shareDialog), snippets: new EmbedSnippets(els.embedSnippets, new URL('./', location.href).href) };
  });
  installShareButton(
    els.share,
    () => shareDialog().then((made) => made.dialog),
    () => link.capture(),
    notice,
    (state, fragment) => void shareDialog().then((made) => made.snippets.show(state, fragment)),
  );
  openPastedLinks({ notice, opening, link, buildNow: () => preview.rebuild({ force: true }) });
  return { preload: () => shareDialog().catch(() => undefined) };
}
