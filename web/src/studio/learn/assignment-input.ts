// The hidden file input behind "Open an assignment file…" (the Learn panel's list and the
// assignment panel): a Markdown or text file, handed on once picked.

/** A hidden input that hands the file picked to `open` (its `click()` opens the browser's dialog). */
export function assignmentFileInput(testid: string, open: (file: File) => void): HTMLInputElement {
  const input = document.createElement('input');
  input.type = 'file';
  input.accept = '.md,.markdown,.txt,text/markdown,text/plain';
  input.hidden = true;
  input.dataset.testid = testid;
  input.addEventListener('change', () => {
    const file = input.files?.[0];
    input.value = '';
    if (file) open(file);
  });
  return input;
}
