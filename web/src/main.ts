// The studio page: wires the grammar editor, the build worker, the 3D view, the context-sensitivity
// view, the downloads and the controls around them (see index.html). The logic lives in ./studio,
// ./editor and ./view; this file only connects the pieces.
import './style.css';
import {
  coreVersion,
  grammarDirectives,
  initCore,
  turtleCommands,
  type BuildOptions,
  type EditsDocument,
} from './core';
import { createGrammarEditor, type GrammarEditor } from './editor';
import { decodeState, encodeState, hasSharedState, type SharedState } from './share/codec';
import { GrammarStore, titleOf } from './share/storage';
import { PlantView } from './view';
import {
  BranchEditSession,
  BuildClient,
  ContextView,
  DerivationControls,
  GalleryDialog,
  GalleryThumbnails,
  GrowthPanel,
  LivePreview,
  SliderPanel,
  askToReplace,
  attachSplitter,
  browserStorage,
  closeLikeAMenu,
  connectTestHook,
  createBuildWorker,
  emptyTestHook,
  fetchExample,
  installDownloads,
  installDrop,
  installShortcuts,
  LibraryDialog,
  linkWithFragment,
  lsysFileName,
  Notice,
  openGrammarBytes,
  dialectName,
  ShareDialog,
  renderShortcutHelp,
  saveFile,
  showStatus,
  sidesChoices,
  studioElements,
  ViewOptions,
  ViewTools,
  type GalleryEntry,
  type ShortcutAction,
  type StudioElements,
  type StudioTestHook,
} from './studio';

/** The example shown at start (in public/examples). */
const INITIAL_EXAMPLE = 'abop-1.24d.lsys';

async function startStudio(els: StudioElements, hook: StudioTestHook): Promise<void> {
  showStatus(els.status, { state: 'loading', text: 'Loading…' });
  const notice = new Notice(els.notice);
  const store = new GrammarStore(browserStorage());
  // The page's own core instance serves the tables (commands, directives, version) and the
  // importers of opened files; builds run in the worker's.
  const [start] = await Promise.all([startingText(store, notice), initCore()]);
  const source = start.text;
  els.version.textContent = `core ${coreVersion()}`;

  const view = new PlantView(els.viewport);
  const viewOptions = new ViewOptions(sidesChoices(els.viewTools.sides));
  viewOptions.applyShared(start.state?.view); // a link's, before anything follows the options
  const derivation = new DerivationControls(els.derivation);
  const options = (): BuildOptions => ({
    iterations: derivation.iterations(),
    seed: derivation.seed(),
    sides: viewOptions.values.sides,
    smoothAll: viewOptions.values.smoothAll,
  });
  let editor: GrammarEditor | undefined;
  /** Set once autosave is ready (below); the editor calls it on every change. */
  let autosaveOnChange = () => {};
  /** Set once branch editing is ready (below): the edits for downloads and links, and a link's. */
  let editsForExport: () => EditsDocument | undefined = () => undefined;
  let editsForLink: () => EditsDocument | undefined = () => undefined;
  let restoreEdits: (doc: EditsDocument) => void = () => {};
  // The context-sensitivity view: the cursor on a production lights up what it wrote.
  const contexts = new ContextView(els.contexts, view, () => editor, viewOptions);
  const preview = new LivePreview({
    client: new BuildClient(createBuildWorker),
    view,
    status: els.status,
    staleBadge: els.staleBadge,
    text: () => editor?.text() ?? source,
    options,
    diagnosticsChanged: () => editor?.refreshDiagnostics(),
    adopt: (result) => {
      contexts.setBuild(result.build, result.inspector, result.source);
      if (editor) contexts.cursorAt(editor.view.state.selection.main.head);
    },
  });
  const sliders = new SliderPanel(els.sliders, els.constantsCount, els.constantsEmpty, {
    replaceRange: (from, to, insert, history) => editor?.replaceRange(from, to, insert, history),
  });
  const growth = new GrowthPanel(els.growthRows, els.growthCount, {
    text: () => editor?.text() ?? source,
    replaceRange: (from, to, insert) => editor?.replaceRange(from, to, insert),
  });
  editor = createGrammarEditor({
    parent: els.editor,
    doc: source,
    onChange: (text) => {
      sliders.update(text);
      growth.update(text);
      preview.rebuild();
      autosaveOnChange();
    },
    diagnose: (text) => preview.feed.diagnose(text),
    commands: turtleCommands(),
    directives: grammarDirectives(),
    onCursor: (pos) => contexts.cursorAt(pos),
  });
  const grammarEditor = editor;
  sliders.update(source);
  growth.update(source);

  // Options: the derivation's and the view's; a change of either asks for a build (meshing ones).
  derivation.onChange(() => preview.rebuild());
  const viewTools = new ViewTools(els.viewTools, viewOptions, view);
  viewOptions.onChange((_, changed) => (changed.has('sides') || changed.has('smoothAll')) && preview.rebuild());
  preview.onDelivered((result) => {
    derivation.buildShown(result.build.grammarIterations);
    viewTools.showProjection();
  });
  // Opening another text (an example, a file, a saved grammar, a shared link). The text the user
  // started from, if it was an example left unchanged, is `pristine`; anything else is theirs, and
  // opening something else asks first (and stays undoable in the editor).
  let pristine: string | undefined = start.from === 'example' ? source : undefined;
  let currentFile = start.from === 'example' ? INITIAL_EXAMPLE : '';
  const replaceText = async (text: string, title: string, file = ''): Promise<boolean> => {
    const mine = grammarEditor.text();
    if (mine !== pristine && mine !== text && !(await askToReplace(els.confirm.dialog, els.confirm.example, title))) {
      grammarEditor.view.focus();
      return false;
    }
    derivation.clear();
    sliders.reset();
    viewOptions.set({ projection: 'auto' });
    view.frameNextPlant();
    pristine = file.endsWith('.lsys') && currentIsExample(file) ? text : undefined;
    currentFile = file;
    grammarEditor.replaceText(text);
    grammarEditor.view.focus();
    preview.rebuild(true);
    return true;
  };
  const currentIsExample = (file: string) => file !== '' && !file.includes('/');
  const openExample = async (entry: GalleryEntry) => {
    const text = await fetchExample(entry.file);
    if (await replaceText(text, entry.title, entry.file)) notice.hide();
  };
  const gallery = new GalleryDialog(
    els.gallery,
    els.galleryList,
    new GalleryThumbnails(fetchExample),
    (entry) => void openExample(entry).catch((error: unknown) => console.error('Could not open the example:', error)),
    () => currentFile,
  );
  const openGallery = () => void gallery.open().catch((error: unknown) => console.error('Could not open the gallery:', error));
  els.openGallery.addEventListener('click', openGallery);

  // Autosave: every change, shortly after typing stops, and when the page goes away.
  let autosaveTimer: ReturnType<typeof setTimeout> | undefined;
  let autosaveFailed = false;
  const autosaveNow = () => {
    clearTimeout(autosaveTimer);
    autosaveTimer = undefined;
    const ok = store.autosave(grammarEditor.text());
    if (!ok && !autosaveFailed) notice.show('error', 'Your text cannot be saved in this browser (its storage is full or switched off): save it as a file or share it.');
    autosaveFailed = !ok;
  };
  autosaveOnChange = () => {
    clearTimeout(autosaveTimer);
    autosaveTimer = setTimeout(autosaveNow, 300);
  };
  window.addEventListener('pagehide', () => autosaveTimer !== undefined && autosaveNow());
  document.addEventListener('visibilitychange', () => document.visibilityState === 'hidden' && autosaveTimer !== undefined && autosaveNow());
  if (start.from === 'link') autosaveNow(); // the link's text is now the work in progress

  // Files: open (picker, Ctrl+O, drag and drop; other dialects imported with their notes) and save.
  const openFile = async (file: File) => {
    const opened = openGrammarBytes(file.name, new Uint8Array(await file.arrayBuffer()));
    if (!opened.ok) {
      notice.show('error', `Could not open ${file.name}: ${opened.error}.`);
      return;
    }
    if (!(await replaceText(opened.text, file.name, `file/${file.name}`))) return;
    if (opened.dialect) {
      const what = `Imported ${file.name} from ${dialectName(opened.dialect)}`;
      notice.show(
        'info',
        opened.notes.length === 0 ? `${what}: everything was translated.` : `${what}. Not translated, or only approximately (${opened.notes.length}):`,
        opened.notes,
      );
    } else if (opened.notes.length > 0) notice.show('info', `Opened ${file.name}.`, opened.notes);
    else notice.hide();
  };
  const pickFile = () => {
    els.fileMenu.menu.open = false;
    els.fileMenu.fileInput.value = '';
    els.fileMenu.fileInput.click();
  };
  els.fileMenu.openFile.addEventListener('click', pickFile);
  els.fileMenu.fileInput.addEventListener('change', () => {
    const file = els.fileMenu.fileInput.files?.[0];
    if (file) void openFile(file).catch((error: unknown) => notice.show('error', `Could not open ${file.name}: ${String(error)}`));
  });
  const saveAsFile = () => {
    els.fileMenu.menu.open = false;
    const text = grammarEditor.text();
    saveFile(new TextEncoder().encode(text), lsysFileName(titleOf(text)), 'text/plain');
  };
  els.fileMenu.saveFile.addEventListener('click', saveAsFile);
  installDrop(els.studio, (file) => void openFile(file).catch((error: unknown) => notice.show('error', `Could not open ${file.name}: ${String(error)}`)));
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
  closeLikeAMenu(els.fileMenu.menu);

  // My grammars.
  const library = new LibraryDialog(els.library, store, {
    text: () => grammarEditor.text(),
    open: (entry) => void replaceText(entry.text, entry.name, `saved/${entry.id}`).then((done) => done && notice.hide()),
  });
  els.fileMenu.openLibrary.addEventListener('click', () => {
    els.fileMenu.menu.open = false;
    library.open();
  });

  // Share: the whole state in the link's fragment.
  const shareDialog = new ShareDialog(els.shareDialog);
  const sharedState = (): SharedState => {
    const state: SharedState = { text: grammarEditor.text(), ...derivation.toShared() };
    const values = sliders.values();
    if (Object.keys(values).length > 0) state.sliders = values;
    state.view = viewOptions.toShared();
    state.camera = view.cameraPose();
    const edits = editsForLink();
    if (edits) state.edits = edits;
    return state;
  };
  els.share.addEventListener('click', () => {
    void encodeState(sharedState())
      .then((fragment) => shareDialog.open(linkWithFragment(location, fragment)))
      .catch((error: unknown) => notice.show('error', `Could not make a link: ${String(error)}`));
  });
  // A link pasted into this tab's address bar.
  window.addEventListener('hashchange', () => {
    if (!hasSharedState(location.hash)) return;
    if (autosaveTimer !== undefined) autosaveNow(); // the text now is what the link may replace
    void openLink(location.hash, store, notice).then((opened) => {
      history.replaceState(null, '', linkWithFragment(location, ''));
      if (!opened) return;
      void replaceText(opened.state.text, 'the shared link', 'link').then((done) => {
        if (!done) return;
        applyLinkOptions(opened.state);
        if (opened.state.edits) restoreEdits(opened.state.edits);
        if (opened.state.camera) cameraToApply = opened.state.camera;
        preview.rebuild(true);
      });
    });
  });
  // The link's options, before its first build (the camera after it: it needs the plant).
  const applyLinkOptions = (state: SharedState) => {
    derivation.applyShared(state);
    viewOptions.applyShared(state.view);
  };
  let cameraToApply: SharedState['camera'] = undefined;
  preview.onDelivered((result) => {
    if (!cameraToApply || !result.build.ok) return;
    view.setCameraPose({ zoom: 1, ...cameraToApply });
    cameraToApply = undefined;
  });
  if (start.from === 'link' && start.state) {
    applyLinkOptions(start.state);
    cameraToApply = start.state.camera;
  }
  // Branch editing (issue 8): the plant on screen with its edits, handles in Edit mode.
  const branchEdits = new BranchEditSession(els.branchEditing, view, {
    shown: () => {
      const good = preview.lastGood;
      return good && { source: good.source, options: good.options, segments: good.build.stats.segments, flat: good.build.flat };
    },
    tell: (kind, message, items) => (message === null ? notice.hide() : notice.show(kind, message, items)),
    modeChanged: (on) => {
      contexts.picking = !on;
      if (on) contexts.pickModule(null);
    },
  });
  preview.onDelivered((result) => {
    if (result.build.ok) branchEdits.plantShown();
  });
  window.addEventListener('keydown', (event) => {
    // Ctrl+Z over the view undoes branch edits; in the editor and fields it stays theirs.
    const inText = (event.target as HTMLElement | null)?.closest('input, textarea, select, .cm-editor, dialog');
    if (!inText && (branchEdits.active || branchEdits.document()) && branchEdits.handleKey(event)) event.preventDefault();
  });
  if (start.from === 'link' && start.state?.edits) branchEdits.restore(start.state.edits);
  editsForExport = () => branchEdits.document();
  editsForLink = () => branchEdits.document();
  restoreEdits = (doc) => branchEdits.restore(doc);
  connectTestHook(hook, { preview, view, branchEdits });

  // Downloads: the plant on screen (the last good build's text and options), written by the page's
  // own core instance, as a model file or a PNG of the view.
  installDownloads(els.downloads, view, () => preview.lastGood && { source: preview.lastGood.source, options: { ...preview.lastGood.options, edits: editsForExport() } });

  // Keyboard: shortcuts anywhere, their help, the splitter.
  const actions: Record<ShortcutAction, () => void> = {
    stepBack: () => derivation.playback.stepBy(-1),
    stepForward: () => derivation.playback.stepBy(+1),
    playPause: () => derivation.playback.toggle(),
    reroll: () => derivation.reroll(),
    gallery: openGallery,
    frame: () => view.frame(),
    projection: () => viewTools.toggleProjection(),
  };
  installShortcuts(window, (action) => actions[action]());
  renderShortcutHelp(els.shortcutList);
  attachSplitter(els.splitter, els.studio);

  const firstBuild = new Promise<void>((resolve) => {
    const stop = preview.onDelivered(() => {
      stop();
      resolve();
    });
  });
  preview.rebuild();
  await firstBuild;
}

/** Where the editor's first text comes from. */
interface StartingText {
  text: string;
  from: 'link' | 'autosave' | 'example';
  /** The link's state, when it came from one. */
  state?: SharedState;
}

/**
 * The text the studio opens with: a shared link's (its fragment is then removed from the address,
 * so a reload restores the user's later edits), else the autosaved text, else the first example.
 * A link that cannot be opened is said in the notice, and the studio opens as if it had none.
 */
async function startingText(store: GrammarStore, notice: Notice): Promise<StartingText> {
  if (hasSharedState(location.hash)) {
    const opened = await openLink(location.hash, store, notice);
    history.replaceState(null, '', linkWithFragment(location, ''));
    if (opened) return { text: opened.state.text, from: 'link', state: opened.state };
  }
  const saved = store.restore();
  if (saved && saved.text.trim() !== '') return { text: saved.text, from: 'autosave' };
  return { text: await fetchExample(INITIAL_EXAMPLE), from: 'example' };
}

/**
 * Decodes a shared link. A rejected one is said in the notice (and nothing changes). An accepted
 * one first keeps the autosaved work in My grammars, unless it is the link's text or saved there
 * already: opening a link never loses a user's text.
 */
async function openLink(fragment: string, store: GrammarStore, notice: Notice): Promise<{ state: SharedState } | null> {
  const decoded = await decodeState(fragment);
  if (!decoded.ok) {
    notice.show('error', `This link could not be opened: ${decoded.error}. The studio opened as usual.`);
    return null;
  }
  const previous = store.restore();
  if (previous && previous.text.trim() !== '' && previous.text !== decoded.state.text && !store.list().some((g) => g.text === previous.text)) {
    const kept = store.save(`Before a shared link: ${titleOf(previous.text)}`, previous.text);
    notice.show(
      'info',
      kept
        ? `Opened a shared link. Your previous text is kept in My grammars as “${kept.name}”.`
        : 'Opened a shared link. Your previous text could not be kept (this browser’s storage is full): Ctrl+Z in the editor does not reach it.',
    );
  } else notice.hide();
  return { state: decoded.state };
}

const els = studioElements();
const hook = emptyTestHook();
hook.ready = startStudio(els, hook);
hook.ready.catch((error: unknown) => {
  console.error('Meristem could not start:', error);
  showStatus(els.status, { state: 'crashed', text: `Could not start: ${String(error)}` });
});
window.__meristem = hook;
