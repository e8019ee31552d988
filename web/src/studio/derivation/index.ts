// The derivation and the inspector: the iterations, seed and playback controls; the String tab
// (the context view) and the Derivation tab (loaded with its tab: derivation-loader.ts).
export { DerivationControls } from './derivation-controls';
export { createInspector, type Inspector } from './inspector';
export type { LazyContextView } from './context-loader';
export type { LazyDerivationView } from './derivation-loader';
