// What the studio shares and keeps: the share link's state (`codec.ts`: the whole state in the
// link's fragment, loaded on first use by `codec-loader.ts`, which says whether an
// address holds one and the link's limits), the grammars kept in the browser (`storage.ts`:
// localStorage; `kept-texts.ts`: IndexedDB, for the texts kept before something replaced them);
// `growth-state.ts`: the growth timeline's state in a link or an embed's attributes;
// `variants-state.ts`: the Variants view's plants in a link (a door of its own). Used by the
// studio and embeds.
export type { SharedState } from './codec';
export type { SharedVariant } from './variants-state';
export { decodeState, encodeState, hasSharedState, loadCodec, MAX_FRAGMENT, MAX_TEXT } from './codec-loader';
export { cleanGrowth, GROWTH_SPEED_MAX, GROWTH_SPEED_MIN, GROWTH_TIME_MAX, type SharedGrowth } from './growth-state';
export { cleanName, GrammarStore, titleOf, type Autosave, type KeyValueStorage, type StoredGrammar } from './storage';
export { indexedDatabase, KeptTexts, type KeptText, type KeyValueDatabase } from './kept-texts';
export { memoryStorage } from './memory-storage';
