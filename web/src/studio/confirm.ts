// The question asked before an example replaces text the user changed.

/**
 * Shows the confirm dialog (index.html `#confirm-replace`) naming the example `title`; settles
 * true when the user chose to replace, false on "Keep my text", Escape or closing.
 */
export function askToReplace(dialog: HTMLDialogElement, exampleSlot: HTMLElement, title: string): Promise<boolean> {
  exampleSlot.textContent = title;
  dialog.returnValue = '';
  return new Promise((resolve) => {
    dialog.addEventListener('close', () => resolve(dialog.returnValue === 'replace'), { once: true });
    dialog.showModal();
  });
}
