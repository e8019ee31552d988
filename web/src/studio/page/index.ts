// The page around the studio's areas: its elements, the notice line, questions, menus, what
// loads on first use (dialogs, the Help panel), the test hook, "a new version is ready".
// help-panel is not re-exported as code: it loads when first opened (help-loader.ts).
export { byId, studioElements, type StudioElements } from './page-elements';
export { Notice } from './notice';
export { askToDownload, askToReplace, type QuestionDialog } from './confirm';
export { closeLikeAMenu } from './menus';
export { onDemand } from '../../core';
export { lazyDialog, type LazyDialog } from './on-demand';
export { lazyHelp, type HelpOpener } from './help-loader';
export { delay, nextFrame } from './frames';
export { loadAppUpdates } from './app-update-loader';
