// Saving a file from the page: the name a grammar's files are saved under, and handing the bytes
// to the browser as a download. Small and on its own: File > Save needs it with the first plant,
// the Download menu and Stages after it.

/** Words of a title that name no figure in particular (`ABOP Fig. 1.24d` is saved as `abop-1.24d`). */
const FIGURE_WORDS = /^(fig\.?|figure)$/i;

/**
 * The name files of a grammar are saved under: its title (the first line of its opening `//`
 * comment, up to a colon: `// ABOP Fig 1.24d: …` gives `abop-1.24d`, `// Barnsley fern` gives
 * `barnsley-fern`), else the name of the file it was opened as (an example, `file/NAME`; not a
 * saved grammar's `saved/ID`), else `plant`.
 */
export function figureName(file: string, source = ''): string {
  const title = /^\s*\/\/(.*)/.exec(source)?.[1].split(':')[0] ?? '';
  const words = title.split(/\s+/).filter((w) => w !== '' && !FIGURE_WORDS.test(w));
  const fromTitle = slug(words.join('-')).slice(0, 48).replace(/-+$/, '');
  if (fromTitle !== '') return fromTitle;
  const name = slug(file.replace(/^(file|saved)\//, '').replace(/\.[A-Za-z0-9]+$/, ''));
  return name === '' || file.startsWith('saved/') ? 'plant' : name;
}

/** Lower case, runs of anything but letters, digits, `.` and `_` as one `-`, none at the ends. */
function slug(text: string): string {
  return text
    .toLowerCase()
    .replace(/[^\p{L}\p{N}._]+/gu, '-')
    .replace(/^[-.]+|[-.]+$/g, '');
}

/** Hands `data` to the browser as a download named `fileName`. */
export function saveFile(data: Blob | Uint8Array, fileName: string, mimeType: string): void {
  const blob = data instanceof Blob ? data : new Blob([data.slice().buffer as ArrayBuffer], { type: mimeType });
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  link.hidden = true;
  document.body.append(link);
  link.click();
  link.remove();
  // The download has started from the URL by now; a minute is generous before letting it go.
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
}
