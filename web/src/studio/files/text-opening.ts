// Opening another text in the editor: an example, a file, a saved grammar, a lesson's grammar, a
// shared link. The text the user started from, if it was an example left unchanged, is pristine;
// anything else is theirs: opening something else asks first, keeps their text (in My grammars, or
// this browser's database), or when nothing can keep it has them download it first; and it stays
// undoable in the editor. Files in other dialects are imported off the page's thread.
import type { StoredGrammar } from '../../share';
import type { GrammarEditor } from '../../editor';
import type { ObjectFile } from '../../core';
import { askToDownload, askToReplace, type Notice, type QuestionDialog } from '../page';
import { fetchExample, type GalleryEntry } from '../gallery';
import { dialectName, saveGrammarFile, type OpenedFile } from './grammar-files';
import { keptSentence, type TextKeeper } from './keeping';

/** What opening a text reads and changes on the page. */
export interface TextOpeningParts {
  editor: GrammarEditor;
  /** The question asked before replacing the user's text (index.html `#confirm-replace`). */
  confirm: QuestionDialog;
  /** The question asked when the user's text cannot be kept before it is replaced (`#cannot-keep`). */
  cannotKeep: QuestionDialog;
  keeper: TextKeeper;
  /** Reads a file the user opened (other dialects imported, in a worker, with Cancel and a time limit). */
  readFile(file: File): Promise<OpenedFile>;
  /** Reads files opened together, called `name` (imported whole in a worker, as `readFile`). */
  readFiles(files: ObjectFile[], name: string): Promise<OpenedFile>;
  notice: Notice;
  /** Forgets what belonged to the text being replaced (its iterations, seed, sliders, projection, framing). */
  forgetText(): void;
  /** Builds the new text, even when it is the text on screen (it is framed again). */
  buildNow(): void;
}

/** The text the editor holds first, and the file it is (an example's name, or ''). */
export interface OpenedText {
  text: string;
  file: string;
}

/**
 * Where a file name says a text came from: a gallery example is its own name (`abop-1.24d.lsys`),
 * others have a kind in front (`file/NAME`, `saved/ID`, `lesson/SLUG/g0`). Examples and the
 * grammars of lessons are ours: left unchanged, they are replaced without asking.
 */
function isExample(file: string): boolean {
  return (file.endsWith('.lsys') && !file.includes('/')) || file.startsWith('lesson/');
}

/** Opens texts over the editor's, asking first when the user's text would be lost. */
export class TextOpening {
  /** The text on screen if it is an example nobody changed (it may be replaced without asking). */
  private pristine: string | undefined;
  private file: string;

  constructor(
    private readonly parts: TextOpeningParts,
    first: OpenedText,
  ) {
    this.pristine = isExample(first.file) ? first.text : undefined;
    this.file = first.file;
  }

  /** The example, file (`file/NAME`) or saved grammar (`saved/ID`) opened last; '' if none. */
  get currentFile(): string {
    return this.file;
  }

  /** The file the text on screen is named after: `untitled` once an example's text was changed (its own title names it, see `figureName`). */
  get namedFile(): string {
    return this.pristine === undefined || this.parts.editor.text() === this.pristine ? this.file : 'untitled';
  }

  /**
   * Replaces the editor's text by `text` (titled `title` in the questions), unless the user's own
   * text would be lost and they choose to keep it; settles whether it was replaced. Their text is
   * kept first, named after `what` replaced it (default: the title, quoted); `tell` is given the
   * sentence that says where ('' when nothing needed keeping) for the notice (default: it says so,
   * or hides the notice).
   */
  async replace(text: string, title: string, file = '', how: ReplaceOptions = {}): Promise<boolean> {
    const { editor, confirm, notice } = this.parts;
    const mine = editor.text();
    const theirs = mine !== this.pristine && mine !== text;
    if (theirs && !(await askToReplace(confirm.dialog, confirm.example, title))) {
      editor.focus();
      return false;
    }
    const kept = theirs ? await this.keep(mine, title, how.what ?? `“${title}”`) : '';
    if (kept === null) {
      editor.focus();
      return false;
    }
    this.parts.forgetText();
    this.pristine = isExample(file) ? text : undefined;
    this.file = file;
    editor.replaceText(text);
    editor.focus();
    this.parts.buildNow();
    (how.tell ?? ((said) => (said ? notice.show('info', `Opened ${title}. ${said}`) : notice.hide())))(kept);
    return true;
  }

  /**
   * Keeps the user's text `mine` before `title` replaces it: the sentence that says where, or
   * null when it could be kept nowhere and the user declined to download it.
   */
  private async keep(mine: string, title: string, what: string): Promise<string | null> {
    const kept = await this.parts.keeper.keep(mine, what);
    if (kept === 'safe') return '';
    if (kept) return keptSentence(kept);
    if (!(await askToDownload(this.parts.cannotKeep, title))) return null;
    return `Your previous text was downloaded as ${saveGrammarFile(mine)}: this browser’s storage could not keep it.`;
  }

  /** Opens a gallery example. */
  openExample(entry: GalleryEntry): void {
    const open = async () => {
      const text = await fetchExample(entry.file);
      await this.replace(text, entry.title, entry.file);
    };
    open().catch((error: unknown) => console.error('Could not open the example:', error));
  }

  /** Opens a grammar saved in My grammars (or kept in this browser's database: `kept/ID`). */
  openSaved(entry: StoredGrammar, key = `saved/${entry.id}`): void {
    void this.replace(entry.text, entry.name, key);
  }

  /** Opens a file: `.lsys` as it is, another dialect imported, its notes in the notice. */
  openFile(file: File): void {
    this.readFile(file).catch((error: unknown) => this.parts.notice.show('error', `Could not open ${file.name}: ${String(error)}`));
  }

  /**
   * Opens files given together (a dropped folder, several files, a `.zip`): a vlab object or an
   * L-Py model imported whole; `name` is what they are called in the notice (the folder's name).
   */
  openFiles(files: { name: string; file: File }[], name: string): void {
    if (files.length === 1 && !/\.zip$/i.test(files[0].name)) return this.openFile(files[0].file);
    const read = async () => {
      const all = await Promise.all(files.map(async (f) => ({ name: f.name, bytes: new Uint8Array(await f.file.arrayBuffer()) })));
      await this.show(await this.parts.readFiles(all, name), name);
    };
    read().catch((error: unknown) => this.parts.notice.show('error', `Could not open ${name}: ${String(error)}`));
  }

  /** Opens the files picked in the file dialog, named after the L-system among them. */
  openPicked(files: File[]): void {
    const main = files.find((f) => /\.(l|lpy|zip)$/i.test(f.name)) ?? files[0];
    const name = files.length === 1 ? main.name : main.name.replace(/\.[^.]*$/, '');
    this.openFiles(files.map((file) => ({ name: file.name, file })), name);
  }

  private async readFile(file: File): Promise<void> {
    await this.show(await this.parts.readFile(file), file.name);
  }

  /** Puts what was opened in the editor and says in the notice what was not translated. */
  private async show(opened: OpenedFile, name: string): Promise<void> {
    const { notice } = this.parts;
    if (!opened.ok) {
      notice.show('error', `Could not open ${name}: ${opened.error}.`);
      return;
    }
    const tell = (kept: string) => {
      const after = kept ? ` ${kept}` : '';
      if (opened.dialect) {
        const what = `Imported ${name} from ${dialectName(opened.dialect)}`;
        const n = opened.notes.length;
        notice.show('info', n === 0 ? `${what}: everything was translated.${after}` : `${what}.${after} Not translated, or only approximately (${n}):`, opened.notes);
      } else if (opened.notes.length > 0 || kept) notice.show('info', `Opened ${name}.${after}`, opened.notes);
      else notice.hide();
    };
    await this.replace(opened.text, name, `file/${name}`, { tell });
  }
}

/** How {@link TextOpening.replace} names the kept text and tells where it went. */
export interface ReplaceOptions {
  /** What replaces the text, in the kept text's name (`Before WHAT: …`); default the title, quoted. */
  what?: string;
  /** Told where the user's text was kept ('' when nothing needed keeping), once the new text is in. */
  tell?: (kept: string) => void;
}
