// The File menu: open a grammar file (the picker, or Ctrl+O), save the text as a `.lsys` file
// (Ctrl+S), and My grammars.
import { saveGrammarFile } from './grammar-files';
import { closeLikeAMenu } from '../page';

/** The menu and its file picker (see index.html). */
export interface FileMenuElements {
  menu: HTMLDetailsElement;
  openFile: HTMLButtonElement;
  saveFile: HTMLButtonElement;
  openLibrary: HTMLButtonElement;
  /** The hidden `<input type=file>` behind Open. */
  fileInput: HTMLInputElement;
}

/** What the menu's items do. */
export interface FileMenuActions {
  /** Opens the files the user picked (one grammar, or a vlab object's files together). */
  openFiles(files: File[]): void;
  /** The grammar text to save. */
  text(): string;
  /** Opens My grammars. */
  openLibrary(): void;
}

/** Makes the File menu work, with its keys anywhere on the page (before the editor sees them). */
export function installFileMenu(els: FileMenuElements, actions: FileMenuActions): void {
  const pickFile = () => {
    els.menu.open = false;
    els.fileInput.value = '';
    els.fileInput.click();
  };
  const saveAsFile = () => {
    els.menu.open = false;
    saveGrammarFile(actions.text());
  };
  els.openFile.addEventListener('click', pickFile);
  els.fileInput.addEventListener('change', () => {
    const files = Array.from(els.fileInput.files ?? []);
    if (files.length > 0) actions.openFiles(files);
  });
  els.saveFile.addEventListener('click', saveAsFile);
  window.addEventListener(
    'keydown',
    (event) => {
      if (!(event.ctrlKey || event.metaKey) || event.altKey || event.shiftKey || event.repeat) return;
      if (event.code === 'KeyO') pickFile();
      else if (event.code === 'KeyS') saveAsFile();
      else return;
      event.preventDefault();
      event.stopPropagation();
    },
    { capture: true },
  );
  closeLikeAMenu(els.menu);
  els.openLibrary.addEventListener('click', () => {
    els.menu.open = false;
    actions.openLibrary();
  });
}
