// The studio page's own logic: building in a worker on edit, the status line, the panels and
// controls around the editor and the view, the context-sensitivity view, downloads, and the page
// around them (its elements, opening texts and links, autosave, the menus, the test hook).
export { reportBuilding, reportPlant, reportErrors, plural, millis, type StatusReport } from './status';
export { BuildClient, createBuildWorker, type BuildOutcome, type BuildResult, type WorkerLike } from './worker-client';
export { transferablesOf, type BuildRequest, type BuildResponse } from './worker-protocol';
export { DiagnosticsFeed } from './diagnostics-feed';
export { BUILDING_AFTER, LivePreview, showStatus, type LivePreviewParts } from './live-preview';
export { SliderPanel, sliderRanges, type SliderRange, type SliderEditor } from './sliders';
export { Playback, type PlaybackHost, type PlaybackOptions } from './playback';
export { attachSplitter, clampShare, shareAfterKey } from './splitter';
export { installShortcuts, renderShortcutHelp, shortcutFor, SHORTCUTS, type Shortcut, type ShortcutAction } from './shortcuts';
export { fetchExample, fetchManifest } from './gallery';
// gallery-dialog and library-dialog are not re-exported: main.ts loads them when first opened.
export { galleryManifest, parseExampleHeader, isGalleryManifest, type GalleryEntry } from './gallery-manifest';
export { ABOP_CHAPTERS, abopChapterHeading } from './chapters';
export type { LearnElements, LearnHost } from './learn-panel'; // the panel itself loads on first use (learn-loader.ts)
export { installLearnPanel } from './learn-loader';
export { chapterHeading, compareLessons, isLesson, isLessonIndex, type Lesson, type LessonGrammar, type LessonSummary, type LessonTask } from './lesson-manifest';
export { CHECK_FACTS, CHECK_FUNCTIONS, evaluateCheck, needsDerivedString, parseCheck, plantFacts, spokenAnswer, MAX_CHECKED_MODULES, type CheckAnswer, type CheckNode, type PlantFacts } from './lesson-check';
export { askToDownload, askToReplace, type QuestionDialog } from './confirm';
export { ContextView, type ContextViewElements } from './context-view';
export { LazyDerivationView } from './derivation-loader';
// derivation-view (the Derivation tab) is not re-exported: it loads with the tab (derivation-loader).
export { countsInWords, describeProduction, madeInWords, reportInWords, lineOf } from './explain-words';
export { installInspectorTabs } from './inspector-tabs';
export { LayoutModes, type LayoutElements, type LayoutHost } from './layout-modes';
export { afterPaint, figureName, fileSize, pictureSize, saveFile, PICTURE_MAX, PICTURE_MIN, type PictureSize } from './downloads';
export { createExportWorker, describeProgress, runExport, type ExportOutcome, type ExportRequest, type ExportResponse, type RunningExport } from './export-client';
export { Notice, type NoticeElements, type NoticeKind } from './notice';
export type { EmbedSnippetElements, SnippetControls } from './embed-snippets';
export { installShareButton, linkWithFragment } from './share-button';
// share-dialog and embed-snippets are not re-exported: main.ts loads them with the first share.
export type { ShareDialogElements } from './share-dialog';
export type { LibraryElements, LibraryHost } from './library-dialog';
export { checkGrammarBytes, openGrammarBytes, saveGrammarFile, decodeText, dialectName, lsysFileName, MAX_FILE_BYTES, type OpenedFile } from './grammar-files';
// branch-editing is not re-exported as code: the studio loads it on first use (branch-editing-loader).
export type { BranchEditSession, BranchEditingElements, BranchEditingHost } from './branch-editing';
export { LazyBranchEditing, type BranchEdits } from './branch-editing-loader';
export { onDemand } from './on-demand';
export { GrowthPanel, type GrowthEditor } from './growth-panel';
export { byId, studioElements, type StudioElements } from './page-elements';
export { ViewOptions, DEFAULT_VIEW_OPTIONS, tubesFor, type SharedViewOptions, type ViewOption, type ViewOptionValues, type ViewOptionsListener } from './view-options';
export { ViewTools, sidesChoices, type ViewToolElements } from './view-tools';
// stages (the Stages mode) is not re-exported: it loads when first turned on (stages-loader).
export { LazyStagesMode } from './stages-loader';
export type { StagesElements, StagesHost } from './stages';
export { stagesSvg, parseStageSvg, type StageDrawing } from './stages-svg';
export { ViewFollowing, growthKey, isLastStep, type PlayFraming, type ViewFollowingElements } from './view-following';
export { DerivationControls, type DerivationElements, type SharedDerivation } from './derivation-controls';
export { TextOpening, type OpenedText, type TextOpeningParts } from './text-opening';
export { openPastedLinks, startingText, type PastedLinkParts, type StartingParts, type StartingText } from './link-opening';
export { TextKeeper, keptSentence, restoreAutosave, type KeptPlace, type Keeping } from './keeping';
export { createImportWorker, readGrammarFile, readObjectFiles, runImport, IMPORT_TIME_LIMIT, type ImportOutcome, type ImportRequest, type ImportResponse } from './import-client';
export { runWorkerJob, type JobWorkerLike, type WorkerJob } from './worker-job';
export { LinkState, type LinkStateParts } from './link-state';
export { Autosave, AUTOSAVE_DELAY } from './autosave';
export { browserDatabase, browserStorage } from './browser-storage';
export { installFileMenu, type FileMenuActions, type FileMenuElements } from './file-menu';
export { installDrop } from './file-drop';
export { closeLikeAMenu } from './menus';
// download-menu is not re-exported: main.ts loads it after the first plant.
export type { DownloadedPlant, DownloadMenuElements, ExportState } from './download-menu';
export { connectTestHook, emptyTestHook, type StudioTestHook, type TestedStudio } from './test-hook';
export { reportCoreCrashes } from './core-crashes';
export { installAppUpdates, type RegisterServiceWorker } from './app-update';
// help-panel is not re-exported: main.ts loads it when the Help panel is first opened.
export type { HelpPanelElements } from './help-panel';
