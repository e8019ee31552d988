// The studio page: creates the pieces of ./studio, ./editor and ./view and connects them, each
// piece after those it needs (see index.html for the page, ARCHITECTURE.md for the pieces).
import './style.css';
import { registerSW } from 'virtual:pwa-register';
import { coreVersion, initCore, loadVocabulary, type Vocabulary } from './core';
import { createLazyGrammarEditor, type GrammarEditor } from './editor/grammar-text';
import { growthAttributes } from './editor/growth-directives';
import { INITIAL_EXAMPLE } from './studio/files/initial-example';
import { KeptTexts } from './share/kept-texts';
import { GrammarStore } from './share/storage';
import { PlantView } from './view';
import {
  Autosave, LazyBranchEditing, BuildClient, ContextView, DerivationControls, GrowthPanel,
  LazyDerivationView, installLearnPanel, LinkState, LivePreview, Notice, SliderPanel, LazyStagesMode, TextOpening,
  TextKeeper, ViewFollowing, ViewOptions, ViewTools, tubesFor, attachSplitter, browserDatabase, browserStorage, createImportWorker, connectTestHook, createBuildWorker, emptyTestHook, fetchExample,
  figureName, installDrop, onDemand, installInspectorTabs, LayoutModes,
  installFileMenu, installShareButton, installShortcuts, openPastedLinks, readGrammarFile, readObjectFiles, renderShortcutHelp, reportCoreCrashes, showStatus, sidesChoices,
  startingText, studioElements, installAppUpdates, type ShortcutAction, type StudioElements, type StudioTestHook,
} from './studio';


/** `firstLoadDone` is called when what the first plant downloads has arrived (the rest may load then). */
async function startStudio(els: StudioElements, hook: StudioTestHook, firstLoadDone: () => void): Promise<void> {
  showStatus(els.status, { state: 'loading', text: 'Loading…' });
  const notice = new Notice(els.notice);
  // The user's work: localStorage, else (when that is full) IndexedDB; kept before anything replaces it.
  const store = new GrammarStore(browserStorage());
  const kept = new KeptTexts(browserDatabase());
  const keeper = new TextKeeper(store, kept);
  // The page compiles the core and hands it to the build worker (builds run there, imports of
  // opened files in an import worker's, with the importers: core/io.ts); the page's own instance
  // only says the version. The build worker starts at once, and the studio is set up (the view's
  // WebGL context, the panels) while the core still downloads: the first build is asked for as
  // soon as it has arrived (issue 22).
  const starting = { store, kept, keeper, notice, cannotKeep: els.cannotKeep };
  const buildClient = new BuildClient(createBuildWorker);
  buildClient.warmUp();
  const coreStarted = initCore();
  coreStarted.catch(() => undefined); // awaited below, before the first build: a failure is reported there
  const start = await startingText(starting, INITIAL_EXAMPLE);

  const view = new PlantView(els.viewport);
  void view.compileShaders(); // while the core downloads: its first frame then compiles nothing
  const viewOptions = new ViewOptions(sidesChoices(els.viewTools.sides));
  viewOptions.applyShared(start.state?.view); // a link's, before anything follows the options
  const derivation = new DerivationControls(els.derivation, notice);
  const autosave = new Autosave(store, kept, notice);
  // The editor and the pieces around it need each other: they reach it once it is made (below).
  let editor: GrammarEditor | undefined;
  const currentText = () => editor?.text() ?? start.text;
  const contexts = new ContextView(els.contexts, view, () => editor, viewOptions);
  // The derivation, step by step (loaded with its tab): its hover lights up the plant through the context view.
  const derivationView = new LazyDerivationView(els.derivationPanel, {
    preview: (modules, production) => contexts.showPreview(modules, production),
    pick: (module) => contexts.pickModule(module),
    describeProduction: (index) => contexts.describeProduction(index),
    conditionOf: (index) => contexts.conditionOf(index),
  });
  installInspectorTabs(els.inspectorTabs, (tab) => derivationView.setShown(tab === 'tab-derivation'));
  const preview = new LivePreview({
    client: buildClient,
    view,
    status: els.status,
    stop: els.stopBuild,
    problems: els.showProblems,
    staleBadge: els.staleBadge,
    inspectorStale: els.inspectorStale,
    workerReplaced: () => {
      contexts.reload();
      derivationView.reload();
    },
    text: currentText,
    options: () => ({
      iterations: derivation.iterations(),
      seed: derivation.seed(),
      sides: viewOptions.values.sides,
      smoothAll: viewOptions.values.smoothAll,
      // The Lines mode (and `auto` for a flat plant) draws no tubes: they are not meshed.
      tubes: tubesFor(viewOptions.values.render),
    }),
    diagnosticsChanged: () => editor?.refreshDiagnostics(),
    adopt: (result) => {
      contexts.setBuild(result.build, result.inspector, result.source);
      derivationView.setBuild(result.build, result.inspector);
      if (editor) contexts.cursorAt(editor.cursor());
    },
    crashed: reportCoreCrashes(notice),
  });
  const sliders = new SliderPanel(els.sliders, els.constantsCount, els.constantsEmpty, {
    replaceRange: (from, to, insert, history) => editor?.replaceRange(from, to, insert, history),
  });
  // The Help panel (the language reference) loads when first opened (issue 22).
  const openHelpFirst = () => void openHelp();
  const help = onDemand(async () => {
    const { HelpPanel } = await import('./studio/page/help-panel');
    els.help.opener.removeEventListener('click', openHelpFirst); // the panel listens to its button now
    return new HelpPanel(els.help);
  });
  const openHelp = (anchor?: string) => help().then((panel) => panel.open(anchor)).catch((error: unknown) => console.error('Could not open the help:', error));
  els.help.opener.addEventListener('click', openHelpFirst);
  // What reads the text with the language's vocabulary (the sliders, the Growth panel, the
  // iterations line) starts once it has arrived, after the first plant (issue 22, the first load:
  // core/vocabulary.ts); the text is built meanwhile.
  let growth: GrowthPanel | undefined;
  let vocabulary: Vocabulary | undefined;
  const readText = (text: string) => {
    if (!vocabulary) {
      if (vocabularyFailed) void readVocabulary(); // after a failed fetch, each edit tries again
      return;
    }
    sliders.update(text);
    growth?.update(text);
    derivation.textChanged(text);
  };
  // Once: the panels that need the vocabulary. A failed fetch (the network gone between the first
  // plant and it) is logged, the studio goes on without them, and the next edit tries again.
  let vocabularyAsked = false;
  let vocabularyFailed = false;
  const readVocabulary = async () => {
    if (vocabularyAsked) return;
    vocabularyAsked = true;
    vocabularyFailed = false;
    try {
      const arrived = await loadVocabulary();
      vocabulary = arrived;
      growth = new GrowthPanel(
        els.growthRows,
        els.growthCount,
        { text: currentText, replaceRange: (from, to, insert) => editor?.replaceRange(from, to, insert) },
        growthAttributes(arrived),
      );
      readText(currentText());
    } catch (error) {
      vocabularyAsked = false;
      vocabularyFailed = true;
      console.error('Could not load the language vocabulary (sliders, Growth panel):', error);
    }
  };
  // The grammar in a plain textarea until CodeMirror arrives, after the first plant (below).
  const grammarEditor = createLazyGrammarEditor(
    {
      parent: els.editor,
      doc: start.text,
      onChange: (text) => {
        readText(text);
        preview.rebuild();
        autosave.changed(text);
      },
      diagnose: (text) => preview.feed.diagnose(text),
      vocabulary: loadVocabulary,
      onCursor: (pos) => contexts.cursorAt(pos),
      openReference: (anchor) => void openHelp(anchor),
    },
    () => import('./editor/grammar-editor'),
  );
  editor = grammarEditor;
  // The layout for the room: narrow screens, Large for a projector, fullscreen.
  const layout = new LayoutModes(
    els.layout,
    { remeasureEditor: () => grammarEditor.requestMeasure(), largeChanged: (large) => view.setLineScale(large ? 2 : 1) },
    browserStorage(),
  );
  els.stopBuild.addEventListener('click', () => grammarEditor.focus()); // the text stays, to edit on
  els.showProblems.addEventListener('click', () => {
    layout.showPane('grammar'); // on a narrow screen the list is under the text, in the grammar's pane
    grammarEditor.showProblems();
  });

  // Options: the derivation's and the view's; a change of either asks for a build (meshing ones).
  derivation.onChange(() => preview.rebuild());
  const viewTools = new ViewTools(els.viewTools, viewOptions, view);
  viewOptions.onChange((_, changed) => (changed.has('sides') || changed.has('smoothAll') || changed.has('render')) && preview.rebuild());
  // The view follows the plant; Play shows the growth in one frame (or frames every step).
  const following = new ViewFollowing(els.following, view, () => preview.lastGood);
  following.follow(derivation.playback);
  // Stages: the iterations side by side, grown in a worker of their own (loaded when first turned on).
  const stages = new LazyStagesMode(els.stages, {
    shown: () => preview.lastGood,
    createClient: () => new BuildClient(createBuildWorker),
    lighting: () => viewOptions.values.lighting,
    fileName: () => figureName(opening.currentFile, preview.lastGood?.source),
    toggled: (on) => viewTools.pauseForStages(on),
  });
  viewOptions.onChange((values, changed) => changed.has('lighting') && stages.setLighting(values.lighting));
  preview.onDelivered((result) => {
    following.delivered(result);
    stages.delivered(result);
    derivation.buildShown(result.build);
    viewTools.showProjection();
  });

  // Opening other texts: examples, files (picker, Ctrl+O, drop), saved grammars, links.
  const opening = new TextOpening(
    {
      editor: grammarEditor,
      confirm: els.confirm,
      cannotKeep: els.cannotKeep,
      keeper,
      readFile: (file) => readGrammarFile(file, { createWorker: createImportWorker, notice }),
      readFiles: (files, name) => readObjectFiles(files, name, { createWorker: createImportWorker, notice }),
      notice,
      forgetText: () => {
        derivation.clear();
        sliders.reset();
        viewOptions.set({ projection: 'auto', render: 'auto' });
        view.frameNextPlant();
      },
      buildNow: () => preview.rebuild(true),
    },
    start,
  );
  // The gallery and My grammars load when first opened (issue 22: the first plant needs neither).
  const gallery = onDemand(async () => {
    const [{ GalleryDialog }, { GalleryThumbnails }] = await Promise.all([import('./studio/gallery/gallery-dialog'), import('./studio/gallery/thumbnails')]);
    return new GalleryDialog(els.gallery, els.galleryList, new GalleryThumbnails(fetchExample), (entry) => opening.openExample(entry), () => opening.currentFile);
  });
  const openGallery = () => void gallery().then((dialog) => dialog.open()).catch((error: unknown) => console.error('Could not open the gallery:', error));
  els.openGallery.addEventListener('click', openGallery);
  installLearnPanel({ preview, open: (text, title, key) => opening.replace(text, title, key) }); // lessons (issue 17), loaded on first use
  if (start.from === 'link') void autosave.save(start.text); // the link's text is now the work in progress
  const library = onDemand(async () => {
    const { LibraryDialog } = await import('./studio/files/library-dialog');
    return new LibraryDialog(els.library, store, kept, { text: () => grammarEditor.text(), open: (entry, key) => opening.openSaved(entry, key) });
  });
  const openLibrary = () => void library().then((dialog) => dialog.open()).catch((error: unknown) => console.error('Could not open My grammars:', error));
  installFileMenu(els.fileMenu, { openFiles: (files) => opening.openPicked(files), text: () => grammarEditor.text(), openLibrary });
  installDrop(els.studio, (files, name) => opening.openFiles(files, name));

  // Branch editing (issue 8): the plant on screen with its edits, handles in Edit mode (loaded on first use).
  const branchEdits = new LazyBranchEditing(els.branchEditing, view, {
    shown: () => {
      const good = preview.lastGood;
      return good && { source: good.source, options: good.options, segments: good.build.stats.segments, flat: good.build.flat };
    },
    tell: (kind, message, items) => (message === null ? notice.hide() : notice.show(kind, message, items)),
    modeChanged: (on) => {
      following.editing(on);
      viewTools.showProjection();
      contexts.picking = !on;
      if (on) contexts.pickModule(null);
    },
  });

  // Share links: the whole state in the link's fragment; the page's own link, and pasted ones.
  const link = new LinkState({ editor: grammarEditor, derivation, sliders, viewOptions, view, branchEdits, preview });
  if (start.state) link.restore(start.state); // iterations, seed, edits, camera (its view options apply already)
  // The Share dialog and its embed snippets load with the first share (issue 22).
  const shareDialog = onDemand(async () => {
    const [{ ShareDialog }, { EmbedSnippets }] = await Promise.all([import('./studio/links/share-dialog'), import('./studio/links/embed-snippets')]);
    return { dialog: new ShareDialog(els.shareDialog), snippets: new EmbedSnippets(els.embedSnippets, new URL('./', location.href).href) };
  });
  installShareButton(
    els.share,
    () => shareDialog().then((made) => made.dialog),
    () => link.capture(),
    notice,
    (state, fragment) => void shareDialog().then((made) => made.snippets.show(state, fragment)),
  );
  openPastedLinks({ notice, opening, link, buildNow: () => preview.rebuild(true) });

  preview.onDelivered((result) => {
    if (result.build.ok) branchEdits.plantShown();
  });
  connectTestHook(hook, { preview, view, branchEdits });


  // Keyboard: shortcuts anywhere, their help, the splitter.
  const actions: Record<ShortcutAction, () => void> = {
    stepBack: () => derivation.playback.stepBy(-1),
    stepForward: () => derivation.playback.stepBy(+1),
    playPause: () => derivation.playback.toggle(),
    reroll: () => derivation.reroll(),
    gallery: openGallery,
    frame: () => view.frame(),
    projection: () => viewTools.toggleProjection(),
    stages: () => (stages.open ? stages.close() : stages.show()),
    fullscreen: () => layout.toggleViewOnly(),
    large: () => layout.setLarge(!layout.large),
    help: () => void openHelp(),
  };
  installShortcuts(window, (action) => actions[action]());
  renderShortcutHelp(els.shortcutList);
  attachSplitter(els.splitter, els.studio);

  await coreStarted;
  els.version.textContent = `core ${coreVersion()}`;
  const firstBuild = preview.nextDelivery();
  const underWay = preview.nextProgress();
  preview.rebuild();
  // The editor (issue 22, the first load) loads after the first plant's frame; or, when that build
  // takes long (or is stopped), a second after the worker started it: every download of the first
  // plant is done by then. The studio is ready with the plant and the editor.
  await Promise.race([firstBuild, underWay.then(() => delay(1000))]);
  await nextFrame();
  firstLoadDone();
  const vocabularyRead = readVocabulary();
  // Downloads: the plant on screen (the last good build's text and options, with the edits); the
  // menu's code loads after the first plant (issue 22).
  const downloadsInstalled = import('./studio/downloads/download-menu').then(({ installDownloads }) =>
    installDownloads(els.downloads, view, () => {
      const good = preview.lastGood;
      return good && { source: good.source, options: { ...good.options, edits: branchEdits.document() }, name: figureName(opening.currentFile, good.source) };
    }),
  );
  const editorLoaded = grammarEditor.loaded;
  await firstBuild;
  await vocabularyRead;
  await editorLoaded;
  await view.controlsReady; // the mouse moves the camera (the OrbitControls load after the first plant's frame)
  await downloadsInstalled;
  // The first load is done: the build worker loads the studio core (crate/pkg, built for speed:
  // a big plant's tubes in about half the time) for the builds after it.
  buildClient.useStudioCore();
  // The dialogs and branch editing load now, in the background, so that the first click opens one
  // at once (a failure here is tried again by that click).
  await Promise.all([...[gallery(), library(), shareDialog(), help()].map((made) => made.catch(() => undefined)), branchEdits.preload()]);
}

/** Settles after `ms` milliseconds. */
function delay(ms: number): Promise<void> {
  return new Promise((resolve) => setTimeout(resolve, ms));
}

/** Settles after the next frame is drawn, or after 200 ms in a page that draws none (hidden). */
function nextFrame(): Promise<void> {
  return new Promise((resolve) => {
    requestAnimationFrame(() => setTimeout(resolve));
    setTimeout(resolve, 200);
  });
}

const els = studioElements();
const hook = emptyTestHook();
let firstLoadDone!: () => void;
const firstLoad = new Promise<void>((resolve) => (firstLoadDone = resolve));
hook.ready = startStudio(els, hook, firstLoadDone);
hook.ready.catch((error: unknown) => {
  console.error('Meristem could not start:', error);
  showStatus(els.status, { state: 'crashed', text: `Could not start: ${String(error)}` });
});
window.__meristem = hook;
// Offline use, and "a new version is ready" (issue 22): registered once the first plant's downloads
// are done (or the studio could not start), so the service worker's precaching (the whole site, a
// few MB) never competes with them.
hook.ready.catch(() => firstLoadDone());
void firstLoad.then(() => installAppUpdates(registerSW));
