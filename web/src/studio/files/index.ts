// Files and the user's work: opening texts (examples, files, saved grammars), importing other
// dialects in a worker, autosave and keeping the text before it is replaced, the browser's storage.
// library-dialog is not re-exported: it loads when first opened (wire-files.ts).
export { browserKeeping, createOpening, wireFiles } from './wire-files';
export { Autosave } from './autosave';
export { browserStorage } from './browser-storage';
export { INITIAL_EXAMPLE } from './initial-example';
export { keptSentence, restoreAutosave, type TextKeeper } from './keeping';
export type { OpenedText, TextOpening } from './text-opening';
export { saveGrammarFile } from './grammar-files';
export { figureName, saveFile } from './save-file';
