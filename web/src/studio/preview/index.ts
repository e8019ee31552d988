// The live preview: every change of the text or of a build option sends a build to the worker;
// the status line says how it went; the editor's linter gets the builds' diagnostics.
export { createLivePreview } from './studio-preview';
export { LivePreview, showStatus } from './live-preview';
export { DiagnosticsFeed } from './diagnostics-feed';
export { plural } from './status';
