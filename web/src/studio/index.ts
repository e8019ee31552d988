// The studio page's own logic: building in a worker on edit, the status line, the panels and
// controls around the editor and the view, the context-sensitivity view, downloads, and the page
// around them (its elements, opening texts and links, autosave, the menus, the test hook).
export { reportBuilding, reportPlant, reportErrors, plural, millis, type StatusReport } from './preview/status';
export { BuildClient, createBuildWorker, type BuildOutcome, type BuildResult, type WorkerLike } from '../build/worker-client';
export { transferablesOf, type BuildRequest, type BuildResponse } from '../build/worker-protocol';
export { DiagnosticsFeed } from './preview/diagnostics-feed';
export { BUILDING_AFTER, LivePreview, showStatus, type LivePreviewParts } from './preview/live-preview';
export { SliderPanel, sliderRanges, type SliderRange, type SliderEditor } from './controls/sliders';
export { Playback, type PlaybackHost, type PlaybackOptions } from './controls/playback';
export { attachSplitter, clampShare, shareAfterKey } from './controls/splitter';
export { installShortcuts, renderShortcutHelp, shortcutFor, SHORTCUTS, type Shortcut, type ShortcutAction } from './controls/shortcuts';
export { fetchExample, fetchManifest } from './gallery/gallery';
// gallery-dialog and library-dialog are not re-exported: main.ts loads them when first opened.
export { galleryManifest, parseExampleHeader, isGalleryManifest, type GalleryEntry } from './gallery/gallery-manifest';
export { ABOP_CHAPTERS, abopChapterHeading } from './gallery/chapters';
export type { LearnElements, LearnHost } from './learn/learn-panel'; // the panel itself loads on first use (learn-loader.ts)
export { installLearnPanel } from './learn/learn-loader';
export { chapterHeading, compareLessons, isLesson, isLessonIndex, type Lesson, type LessonGrammar, type LessonSummary, type LessonTask } from './learn/lesson-manifest';
export { CHECK_FACTS, CHECK_FUNCTIONS, evaluateCheck, needsDerivedString, parseCheck, plantFacts, spokenAnswer, MAX_CHECKED_MODULES, type CheckAnswer, type CheckNode, type PlantFacts } from './learn/lesson-check';
export { askToDownload, askToReplace, type QuestionDialog } from './page/confirm';
export { ContextView, type ContextViewElements } from './derivation/context-view';
export { LazyDerivationView } from './derivation/derivation-loader';
// derivation-view (the Derivation tab) is not re-exported: it loads with the tab (derivation-loader).
export { countsInWords, describeProduction, madeInWords, reportInWords, lineOf } from './derivation/explain-words';
export { installInspectorTabs } from './derivation/inspector-tabs';
export { LayoutModes, type LayoutElements, type LayoutHost } from './controls/layout-modes';
export { afterPaint, figureName, fileSize, pictureSize, saveFile, PICTURE_MAX, PICTURE_MIN, type PictureSize } from './downloads/downloads';
export { createExportWorker, describeProgress, runExport, type ExportOutcome, type ExportRequest, type ExportResponse, type RunningExport } from './downloads/export-client';
export { Notice, type NoticeElements, type NoticeKind } from './page/notice';
export type { EmbedSnippetElements, SnippetControls } from './links/embed-snippets';
export { installShareButton, linkWithFragment } from './links/share-button';
// share-dialog and embed-snippets are not re-exported: main.ts loads them with the first share.
export type { ShareDialogElements } from './links/share-dialog';
export type { LibraryElements, LibraryHost } from './files/library-dialog';
export { checkGrammarBytes, openGrammarBytes, saveGrammarFile, decodeText, dialectName, lsysFileName, MAX_FILE_BYTES, type OpenedFile } from './files/grammar-files';
// branch-editing is not re-exported as code: the studio loads it on first use (branch-editing-loader).
export type { BranchEditSession, BranchEditingElements, BranchEditingHost } from './branches/branch-editing';
export { LazyBranchEditing, type BranchEdits } from './branches/branch-editing-loader';
export { onDemand } from './page/on-demand';
export { GrowthPanel, type GrowthEditor } from './controls/growth-panel';
export { byId, studioElements, type StudioElements } from './page/page-elements';
export { ViewOptions, DEFAULT_VIEW_OPTIONS, tubesFor, type SharedViewOptions, type ViewOption, type ViewOptionValues, type ViewOptionsListener } from './controls/view-options';
export { ViewTools, sidesChoices, type ViewToolElements } from './controls/view-tools';
// stages (the Stages mode) is not re-exported: it loads when first turned on (stages-loader).
export { LazyStagesMode } from './stages/stages-loader';
export type { StagesElements, StagesHost } from './stages/stages';
export { stagesSvg, parseStageSvg, type StageDrawing } from './stages/stages-svg';
export { ViewFollowing, growthKey, isLastStep, type PlayFraming, type ViewFollowingElements } from './controls/view-following';
export { DerivationControls, type DerivationElements, type SharedDerivation } from './derivation/derivation-controls';
export { TextOpening, type OpenedText, type TextOpeningParts } from './files/text-opening';
export { openPastedLinks, startingText, type PastedLinkParts, type StartingParts, type StartingText } from './links/link-opening';
export { TextKeeper, keptSentence, restoreAutosave, type KeptPlace, type Keeping } from './files/keeping';
export { createImportWorker, readGrammarFile, readObjectFiles, runImport, IMPORT_TIME_LIMIT, type ImportOutcome, type ImportRequest, type ImportResponse } from './files/import-client';
export { runWorkerJob, type JobWorkerLike, type WorkerJob } from '../build/worker-job';
export { LinkState, type LinkStateParts } from './links/link-state';
export { Autosave, AUTOSAVE_DELAY } from './files/autosave';
export { browserDatabase, browserStorage } from './files/browser-storage';
export { installFileMenu, type FileMenuActions, type FileMenuElements } from './files/file-menu';
export { installDrop } from './files/file-drop';
export { closeLikeAMenu } from './page/menus';
// download-menu is not re-exported: main.ts loads it after the first plant.
export type { DownloadedPlant, DownloadMenuElements, ExportState } from './downloads/download-menu';
export { connectTestHook, emptyTestHook, type StudioTestHook, type TestedStudio } from './page/test-hook';
export { reportCoreCrashes } from './preview/core-crashes';
export { installAppUpdates, type RegisterServiceWorker } from './page/app-update';
// help-panel is not re-exported: main.ts loads it when the Help panel is first opened.
export type { HelpPanelElements } from './page/help-panel';
