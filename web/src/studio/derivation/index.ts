// The derivation and the inspector: the iterations, seed and playback controls; the String tab
// (the context view) and the Derivation tab (loaded with its tab: derivation-loader.ts).
export { DerivationControls } from './derivation-controls';
export { createInspector, type Inspector } from './inspector';
export type { ContextView } from './context-view';
export type { LazyDerivationView } from './derivation-loader';
