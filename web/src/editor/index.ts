// The grammar editor (CodeMirror 6): highlighting of the grammar language, hover docs of turtle
// commands, and the core's diagnostics. The studio imports `./grammar-text` (a textarea at first)
// and loads `./grammar-editor` (CodeMirror) after its first plant: importing this index pulls in CodeMirror.
export { createLazyGrammarEditor, type EditorModule, type GrammarEditor, type GrammarEditorOptions, type LazyGrammarEditor } from './grammar-text';
export { createGrammarEditor, type CodeMirrorGrammarEditor } from './grammar-editor';
export { grammarLanguage, grammarHighlightStyle, grammarTags, grammarSupport } from './language';
export { commandHover, commandHoverText } from './hover';
export { grammarCompletion, grammarCompletionSource } from './completion';
export { grammarLinting, LINT_DELAY_MS, type Diagnose } from './diagnostics';
export { studioEditorTheme } from './theme';
export { defineConstants, defineNames, defaultRange, defaultStep, formatNumber, type DefineConstant, type DefineName } from './defines';
export { growthAttributes, type GrowthAttribute, type GrowthField } from './growth-directives';
export { REFERENCE_PATH, referenceAnchor } from './reference';
