// The questions asked before the user's text is replaced: whether to replace it at all, and, when
// this browser cannot keep it anywhere, whether to download it first.

/** A question dialog (index.html) and the slot in it that names what would replace the text. */
export interface QuestionDialog {
  dialog: HTMLDialogElement;
  /** Where the title of what would be opened is written. */
  example: HTMLElement;
}

/**
 * Shows `question` naming `title`; settles true when the user chose the button of value `yes`,
 * false on the other button, Escape or closing.
 */
function ask(question: QuestionDialog, title: string, yes: string): Promise<boolean> {
  const { dialog, example } = question;
  example.textContent = title;
  dialog.returnValue = '';
  return new Promise((resolve) => {
    dialog.addEventListener('close', () => resolve(dialog.returnValue === yes), { once: true });
    dialog.showModal();
  });
}

/**
 * Shows the confirm dialog (index.html `#confirm-replace`) naming the example `title`; settles
 * true when the user chose to replace, false on "Keep my text", Escape or closing.
 */
export function askToReplace(dialog: HTMLDialogElement, exampleSlot: HTMLElement, title: string): Promise<boolean> {
  return ask({ dialog, example: exampleSlot }, title, 'replace');
}

/**
 * Says that the user's text cannot be kept in this browser before `title` replaces it (index.html
 * `#cannot-keep`); settles true when they chose to download it and open `title`, false when they
 * keep their text (and `title` is not opened).
 */
export function askToDownload(question: QuestionDialog, title: string): Promise<boolean> {
  return ask(question, title, 'download');
}
