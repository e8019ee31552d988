// The Help panel (the language reference) loads when first opened (issue 22: the first plant does
// not need it).
import type { HelpPanelElements } from './help-panel';
import { onDemand } from '../../core';

/** Opens the Help panel, loading it first if need be. */
export interface HelpOpener {
  /** Opens the panel at a row of the reference (`referenceAnchor`), or where it was. */
  open(anchor?: string): void;
  /** Loads the panel in the background (a failure is tried again by the first use). */
  preload(): Promise<unknown>;
}

/** The Help panel on `els`, loaded by the first click of its button or the first `open`. */
export function lazyHelp(els: HelpPanelElements): HelpOpener {
  const openFirst = () => opener.open();
  const panel = onDemand(async () => {
    const { HelpPanel } = await import('./help-panel');
    els.opener.removeEventListener('click', openFirst); // the panel listens to its button now
    return new HelpPanel(els);
  });
  const opener: HelpOpener = {
    open: (anchor) => void panel().then((help) => help.open(anchor)).catch((error: unknown) => console.error('Could not open the help:', error)),
    preload: () => panel().catch(() => undefined),
  };
  els.opener.addEventListener('click', openFirst);
  return opener;
}
