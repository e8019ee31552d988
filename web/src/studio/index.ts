// The studio page's own logic: building in a worker on edit, the status line, the panels and
// controls around the editor and the view, the context-sensitivity view, downloads, and the page
// around them (its elements, opening texts and links, autosave, the menus, the test hook).
export { reportPlant, reportErrors, plural, millis, type StatusReport } from './status';
export { BuildClient, createBuildWorker, type BuildOutcome, type BuildResult, type WorkerLike } from './worker-client';
export { transferablesOf, type BuildRequest, type BuildResponse } from './worker-protocol';
export { DiagnosticsFeed } from './diagnostics-feed';
export { LivePreview, showStatus, type LivePreviewParts } from './live-preview';
export { SliderPanel, sliderRanges, type SliderRange, type SliderEditor } from './sliders';
export { Playback, type PlaybackHost, type PlaybackOptions } from './playback';
export { attachSplitter, clampShare, shareAfterKey } from './splitter';
export { installShortcuts, renderShortcutHelp, shortcutFor, SHORTCUTS, type Shortcut, type ShortcutAction } from './shortcuts';
export { GalleryDialog, fetchExample, fetchManifest } from './gallery';
export { GalleryThumbnails } from './thumbnails';
export { galleryManifest, parseExampleHeader, isGalleryManifest, type GalleryEntry } from './gallery-manifest';
export { askToReplace } from './confirm';
export { ContextView, type ContextViewElements } from './context-view';
export { afterPaint, fileSize, pictureSize, saveFile, PICTURE_MAX, PICTURE_MIN, type PictureSize } from './downloads';
export { createExportWorker, describeProgress, runExport, type ExportOutcome, type ExportRequest, type ExportResponse, type RunningExport } from './export-client';
export { Notice, type NoticeElements, type NoticeKind } from './notice';
export { ShareDialog, installShareButton, linkWithFragment, type ShareDialogElements } from './share-dialog';
export { LibraryDialog, type LibraryElements, type LibraryHost } from './library-dialog';
export { openGrammarBytes, decodeText, dialectName, lsysFileName, MAX_FILE_BYTES, type OpenedFile } from './grammar-files';
export { BranchEditSession, MAX_EDITABLE_SEGMENTS, pathText, staleEditsMessage, type BranchEditingElements, type BranchEditingHost } from './branch-editing';
export { GrowthPanel, type GrowthEditor } from './growth-panel';
export { byId, studioElements, type StudioElements } from './page-elements';
export { ViewOptions, DEFAULT_VIEW_OPTIONS, type SharedViewOptions, type ViewOption, type ViewOptionValues, type ViewOptionsListener } from './view-options';
export { ViewTools, sidesChoices, type ViewToolElements } from './view-tools';
export { DerivationControls, type DerivationElements, type SharedDerivation } from './derivation-controls';
export { TextOpening, type OpenedText, type TextOpeningParts } from './text-opening';
export { openLink, openPastedLinks, startingText, type PastedLinkParts, type StartingText } from './link-opening';
export { LinkState, type LinkStateParts } from './link-state';
export { Autosave, AUTOSAVE_DELAY } from './autosave';
export { browserStorage } from './browser-storage';
export { installFileMenu, type FileMenuActions, type FileMenuElements } from './file-menu';
export { installDrop } from './file-drop';
export { closeLikeAMenu } from './menus';
export { installDownloads, showExportStatus, type DownloadedPlant, type DownloadMenuElements, type ExportState } from './download-menu';
export { connectTestHook, emptyTestHook, type StudioTestHook, type TestedStudio } from './test-hook';
