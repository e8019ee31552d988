// What the studio shares and keeps: the share link's state (`codec.ts`: the whole state in the
// link's fragment), the grammars kept in the browser (`storage.ts`: localStorage; `kept-texts.ts`:
// IndexedDB, for the texts kept before something replaced them). Used by the studio and embeds.
export { decodeState, encodeState, hasSharedState, MAX_FRAGMENT, MAX_TEXT, type SharedState } from './codec';
export { cleanName, GrammarStore, titleOf, type Autosave, type KeyValueStorage, type StoredGrammar } from './storage';
export { indexedDatabase, KeptTexts, type KeptText, type KeyValueDatabase } from './kept-texts';
export { memoryStorage } from './memory-storage';
