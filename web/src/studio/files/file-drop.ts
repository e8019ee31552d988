// Opening a grammar file, several files or a folder (a vlab object) by dropping it on the page.

/** A dropped file with its path inside the dropped folder (its own name when none). */
export interface DroppedFile {
  name: string;
  file: File;
}

/** How deep a dropped folder is read (a vlab object keeps its files at its top). */
const MAX_DEPTH = 2;

/** The files of a dropped entry: a file, or a folder's files down to {@link MAX_DEPTH}. */
async function entryFiles(entry: FileSystemEntry, path: string, depth: number): Promise<DroppedFile[]> {
  if (entry.isFile) {
    const file = await new Promise<File>((resolve, reject) => (entry as FileSystemFileEntry).file(resolve, reject));
    return [{ name: path + entry.name, file }];
  }
  if (!entry.isDirectory || depth >= MAX_DEPTH) return [];
  const reader = (entry as FileSystemDirectoryEntry).createReader();
  const children: FileSystemEntry[] = [];
  // readEntries gives the entries in batches until an empty one.
  for (;;) {
    const batch = await new Promise<FileSystemEntry[]>((resolve, reject) => reader.readEntries(resolve, reject));
    if (batch.length === 0) break;
    children.push(...batch);
  }
  const nested = await Promise.all(children.map((child) => entryFiles(child, `${path}${entry.name}/`, depth + 1)));
  return nested.flat();
}

/** What was dropped: its files, and a name for them (the file's, or the folder's). */
async function droppedFiles(data: DataTransfer): Promise<{ files: DroppedFile[]; name: string }> {
  const entries = Array.from(data.items)
    .map((item) => item.webkitGetAsEntry?.())
    .filter((entry): entry is FileSystemEntry => entry != null);
  if (entries.length === 0) {
    const files = Array.from(data.files).map((file) => ({ name: file.name, file }));
    return { files, name: files[0]?.name ?? '' };
  }
  const files = (await Promise.all(entries.map((entry) => entryFiles(entry, '', 0)))).flat();
  return { files, name: entries[0].name };
}

/**
 * Files dropped anywhere on `target` open with `open` (before the editor can insert them as
 * text): one file, several files, or a folder's files, with the name to show for them.
 */
export function installDrop(target: HTMLElement, open: (files: DroppedFile[], name: string) => void): void {
  const hasFiles = (event: DragEvent) => event.dataTransfer?.types.includes('Files') ?? false;
  let depth = 0;
  const leave = () => {
    depth = 0;
    target.classList.remove('drop-target');
  };
  target.addEventListener('dragenter', (event) => {
    if (!hasFiles(event)) return;
    event.preventDefault();
    depth++;
    target.classList.add('drop-target');
  });
  target.addEventListener('dragover', (event) => {
    if (!hasFiles(event)) return;
    event.preventDefault();
    event.dataTransfer!.dropEffect = 'copy';
  });
  target.addEventListener('dragleave', (event) => {
    if (!hasFiles(event)) return;
    depth = Math.max(0, depth - 1);
    if (depth === 0) leave();
  });
  target.addEventListener(
    'drop',
    (event) => {
      if (!hasFiles(event)) return;
      event.preventDefault();
      event.stopPropagation();
      leave();
      if (!event.dataTransfer) return;
      // The items must be read before the drop event returns; their files after.
      droppedFiles(event.dataTransfer)
        .then(({ files, name }) => files.length > 0 && open(files, name))
        .catch((error: unknown) => console.error('Could not read what was dropped:', error));
    },
    { capture: true },
  );
}
