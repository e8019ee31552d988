// Opening other texts, wired to the studio's parts: examples, files (the File menu, Ctrl+O, a
// drop), saved grammars (My grammars), each replacing the text through one TextOpening.
import { GrammarStore, KeptTexts } from '../../share';
import { lazyGallery } from '../gallery';
import { lazyDialog, type LazyDialog } from '../page';
import type { KeptWork, StudioParts } from '../parts';
import type { StartingText } from '../links';
import { browserDatabase, browserStorage } from './browser-storage';
import { installDrop } from './file-drop';
import { installFileMenu } from './file-menu';
import { TextKeeper } from './keeping';
import { TextOpening } from './text-opening';

/** The import worker's client, loaded by the first file opened (no first plant opens one). */
const importClient = () => import('./import-client');

/** The user's work in this browser: localStorage, else (when that is full) IndexedDB; kept before anything replaces it. */
export function browserKeeping(): KeptWork {
  const store = new GrammarStore(browserStorage());
  const kept = new KeptTexts(browserDatabase());
  return { store, kept, keeper: new TextKeeper(store, kept) };
}

/** What replaces the text: opening a text forgets what belonged to the one before, and builds the new one. */
export function createOpening(
  parts: Pick<StudioParts, 'els' | 'notice' | 'keeper' | 'editor' | 'derivation' | 'sliders' | 'viewOptions' | 'view' | 'preview' | 'timeline'>,
  start: StartingText,
): TextOpening {
  const { els, notice, derivation, sliders, viewOptions, view, preview, timeline } = parts;
  return new TextOpening(
    {
      editor: parts.editor,
      confirm: els.confirm,
      cannotKeep: els.cannotKeep,
      keeper: parts.keeper,
      readFile: async (file) => {
        const { readGrammarFile, createImportWorker } = await importClient();
        return readGrammarFile(file, { createWorker: createImportWorker, notice, limitMs: window.__meristem?.importTimeLimitMs });
      },
      readFiles: async (files, name) => {
        const { readObjectFiles, createImportWorker } = await importClient();
        return readObjectFiles(files, name, { createWorker: createImportWorker, notice, limitMs: window.__meristem?.importTimeLimitMs });
      },
      notice,
      forgetText: () => {
        derivation.clear();
        timeline.clear();
        sliders.reset();
        viewOptions.set({ projection: 'auto', render: 'auto' });
        view.frameNextPlant();
      },
      buildNow: () => preview.rebuild({ force: true }),
    },
    start,
  );
}

/** The dialogs that open texts; they load when first opened (issue 22: the first plant needs neither). */
export interface OpeningDialogs {
  gallery: LazyDialog;
  library: LazyDialog;
}

/** Connects the gallery, My grammars, the File menu and drops to the parts' TextOpening. */
export function wireFiles({ els, opening, store, kept, editor }: StudioParts): OpeningDialogs {
  const gallery = lazyGallery(els, opening);
  els.openGallery.addEventListener('click', () => gallery.open());
  const library = lazyDialog('My grammars', async () => {
    const { LibraryDialog } = await import('./library-dialog');
    return new LibraryDialog(els.library, store, kept, { text: () => editor.text(), open: (entry, key) => opening.openSaved(entry, key) });
  });
  installFileMenu(els.fileMenu, { openFiles: (files) => opening.openPicked(files), text: () => editor.text(), openLibrary: () => library.open() });
  installDrop(els.studio, (files, name) => opening.openFiles(files, name));
  return { gallery, library };
}
